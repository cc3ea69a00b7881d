"""``mansion eval realism``: would an architect accept these rooms? (issue 14)

The same measures, from each room's polygon in metres, for generated buildings and for real plans
(T2D / RPLAN), so the two can stand side by side:

- **sliver**: more than 10 % of the room's area lies in parts 1.0 m wide or narrower (what a
  morphological opening with a square a hair over 1 m removes): a strip two 0.5 m solver cells
  wide is a sliver, as it is in the issue's baseline (which these figures reproduce);
- **elongated**: the room's bounding box is more than 3× longer than wide (circulation —
  corridors, halls, lobbies, balconies — is long by nature and excluded);
- **no square**: no square a hair over 1 m × 1 m fits anywhere in the room (it cannot be used);
- **below area / below width**: the room is smaller than its type's minimum area, or more than
  10 % of it is narrower than its type's minimum clear width (:mod:`mansion.models.room_design`;
  circulation people pass through: its building type's corridor width, a toilet lobby and a
  balcony their own, :func:`~mansion.models.room_design.needed_width`);
- **no corridor door**: a room the table wants on a corridor has no access to circulation (a
  circulation room, or a room that serves others: the floor's hub or a zone's sub-hub, as an
  apartment's living room serves its bedrooms as a hall does). Generated floors: an ``access`` edge of the room graph whose two rooms share at least
  0.9 m of wall (a door's width) in the layout. Real plans carry no interior doors, so there a
  shared wall with the living room, the entrance or a circulation room stands for the door;
- **corridor widths**: the clear width of every circulation room (the width that 90 % of its area
  has), against the width it needs (the building type's corridor width, as above).

Generated floors that are copies of another floor are counted once (they are the same rooms).
Real plans are read at :data:`T2D_METRES_PER_PIXEL` (the issue's "about 0.09 m"): the median
RPLAN common room (bedroom) is then 16.8 m² and the median bathroom 6.3 m², each with its share
of the walls around it (every interior pixel belongs to its nearest room).
"""

from __future__ import annotations

import os
import statistics
from collections import Counter
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pydantic import BaseModel, Field
from shapely.geometry import Polygon
from shapely.geometry.base import BaseGeometry

from mansion._io import atomic_write_text
from mansion.exceptions import InvalidInputError
from mansion.building.generate import RELAYOUTS
from mansion.models.building import Building
from mansion.models.room_design import ELONGATED_ASPECT, design_key, needed_width, room_design
from mansion.models.room_shape import (
    EPS as _EPS,
    SHARE_EPS as _SHARE_EPS,
    TOLERANCE,
    box_aspect,
    fits_square,
    mostly_narrower,
    narrow_share,
)

__all__ = [
    "BENCH_TYPES",
    "DOOR_WIDTH",
    "NARROW",
    "T2D_METRES_PER_PIXEL",
    "Figures",
    "RealismReport",
    "RoomRecord",
    "bench_case",
    "building_rooms",
    "clear_width",
    "evaluate_realism",
    "fits_square",
    "narrow_share",
    "plan_rooms",
    "summarise",
]

#: Parts narrower than this (metres) count as slivers.
NARROW = 1.0
#: Shared wall two rooms need for a door between them, metres.
DOOR_WIDTH = 0.9
#: Longest bounding box side over the shortest above which a non-circulation room is elongated.
MAX_BOX_ASPECT = ELONGATED_ASPECT
#: Metres per pixel of the T2D (RPLAN) 256 images.
T2D_METRES_PER_PIXEL = 0.09
#: Room types of the real plans that serve other rooms as circulation does.
_T2D_CIRCULATION = frozenset({"living_room", "entrance"})

#: Every building type the offline planner knows, in the order benchmark seeds cycle through them
#: (the offline hundred of benches/python/bench_generate.py).
BENCH_TYPES = (
    "studio", "family_apartment", "townhouse", "villa", "apartment_block", "office", "hospital",
    "school", "kindergarten", "supermarket", "library", "restaurant", "hotel", "shopping_mall",
)


