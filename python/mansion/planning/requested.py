"""The description's rooms on the building's floors: where each request goes, and whether the
finished program honours it.

:func:`place_requests` turns each :class:`~mansion.planning.description.Placement` into the
floors it asks for, once the number of floors is known ("the top floor" of a four-floor building
is floor 3; "anywhere" is the floor whose template already has such a room, else the ground
floor), and :func:`record_requests` checks the written program against them: a request is
honoured when every floor it names has at least the rooms asked for, and otherwise says why.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from mansion.models.building import FloorCopy, FloorProgram, RoomRequest
from mansion.planning.description import Placement, Request
from mansion.planning.room_names import slug

__all__ = ["FloorRequest", "place_requests", "record_requests"]


@dataclass(frozen=True)
class FloorRequest:
    """``count`` rooms of ``room_type`` on floor ``floor``, for request ``source`` (an index into
    the request's placements), named ``name`` ("" for the type's own name)."""

    room_type: str
    count: int
    floor: int
    name: str
    source: int


def place_requests(
    request: Request, floors: int, has_type: Callable[[int, str], bool]
) -> tuple[list[FloorRequest], list[RoomRequest]]:
    """The floor requests of ``request`` in a building of ``floors`` floors, and a record per
    placement (honoured until :func:`record_requests` finds otherwise). ``has_type(index,
    room_type)`` says whether floor ``index``'s template has such a room already."""
    out: list[FloorRequest] = []
    records: list[RoomRequest] = []
    for k, p in enumerate(request.placements):
        reasons: list[str] = [p.unsupported] if p.unsupported else []
        if p.per_floor:
            wanted = list(range(min(p.from_floor, floors - 1), floors))
            if p.from_floor >= floors:
                reasons.append(f"the building has {floors} floor(s), none above the ground; it is on the ground floor")
        elif p.floor is None:
            wanted = []
        elif p.floor == -1:
            wanted = [floors - 1]
            if p.from_floor >= floors:
                reasons.append(f"the building has {floors} floor(s), none above the ground; it is on the ground floor")
        elif p.floor >= floors:
            # Only a British ordinal one too high gets here (resolve_constraints): read it the
            # American way.
            wanted = [p.floor - 1]
            where = f"{p.where.split(' (')[0]} (American numbering: the building has {floors} floors)"
            p = Placement(**{**p.__dict__, "where": where})
        else:
            wanted = [p.floor] if p.floor is not None else []
        if wanted:
            out += [FloorRequest(p.room_type, p.count, i, p.name, k) for i in wanted]
        else:
            # Anywhere: on the floors that have such rooms already ("a hospital with 20 wards"
            # spreads its wards over the ward floors), else on the ground floor.
            homes = [i for i in range(floors) if has_type(i, p.room_type)] or [0]
            if p.count < len(homes):
                homes = homes[:1]
            share, rest = divmod(p.count, len(homes))
            out += [
                FloorRequest(p.room_type, share + (j < rest), i, p.name, k) for j, i in enumerate(homes)
            ]
        records.append(RoomRequest(
            phrase=p.phrase, name=p.name or p.room_type.replace("_", " "), room_type=p.room_type,
            how=p.how, count=p.count, where=p.where, floors=wanted if not reasons else [],
            honoured=not reasons, reason="; ".join(reasons),
        ))
    records += [
        RoomRequest(
            phrase=phrase, name=phrase, room_type="", count=1, honoured=False,
            reason="names no room the offline planner knows; nothing was built for it",
        )
        for phrase in request.unknown
    ]
    return out, records


def _program(floors: list[FloorProgram | FloorCopy], index: int) -> FloorProgram:
    floor = floors[index]
    program = floors[floor.copy_of] if isinstance(floor, FloorCopy) else floor
    assert isinstance(program, FloorProgram)
    return program


def _rooms_of(program: FloorProgram, want: FloorRequest) -> list[str]:
    return [r.id for r in program.rooms if r.room_type == want.room_type]


def record_requests(
    records: list[RoomRequest], asked: list[FloorRequest], placed: list[FloorRequest],
    floors: list[FloorProgram | FloorCopy], notes: dict[int, str],
) -> list[RoomRequest]:
    """``records`` after checking the written ``floors``: which floors have each request's rooms
    and, where one lacks them, why (``notes``: why a request's rooms left a floor, by source).
    ``asked`` are the floor requests as first placed, ``placed`` after moves between floors: a
    request for given floors is checked on those, one for anywhere where it was placed."""
    out = []
    for k, record in enumerate(records):
        built: list[int] = []
        ids: list[str] = []
        for w in (w for w in placed if w.source == k):
            have = _rooms_of(_program(floors, w.floor), w)
            named = [i for i in have if w.name and i.startswith(slug(w.name))] or have
            if len(have) >= w.count:
                built.append(w.floor)
                ids += named[: w.count]
        missing: list[str] = []
        for w in (w for w in (asked if record.floors else placed) if w.source == k):
            have = _rooms_of(_program(floors, w.floor), w)
            if len(have) < w.count:
                missing.append(f"floor {w.floor} has {len(have)} of the {w.count} asked for")
        update: dict[str, object] = {"built_on": built, "room_ids": ids}
        if missing:
            why = notes.get(k, "the floor cannot hold it at its minimum area")
            update["honoured"] = False
            update["reason"] = "; ".join([record.reason] if record.reason else []) + (
                ("; " if record.reason else "") + f"{', '.join(missing)}: {why}"
            )
        out.append(record.model_copy(update=update))
    return out
