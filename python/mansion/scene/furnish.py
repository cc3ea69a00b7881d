"""Objects in every room of a floor's house, placed around the house's real doors and openings.

Each room gets the offline object plan of its type (:func:`mansion.placement.plan_objects`) and
goes through the Rust engine with the entrances the scene actually has
(:func:`mansion.scene.entrances.room_entrances`):

- a door whose leaf swings into the room keeps the square of its width free (the swing zone);
  on the other side, and along an opening, an apron of :data:`APRON` is enough to step through;
- an entrance narrower than the agent (an opening left where no door asset fitted) is no way in
  for it, so it is not an entrance for the engine either;
- the agent's spawn and each core's landing that stand in the room stay free and reachable.

Stair and lift cores and circulation (corridors, halls) stay clear. Every room of every floor is
furnished in one parallel call to the engine.

Some layouts give a room a neck narrower than the agent, so that even the empty room does not
connect all its doors; the engine rejects such a room as asked. It is then furnished once more
from the largest group of entrances the empty room does connect (found here by a flood fill of
the empty room), the others kept free but not required reached, and the record names the doors
left out. A room the engine still cannot furnish gets no objects; every room's outcome, with the
reason, is recorded in ``metadata.mansion.furnishing``, and generation goes on.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass, replace

import numpy as np
import shapely
from shapely.geometry import Point, Polygon, box

from mansion.exceptions import MansionError
from mansion.models.objects import ObjectPlan
from mansion.placement.offline import plan_objects, room_kind
from mansion.placement.check import FreeSpace, passable
from mansion.placement.place import (
    Entrance,
    PlaceOptions,
    RoomSpec,
    Spot,
    furnish_rooms,
    thor_objects,
)
from mansion.scene.databases import asset_ids
from mansion.scene.entrances import room_entrances
from mansion.scene.house import Furnishing, House, HouseObject, RoomFurnishing
from mansion.scene.navigation import MARGIN

__all__ = ["APRON", "CLEAR", "FurnishJob", "furnish_houses"]

#: Radius (m) of the agent the scenes are furnished for: AI2-THOR's agent is 0.25 m, but
#: navigability is judged at 0.3 m too (issue 17), so furniture leaves 2 · (0.3 + 0.05) = 0.7 m
#: passages. The placement engine alone (the paper's room benchmarks) keeps 0.25 m.
FURNISH_RADIUS = 0.3
#: Depth kept free beyond a door on the side its leaf does not sweep, and along an opening (m):
#: the passage the agent the scenes are furnished for needs, 0.7 m. At 0.6 m (an agent of
#: 0.25 m) a ward's bed 0.63 m from the wall left no room to step through its ensuite's door
#: (the navigation bench, hospital 48).
APRON = 2 * (FURNISH_RADIUS + MARGIN)
#: Side of the square kept free around the spawn and each core landing (m).
CLEAR = 0.6


@dataclass
class FurnishJob:
    """One floor to furnish: its house (objects written into it) and each room's type as the
    layout names it (the house's ``roomType`` is camel-cased for the simulator)."""

    house: House
    room_types: dict[str, str]
    seed: int


def _under_ceiling(house: House, objects: list[HouseObject]) -> list[HouseObject]:
    """The objects without anything reaching above the ceiling (a statue on a tall shelf):
    such a small object is left out, a floor object too tall for the room too."""
    record = house.metadata.mansion
    if record is None:
        return objects
    db = asset_ids()

    def top(o: HouseObject) -> float:
        return o.position.y + db[o.asset_id]["boundingBox"]["y"] / 2 if o.asset_id in db else 0.0

    out = []
    for o in objects:
        if top(o) > record.ceiling_height:
            continue
        o.children = [c for c in o.children if top(c) <= record.ceiling_height]
        out.append(o)
    return out


def _room_seed(seed: int, house_id: str, room_id: str) -> int:
    """A room's own seed, stable whatever else the floor holds."""
    text = f"{seed}:{house_id}:{room_id}".encode()
    return int.from_bytes(hashlib.blake2b(text, digest_size=4).digest(), "little")


def _poses(house: House) -> list[tuple[float, float]]:
    """Where agents stand: the spawn, and every core's landing on this floor."""
    out = [(p.position.x, p.position.z) for p in house.metadata.agent_poses.values()]
    for room in house.rooms:
        core = room.metadata.core if room.metadata else None
        if core is not None and core.landing is not None:
            out.append((core.landing.position.x, core.landing.position.z))
    return list(dict.fromkeys(out))


def _connected_subset(
    spec: RoomSpec, radius: float, cell: float, reach: float
) -> RoomSpec | None:
    """``spec`` with only the largest group of entrances (then spots) that the empty room
    connects still required reached; None when that is every entrance already."""
    space = FreeSpace.build(spec.polygon, spec.segments, [], radius, cell)
    # where the engine enters each door (the strip of its zone within reach of the doorway)
    # and each spot (the cells round its centre)
    cells = [
        space.in_front_of(e.a, e.b, min(reach, e.depth if e.depth is not None else
                                        float(np.hypot(e.b[0] - e.a[0], e.b[1] - e.a[1]))))
        & space.open
        for e in spec.entrances
    ]
    h = min(cell, spec.clear_size / 2)
    cells += [
        np.asarray(shapely.contains_xy(box(x - h, y - h, x + h, y + h), space.px, space.py))
        & space.open
        for x, y in (p.center for p in spec.spots)
    ]
    wanted = [e.entrance for e in spec.entrances] + [p.entrance for p in spec.spots]
    groups: list[tuple[list[int], np.ndarray]] = []
    for i, c in enumerate(cells):
        if not wanted[i] or not c.any():
            continue  # not asked for, or no cell an agent fits in: never an entrance
        for members, reached in groups:
            if (reached & c).any():
                members.append(i)
                break
        else:
            groups.append(([i], space.flood(c)))
    if not groups:
        return None
    keep, _ = max(groups, key=lambda g: (sum(k < len(spec.doors) for k in g[0]), int(g[1].sum())))
    if len(keep) == sum(wanted) or not any(k < len(spec.doors) for k in keep):
        return None
    n = len(spec.doors)
    doors: list[tuple[tuple[float, float], tuple[float, float]] | Entrance] = [
        Entrance(e.a, e.b, e.depth, k in keep) for k, e in enumerate(spec.entrances)
    ]
    spots: list[tuple[float, float] | Spot] = [
        Spot(p.center, n + k in keep) for k, p in enumerate(spec.spots)
    ]
    return RoomSpec(spec.room_id, spec.polygon, doors, spots, spec.clear_size)


def _skip_reason(house: House, room_id: str, room_type: str) -> str | None:
    room = next(r for r in house.rooms if r.id == room_id)
    core = room.metadata.core if room.metadata else None
    if core is not None:
        return f"{core.kind} core: kept clear for the flights or the car"
    if room_kind(room_type) == "circulation":
        return "circulation: kept clear for passage"
    return None


def furnish_houses(
    jobs: list[FurnishJob], building_type: str, options: PlaceOptions | None = None
) -> None:
    """Place objects in every furnishable room of every house, in place: ``house.objects`` and
    ``house.metadata.mansion.furnishing``."""
    opts = options or PlaceOptions(agent_radius=FURNISH_RADIUS)
    # the engine keeps the agent's margin from furniture as from walls (mansion validate's
    # navigability: passages of 2 · (radius + margin)); the record keeps the agent's radius
    engine = replace(opts, agent_radius=opts.agent_radius + MARGIN)
    requests: list[tuple[RoomSpec, ObjectPlan]] = []
    owners: list[tuple[FurnishJob, str, int]] = []
    seeds: list[int] = []
    ids: list[list[str]] = []  # each request's entrance ids, for the record
    records: list[dict[str, RoomFurnishing]] = []
    for job in jobs:
        house = job.house
        rooms: dict[str, RoomFurnishing] = {}
        records.append(rooms)
        entrances = room_entrances(house)
        poses = _poses(house)
        for room in house.rooms:
            rtype = job.room_types.get(room.id, room.room_type)
            why = _skip_reason(house, room.id, rtype)
            if why is not None:
                rooms[room.id] = RoomFurnishing(status="skipped", reason=why)
                continue
            ways = entrances[room.id]
            if not any(passable(e.width, opts.agent_radius) for e in ways):
                rooms[room.id] = RoomFurnishing(
                    status="failed",
                    reason=f"no door or opening wide enough for an agent of radius "
                    f"{opts.agent_radius} m",
                )
                continue
            ring = [(p.x, p.z) for p in room.floor_polygon]
            poly = Polygon(ring)
            spec = RoomSpec(
                room_id=room.id, polygon=ring,
                # a gap narrower than the agent is no way in, but no wall either: the engine
                # keeps it free and does not ask for it to be reached
                doors=[
                    Entrance(e.a, e.b, None if e.swings_here else APRON,
                             entrance=passable(e.width, opts.agent_radius))
                    for e in ways
                ],
                keep_clear=[p for p in poses if poly.contains(Point(p))], clear_size=CLEAR,
            )
            seed = _room_seed(job.seed, house.id or "", room.id)
            plan = plan_objects(room.id, rtype, ring, building_type, seed=seed)
            if not plan.items:
                rooms[room.id] = RoomFurnishing(status="empty", reason=f"no object plan for {rtype!r}")
                continue
            requests.append((spec, plan))
            seeds.append(seed)
            owners.append((job, room.id, len(records) - 1))
            ids.append([e.id for e in ways])
    results = furnish_rooms(requests, options=engine, seeds=seeds) if requests else []
    # rooms whose entrances the empty room does not connect: once more from the largest group
    notes: dict[int, str] = {}
    retry = []
    requests_before = [spec for spec, _ in requests]
    for i, result in enumerate(results):
        if isinstance(result, MansionError):
            subset = _connected_subset(
                requests[i][0], engine.agent_radius, opts.cell, opts.reach_distance
            )
            if subset is not None:
                retry.append(i)
                requests[i] = (subset, requests[i][1])
                before = requests_before[i].entrances
                left = [w for w, e, b in zip(ids[i], subset.entrances, before, strict=True)
                        if b.entrance and not e.entrance]
                notes[i] = (f"furnished from the entrances the empty room connects; "
                            f"{', '.join(left) or 'a pose'} cut off by a neck narrower than the agent")
    if retry:
        again = furnish_rooms([requests[i] for i in retry], options=engine,
                              seeds=[seeds[i] for i in retry])
        for i, result in zip(retry, again, strict=True):
            results[i] = result
    placed: dict[int, list[HouseObject]] = {}
    for i, ((job, room_id, k), result) in enumerate(zip(owners, results, strict=True)):
        if isinstance(result, MansionError):
            records[k][room_id] = RoomFurnishing(status="failed", reason=str(result))
            continue
        objects = _under_ceiling(job.house, [HouseObject.model_validate(o) for o in thor_objects(result)])
        placed.setdefault(k, []).extend(objects)
        dropped = sum(d.count for d in result.dropped)
        if objects:
            records[k][room_id] = RoomFurnishing(
                status="furnished", objects=len(objects),
                small_objects=sum(len(o.children) for o in objects),
                dropped=dropped, reason=notes.get(i),
            )
        else:
            reasons = sorted({d.reason for d in result.dropped})
            records[k][room_id] = RoomFurnishing(
                status="empty", dropped=dropped,
                reason="nothing of its plan fitted" + (f": {reasons[0]}" if reasons else ""),
            )
    for k, job in enumerate(jobs):
        house = job.house
        house.objects = placed.get(k, [])
        record = house.metadata.mansion
        if record is not None:
            # rooms in the house's order, so the record reads like the floor
            rooms = {r.id: records[k][r.id] for r in house.rooms if r.id in records[k]}
            record.furnishing = Furnishing(agent_radius=opts.agent_radius, rooms=rooms)