def bench_case(seed: int) -> tuple[str, int, str]:
    """(building type, floors, description) of benchmark seed ``seed``: types in turn, floors
    spread 1–10 but kept to what the type can be (a studio has one floor, a townhouse at most
    three)."""
    from mansion.planning.program import typology

    kind = BENCH_TYPES[seed % len(BENCH_TYPES)]
    lo, hi = typology(kind).floors
    wanted = 1 + (seed * 7) % 10
    floors = min(max(wanted, lo), max(hi, min(wanted, 10 if hi >= 4 else hi)))
    return kind, floors, f"a {floors}-storey {kind.replace('_', ' ')}"


# -- measures on one polygon ---------------------------------------------------------------------


def clear_width(shape: BaseGeometry, tolerance: float = TOLERANCE) -> float:
    """The widest square side whose opening keeps all but ``tolerance`` of the area: the width
    that most of the room has (a corridor's clear width), to 1 cm."""
    if shape.area <= 0:
        return 0.0
    lo, hi = 0.0, 2.0 * (shape.bounds[2] - shape.bounds[0] + shape.bounds[3] - shape.bounds[1])
    while hi - lo > 0.01:
        mid = (lo + hi) / 2
        if narrow_share(shape, mid) <= tolerance + _SHARE_EPS:
            lo = mid
        else:
            hi = mid
    return round(lo, 2)


# -- rooms of buildings and plans ----------------------------------------------------------------


@dataclass(frozen=True)
class RoomRecord:
    """One measured room."""

    building_type: str
    room_type: str
    polygon: BaseGeometry
    #: True / False: the room has / lacks access to circulation; None: not measured.
    corridor_access: bool | None = None
    #: Where the room is, to name it ("seed 68, floor 0, commercial_kitchen"); None for the
    #: reference plans' rooms, which are counted, not named.
    where: str | None = None

    @property
    def design(self):  # noqa: ANN201 - RoomDesign; kept light for the dataclass
        return room_design(self.room_type)


def building_rooms(building: Building) -> list[RoomRecord]:
    """The rooms (cores left out) of every floor that is not a copy."""
    kind = building.program.building_type
    out: list[RoomRecord] = []
    for floor in building.floors:
        if floor.copy_of is not None:
            continue
        graph = floor.graph
        circulation = {
            n.id
            for n in graph.nodes
            if n.type in ("main", "area") or (not n.is_core and room_design(n.room_type).circulation)
        }
        doors = {
            frozenset((a.a, a.b)) for a in floor.layout.adjacencies if a.longest >= DOOR_WIDTH - _EPS
        }
        served: dict[str, bool] = {}
        for e in graph.edges:
            if e.kind != "access" or frozenset((e.source, e.target)) not in doors:
                continue
            for room, other in ((e.source, e.target), (e.target, e.source)):
                if other in circulation:
                    served[room] = True
        for room in floor.layout.rooms:
            if room.is_core:
                continue
            shape = Polygon(room.polygon, room.holes)
            out.append(RoomRecord(
                kind, room.room_type, shape, corridor_access=served.get(room.id, False),
                where=f"seed {building.seed}, floor {floor.index}, {room.id}",
            ))
    return out


def plan_rooms(plan: Any, scale: float = T2D_METRES_PER_PIXEL) -> list[RoomRecord]:
    """The rooms of a T2D plan (:class:`mansion.eval.t2d.T2DPlan`) with polygons, in metres.

    Rooms without a polygon are left out. A room has corridor access when a shared wall (the
    plan's adjacency) joins it to the living room, the entrance or a circulation room."""
    by_id = {r.id: r for r in plan.rooms}

    def serves(t: str) -> bool:
        return t in _T2D_CIRCULATION or room_design(t).circulation

    access: set[int] = set()
    for a, b in plan.adjacency:
        if serves(by_id[b].type):
            access.add(a)
        if serves(by_id[a].type):
            access.add(b)
    out = []
    for room in plan.rooms:
        if not room.polygon or len(room.polygon) < 3:
            continue
        shape = Polygon([(x * scale, y * scale) for x, y in room.polygon])
        if not shape.is_valid:
            shape = shape.buffer(0)
        out.append(RoomRecord("t2d", room.type, shape, corridor_access=room.id in access))
    return out


# -- figures -------------------------------------------------------------------------------------


class CorridorWidths(BaseModel):
    """Clear widths of circulation rooms, metres, and how many fall below the type's width."""

    count: int = 0
    min: float | None = None
    median: float | None = None
    below_required: int = 0


class Figures(BaseModel):
    """Counts and rates (%) of one group of rooms."""

    buildings: int = 0
    rooms: int = 0
    sliver: int = 0
    sliver_pct: float = 0.0
    elongated: int = 0
    #: Rooms the elongation measure applies to (circulation excluded).
    elongated_of: int = 0
    elongated_pct: float = 0.0
    no_square: int = 0
    no_square_pct: float = 0.0
    below_area: int = 0
    below_area_pct: float = 0.0
    below_width: int = 0
    below_width_pct: float = 0.0
    no_corridor_door: int = 0
    #: Rooms the table wants on a corridor.
    corridor_door_of: int = 0
    no_corridor_door_pct: float = 0.0
    corridors: CorridorWidths = Field(default_factory=CorridorWidths)
    #: Sliver rooms by room type, most first (where the solver still leaves narrow parts).
    sliver_types: dict[str, int] = Field(default_factory=dict)
    #: Rooms below their minimum area or width, by room type.
    undersized_types: dict[str, int] = Field(default_factory=dict)
    #: Each room of a building below its minimum area or width, named with what it lacks
    #: ("seed 68, floor 0, commercial_kitchen (commercial_kitchen): narrower than 3.6 m"), in
    #: the order measured.
    undersized_rooms: list[str] = Field(default_factory=list)


def _pct(n: int, of: int) -> float:
    return round(100.0 * n / of, 2) if of else 0.0


def summarise(rooms: Iterable[RoomRecord], buildings: int = 0, narrow: float = NARROW) -> Figures:
    """The figures of a group of rooms (see the module doc for each measure; ``narrow`` is the
    sliver width and the side of the square a room must hold)."""
    f = Figures(buildings=buildings)
    widths: list[float] = []
    slivers: Counter[str] = Counter()
    undersized: Counter[str] = Counter()
    for r in rooms:
        d = r.design
        key = design_key(r.room_type) or r.room_type
        shape = r.polygon
        f.rooms += 1
        if mostly_narrower(shape, narrow, inclusive=True):
            f.sliver += 1
            slivers[key] += 1
        if not d.circulation:
            f.elongated_of += 1
            f.elongated += box_aspect(shape) > MAX_BOX_ASPECT
        if not fits_square(shape, narrow, inclusive=True):
            f.no_square += 1
        need = d.min_width if r.building_type == "t2d" else needed_width(r.room_type, r.building_type)
        small = shape.area < d.min_area - _EPS
        thin = mostly_narrower(shape, need)
        f.below_area += small
        f.below_width += thin
        if small or thin:
            undersized[key] += 1
            if r.where is not None:
                lacks = [f"{shape.area:.1f} m² of its {d.min_area:g} m²"] if small else []
                lacks += [f"narrower than {need:g} m"] if thin else []
                f.undersized_rooms.append(f"{r.where} ({r.room_type}): {', '.join(lacks)}")
        if d.corridor and r.corridor_access is not None:
            f.corridor_door_of += 1
            f.no_corridor_door += not r.corridor_access
        if d.circulation:
            w = clear_width(shape)
            widths.append(w)
            f.corridors.below_required += w < need - 0.01
    f.sliver_pct = _pct(f.sliver, f.rooms)
    f.elongated_pct = _pct(f.elongated, f.elongated_of)
    f.no_square_pct = _pct(f.no_square, f.rooms)
    f.below_area_pct = _pct(f.below_area, f.rooms)
    f.below_width_pct = _pct(f.below_width, f.rooms)
    f.no_corridor_door_pct = _pct(f.no_corridor_door, f.corridor_door_of)
    if widths:
        f.corridors.count = len(widths)
        f.corridors.min = min(widths)
        f.corridors.median = round(statistics.median(widths), 2)
    f.sliver_types = dict(slivers.most_common())
    f.undersized_types = dict(undersized.most_common())
    return f


class RealismReport(BaseModel):
    """Figures per building type and overall, beside the reference plans' when given."""

    by_type: dict[str, Figures]
    overall: Figures
    #: The sliver width and square side used, metres.
    narrow: float = NARROW
    reference: Figures | None = None
    reference_plans: int = 0
    failures: list[str] = Field(default_factory=list)

    def save(self, path: str | os.PathLike[str]) -> Path:
        return atomic_write_text(path, self.model_dump_json(indent=2) + "\n")


def _load_buildings(paths: Iterable[str | os.PathLike[str]]) -> Iterator[Building]:
    for p in paths:
        path = Path(p)
        if path.is_dir():
            path = path / "building.json"
        if not path.is_file():
            raise InvalidInputError(f"no building.json in {str(p)!r}")
        yield Building.load(path)


def _generated(count: int, seed: int, failures: list[str], relayouts: int = RELAYOUTS) -> Iterator[Building]:
    from mansion.building import generate_building
    from mansion.exceptions import MansionError

    for s in range(seed, seed + count):
        kind, floors, text = bench_case(s)
        try:
            yield generate_building(text, building_type=kind, floors=floors, seed=s, relayouts=relayouts)
        except MansionError as exc:
            failures.append(f"seed {s} ({kind}, {floors} floors): {exc}")


def evaluate_realism(
    buildings: Iterable[str | os.PathLike[str]] = (),
    *,
    generate: int = 0,
    seed: int = 0,
    reference: str | os.PathLike[str] | None = None,
    scale: float = T2D_METRES_PER_PIXEL,
    narrow: float = NARROW,
    progress: Callable[[int], None] | None = None,
    relayouts: int = RELAYOUTS,
) -> RealismReport:
    """Measure buildings (folders or building.json files, and/or ``generate`` offline buildings
    from benchmark seed ``seed`` on, with ``relayouts`` per floor) and, when given, the T2D plans
    of ``reference``."""
    failures: list[str] = []
    by_type: dict[str, list[RoomRecord]] = {}
    counts: Counter[str] = Counter()
    sources: list[Iterable[Building]] = [_load_buildings(buildings)]
    if generate:
        sources.append(_generated(generate, seed, failures, relayouts))
    done = 0
    for source in sources:
        for b in source:
            kind = b.program.building_type
            by_type.setdefault(kind, []).extend(building_rooms(b))
            counts[kind] += 1
            done += 1
            if progress:
                progress(done)
    if not counts and not failures:
        raise InvalidInputError("nothing to measure: give building folders or --generate N")
    ref, n_plans = None, 0
    if reference is not None:
        from mansion.eval.t2d import iter_plans

        rooms: list[RoomRecord] = []
        for _, plan in iter_plans(reference):
            rooms += plan_rooms(plan, scale)
            n_plans += 1
        ref = summarise(rooms, buildings=n_plans, narrow=narrow)
    every = [r for rs in by_type.values() for r in rs]
    return RealismReport(
        by_type={k: summarise(by_type[k], counts[k], narrow) for k in sorted(by_type)},
        overall=summarise(every, sum(counts.values()), narrow),
        narrow=narrow,
        reference=ref,
        reference_plans=n_plans,
        failures=failures,
    )
