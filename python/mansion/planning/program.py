"""The offline building planner: description → :class:`BuildingProgram`.

Steps, in the paper's order: resolve the numeric constraints (floors and area per floor, from the
arguments, else the description, else the building type's usual range and the seed), synthesise
the outlines, choose the vertical connectivity, place the cores, then write each floor's room
program (its first room the circulation hub) and mark identical floors as copies.
"""

from __future__ import annotations

import math
import random
from collections import Counter
from collections.abc import Callable, Sequence

from shapely.geometry import Polygon

from mansion.exceptions import InvalidInputError, PlannerError
from mansion.models.building import (
    BuildingCore,
    BuildingProgram,
    ConnectivityMethod,
    FloorCopy,
    FloorProgram,
    Palette,
    ProgramRoom,
)
from mansion.planning.bays import BAY_TYPOLOGIES, BayPlan, BayProgram
from mansion.planning.cores import CoreRequest, place_cores
from mansion.planning.description import Request
from mansion.planning.footprints import Outline, stack_outlines
from mansion.planning.palette import room_materials
from mansion.planning.requested import FloorRequest, place_requests, record_requests
from mansion.planning.room_names import slug
from mansion.planning.spine import spine_area
from mansion.planning.topology import min_width
from mansion.planning.typologies import TYPOLOGIES, FloorTemplate, Rm, Typology, Zone
from mansion.models.room_design import CORRIDOR_TYPES, corridor_width, design_key, room_design
from mansion.planning.vocabulary import ROOMS, room_kind

__all__ = [
    "AREA_MARGIN",
    "DEFAULT_MAX_FLOOR_AREA",
    "MAX_FLOORS",
    "ProgramOptions",
    "plan_program",
    "connectivity",
    "core_requests",
    "fit_minimums",
    "floor_template",
    "min_target",
    "min_arm",
    "resolve_constraints",
    "sample_outlines",
    "typology",
]

MAX_FLOORS = 10
DEFAULT_MAX_FLOOR_AREA = 500.0
#: Rooms one sub-hub may serve before they are split into wings; more makes cut rounds hard.
MAX_ZONE_ROOMS = 6
#: Rooms (zones and cores included) the floor's hub may serve directly.
MAX_HUB_CHILDREN = 9
#: Target areas stay this far above their type's minimum (the room design table), so the
#: solver's area error (17 % on average over the offline hundred) does not take a room below it.
#: Measured on the offline hundred (issue 14, with the hub spine): 1.2 left 8.7 % of the rooms
#: below their minimum and 2.3 % slivers; 1.3 leaves 8.2 % and 1.9 %, with 1.6 % fewer rooms
#: (more optional and repeated rooms dropped, recorded in the floors' relaxations).
AREA_MARGIN = 1.3
#: The least area (m²) a room is planned from, before the margin: a 1.5 m × 1.5 m square, the
#: smallest room the generator's 0.5 m grid lays out that holds a square over 1 m (``mansion eval
#: realism``'s usable square). A WC compartment at the table's 0.9 m × 1.5 m (1.4 m²) never
#: holds one: planned at 1.8 m², the offline hundred's WCs were 6 of its 15 rooms without a
#: usable square (issue 14).
USABLE_AREA = 1.5 * 1.5
#: A toilet lobby is planned at least this many m² per room it serves: a strip 1.5 m deep (the
#: 0.5 m grid's width for its 1.2 m) along 1.5 m of each room's door. At its type's minimum
#: with the margin (3.25 m²), a mall's cluster of two WCs and an accessible toilet was planned
#: at 14 m², where the grid holds no lobby 1.5 m wide beside an accessible toilet 2 m wide (its
#: 1.6 m on the grid) and two WCs: the slab layouts give a zone exactly its planned area, and
#: on the two realism hundreds 4 rooms of clusters were left without a usable square (1 with
#: this), 12 slivers (9), and two lobbies 1 m wide (none).
TOILET_LOBBY = "toilet_lobby"
LOBBY_PER_ROOM = 1.5 * 1.5
#: The bathroom a guest room or a ward has of its own (the table's ``own_bathroom``), and the
#: share of the pair's area it takes.
ENSUITE = "ensuite"
ENSUITE_SHARE = 0.18


def min_target(room_type: str) -> float:
    """The smallest target area (m²) a room of ``room_type`` may be given: its minimum area
    (with its own bathroom's, if it has one; never below :data:`USABLE_AREA`) and the margin for
    the solver's error."""
    design = room_design(room_type)
    own = room_design(ENSUITE).min_area if design.own_bathroom else 0.0
    return AREA_MARGIN * max(design.min_area + own, USABLE_AREA)


def fit_minimums(
    rooms: list[tuple[str, float]], budget: float, drop_order: list[int],
    least: Sequence[float] = (),
) -> tuple[list[int], list[float], float]:
    """Give every room at least :func:`min_target` (or ``least[i]`` m² where that is more),
    within ``budget`` m².

    Rooms below their minimum are raised; the area comes from the rooms above theirs, in
    proportion to what they have above it. While that is not enough, the rooms of
    ``drop_order`` (indices into ``rooms``) go, in that order. No room is ever shrunk below its
    minimum. Returns (indices of the rooms kept, their areas, area still missing).
    """
    keep = list(range(len(rooms)))
    order = list(drop_order)
    while True:
        floor = {i: max(min_target(rooms[i][0]), least[i] if i < len(least) else 0.0) for i in keep}
        now = {i: max(rooms[i][1], floor[i]) for i in keep}
        excess = sum(now.values()) - budget
        if excess <= 1e-9:
            return keep, [now[i] for i in keep], 0.0
        slack = sum(now[i] - floor[i] for i in keep)
        if excess <= slack:
            f = excess / slack
            return keep, [now[i] - (now[i] - floor[i]) * f for i in keep], 0.0
        if not order:
            return keep, [floor[i] for i in keep], excess - slack
        keep.remove(order.pop(0))


def _dropped(types: list[str], keep: list[int]) -> list[str]:
    """Relaxation notes for the rooms ``fit_minimums`` dropped."""
    gone = Counter(t for i, t in enumerate(types) if i not in set(keep))
    return [
        f"dropped {n} {t.replace('_', ' ')}{'s' if n > 1 else ''}: the floor cannot hold "
        f"{'them' if n > 1 else 'it'} at the minimum area"
        for t, n in gone.items()
    ]


def _frontage(area: float) -> float:
    """The length of corridor a room of ``area`` m² takes: its side on the corridor (rooms
    about square), halved because a corridor serves rooms on both sides."""
    return math.sqrt(max(area, 0.0)) / 2


def planned_corridor(building_type: str, served: list[float], cores: int = 0) -> float:
    """The area (m²) of a corridor serving rooms of ``served`` m² and ``cores`` cores: its
    length (the rooms' frontages, rooms on both sides, 3 m beside each core) times the
    building type's corridor width."""
    length = sum(_frontage(a) for a in served) + 1.5 * cores
    return corridor_width(building_type) * max(length, 2.0)


def typology(key: str) -> Typology:
    if key in TYPOLOGIES:
        return TYPOLOGIES[key]
    if key in BAY_TYPOLOGIES:
        return BAY_TYPOLOGIES[key][0]
    known = ", ".join(sorted([*TYPOLOGIES, *BAY_TYPOLOGIES]))
    raise InvalidInputError(f"unknown building type {key!r}; known: {known}")


class ProgramOptions:
    """The numeric constraints the caller fixed (None: resolve them)."""

    def __init__(
        self,
        *,
        floors: int | None = None,
        area: float | None = None,
        outline: Outline | None = None,
        max_floor_area: float = DEFAULT_MAX_FLOOR_AREA,
        load_bearing: bool | None = None,
        relax: int = 0,
    ) -> None:
        self.floors = floors
        self.area = area
        self.outline = outline
        self.max_floor_area = max_floor_area
        self.load_bearing = load_bearing
        #: How far the program is relaxed after a failed attempt: from 1, optional rooms are
        #: left out and the circulation reserve grows (see generate_building).
        self.relax = relax


#: The usual area (m²) of a room type the vocabulary does not list (a named room such as "a
#: quiet room"): twice the design table's general minimum, a small office's size.
NAMED_ROOM_AREA = 12.0


def _usual_area(room_type: str) -> float:
    return ROOMS[room_type].area if room_type in ROOMS else NAMED_ROOM_AREA


def resolve_constraints(
    request: Request, typ: Typology, options: ProgramOptions, rng: random.Random
) -> tuple[int, float]:
    """The paper's ResolveNumericConstraints: (floors, gross area per floor)."""
    floors = options.floors if options.floors is not None else request.floors
    if floors is None:
        lowest = max(
            [typ.floors[0]]
            + [p.floor + 1 for p in request.placements if p.floor not in (None, -1)]
            + [p.from_floor + 1 for p in request.placements]
        )
        floors = rng.randint(min(lowest, MAX_FLOORS), min(MAX_FLOORS, max(lowest, typ.floors[1])))
    if not 1 <= floors <= MAX_FLOORS:
        raise InvalidInputError(f"a building has 1 to {MAX_FLOORS} floors, asked for {floors}")
    for p in request.placements:
        # A floor the building does not have is a contradiction, unless the British reading of
        # an ordinal overshoots by one and the American one fits (place_requests reads it so).
        if p.floor is not None and p.floor >= floors and not (
            "British numbering" in p.where and p.floor - 1 < floors
        ):
            raise InvalidInputError(
                f"the description puts {p.name or p.room_type.replace('_', ' ')} on floor {p.floor + 1} "
                f"counting the ground floor as the first, but the building has {floors} floors"
            )
    if options.outline is not None:
        area = Polygon(*options.outline).area
    elif options.area is not None:
        area = options.area
        if area > options.max_floor_area:
            raise InvalidInputError(
                f"area {area:g} m² per floor exceeds the cap of {options.max_floor_area:g} m²"
            )
    elif request.area_per_floor is not None:
        area = min(request.area_per_floor, options.max_floor_area)
    elif request.total_area is not None:
        area = min(request.total_area / floors, options.max_floor_area)
    else:
        area = rng.uniform(*typ.area)
        # The rooms the description adds need room of their own: the floor grows by their usual
        # areas (the most any one floor is asked to take), within the cap.
        extra: dict[object, float] = {}
        for p in request.placements:
            key = "every" if p.per_floor else (p.floor if p.floor is not None else 0)
            extra[key] = extra.get(key, 0.0) + p.count * _usual_area(p.room_type)
        if extra:
            every = extra.pop("every", 0.0)
            area += every + max(extra.values(), default=0.0)
    if area < 20:
        raise InvalidInputError(f"{area:g} m² per floor is too small for a building floor (< 20 m²)")
    return floors, min(area, options.max_floor_area) if options.outline is None else area


def connectivity(
    request: Request, typ: Typology, floors: int
) -> tuple[ConnectivityMethod | None, int, int]:
    """(method, stairs, elevators) from the building type, its height and the description."""
    if floors == 1:
        return None, 0, 0
    elevators = request.elevators
    if elevators is None:
        elevators = 0 if floors <= typ.stair_only_floors else (2 if floors >= 6 and typ.family != "residential" else 1)
    stairs = request.stairs
    if stairs is None:
        # Large public floors need two escape stairs; an elevator-only house is asked for, not assumed.
        stairs = 2 if typ.family == "public" and typ.area[0] >= 300 and floors >= 3 else 1
        if request.elevators and request.stairs is None and "only" in request.text.lower() and "elevator" in request.text.lower():
            stairs = 0
    if stairs == 0 and elevators == 0:
        raise InvalidInputError(
            f"a {floors}-floor building needs a stair or an elevator, and the description rules out both"
        )
    method: ConnectivityMethod = (
        "stair_and_elevator" if stairs and elevators else "stair" if stairs else "elevator"
    )
    return method, stairs, elevators


def core_requests(typ: Typology, stairs: int, elevators: int) -> list[CoreRequest]:
    small = typ.family == "residential" and typ.key != "apartment_block"
    stair = (3, 4) if small else (3, 6)
    lift = (2, 2) if small else (3, 3)
    out: list[CoreRequest] = [(f"stair_{i + 1}", "stair", stair) for i in range(stairs)]
    out += [(f"elevator_{i + 1}", "elevator", lift) for i in range(elevators)]
    return out


def _role(typ: Typology, index: int, floors: int) -> str:
    if index == 0:
        return "ground"
    if index == floors - 1 and floors > 2:
        return "top"
    return "upper"


def _template(typ: Typology, role: str) -> FloorTemplate:
    if role == "ground" or typ.upper is None:
        return typ.ground
    if role == "top" and typ.top is not None:
        return typ.top
    return typ.upper


def floor_template(building_type: str, index: int, floors: int) -> FloorTemplate:
    """The template floor ``index`` of a ``floors``-storey building of ``building_type`` is
    programmed from (a bay typology's: its ground template)."""
    typ = typology(building_type)
    return _template(typ, _role(typ, index, floors))


def _apply_placements(rules: list[Rm], wants: list[FloorRequest], index: int) -> list[Rm]:
    """The description's rooms: a requested room type gets exactly the asked count on the floors
    it is asked on, and leaves the other floors (unless it is a fill room there)."""
    out = list(rules)
    asked = {w.room_type for w in wants}
    here: dict[str, int] = {}
    for w in wants:
        if w.floor == index:
            here[w.room_type] = here.get(w.room_type, 0) + w.count
    for room_type in asked:
        same = [r for r in out if r.room_type == room_type]
        if room_type in here:
            zone = same[0].zone if same else None
            out = [r for r in out if r.room_type != room_type]
            out.append(Rm(room_type, here[room_type], area=None if room_type in ROOMS else NAMED_ROOM_AREA, zone=zone))
        else:
            out = [r for r in out if r.room_type != room_type or r.fill]
    return out


def _name_rooms(program: list[ProgramRoom], names: list[FloorRequest]) -> list[ProgramRoom]:
    """The rooms the description named ("a nap room") take the name as their id, and a note."""
    out = list(program)
    taken = {r.id for r in out}
    for want in names:
        if not want.name:
            continue
        base = slug(want.name)
        todo = want.count
        for i, room in enumerate(out):
            if todo == 0:
                break
            if i == 0 and len(out) > 1 or room.room_type != want.room_type or room.notes.startswith("asked for"):
                continue
            rid = base if want.count == 1 else f"{base}_{want.count - todo + 1}"
            while rid in taken and rid != room.id:
                rid += "_"
            taken.discard(room.id)
            taken.add(rid)
            out[i] = room.model_copy(update={"id": rid, "notes": f'asked for as "{want.name}"'})
            todo -= 1
    return out


def _room_ids(rooms: list[tuple[str, float, str | None]]) -> list[str]:
    totals = Counter(t for t, _, _ in rooms)
    seen: Counter[str] = Counter()
    ids = []
    for t, _, _ in rooms:
        seen[t] += 1
        ids.append(t if totals[t] == 1 else f"{t}_{seen[t]}")
    return ids


def _generic_rooms(
    template: FloorTemplate, rules: list[Rm], free: float, reserve: float, where: str,
    building_type: str = "", cores: int = 0, spine: float = 0.0,
) -> tuple[str, float, list[tuple[str, float, str | None]], dict[str, Zone], list[str]]:
    """Hub type and area, rooms (type, area, zone), zones and relaxations of a template floor of
    ``free`` m².

    Rooms are sized from the vocabulary's usual areas and scaled to the floor; corridors (the hub
    and the zones' sub-hubs, when they are corridors) are then planned as their length times the
    building type's corridor width, the rooms taking what they leave, and the hub is never
    planned smaller than ``spine`` (:func:`~mansion.planning.spine.spine_area`, the path to the
    cores the layout keeps for it); last, every room is kept at its minimum
    (:func:`fit_minimums`), optional and extra fill rooms dropping first."""
    zones = {z.id: z for z in template.zones}
    hub_kind = room_kind(template.hub)
    circulation_hub = hub_kind.role == "circulation"

    def zone_hub_area(z: Zone) -> float:
        return z.hub_area if z.hub_area is not None else room_kind(z.hub).area

    def split(rs: list[Rm]) -> tuple[float, float]:
        """(fixed circulation area, scalable sub-hub area): circulation sub-hubs keep their size,
        room-like sub-hubs (a dining room) scale with the rooms."""
        used = {r.zone for r in rs if r.zone}
        circ = sum(zone_hub_area(zones[z]) for z in used if room_kind(zones[z].hub).role == "circulation")
        rooms = sum(zone_hub_area(zones[z]) for z in used if room_kind(zones[z].hub).role != "circulation")
        return circ, rooms

    active = list(rules)
    while True:
        circ, zone_rooms = split(active)
        # A corridor or lobby hub is the circulation reserve; a hub that is a room in its own
        # right (a living room, a sales floor) scales with the other rooms.
        hub_area = max(reserve * free - circ, 0.4 * reserve * free) if circulation_hub else 0.0
        budget = free - hub_area - circ
        fixed = sum(r.count * (r.area or room_kind(r.room_type).area) for r in active if not r.fill)
        fixed += zone_rooms + (0.0 if circulation_hub else hub_kind.area)
        fills = [r for r in active if r.fill]
        counts = {id(r): r.count for r in active}
        if fills:
            unit = sum(r.area or room_kind(r.room_type).area for r in fills) / len(fills)
            extra = max(0, math.floor((budget - fixed) / unit) - sum(r.count for r in fills))
            for k in range(extra):
                counts[id(fills[k % len(fills)])] += 1
        total = fixed + sum(counts[id(r)] * (r.area or room_kind(r.room_type).area) for r in fills)
        scale = budget / total if total > 0 else 0.0
        if scale >= 0.7 or not any(r.optional for r in active):
            break
        # Too many rooms for the floor: drop the last optional one and try again.
        last = max(i for i, r in enumerate(active) if r.optional)
        active.pop(last)
    if scale < 0.55:
        raise PlannerError(
            f"{where}: {free:.0f} m² of free area cannot hold its program "
            f"({total:.0f} m² of rooms at usual sizes); give a larger area or fewer rooms"
        )
    # A floor larger than its program: rooms grow up to 60 %, the hub takes the rest.
    if scale > 1.6:
        hub_area += (scale - 1.6) * total
        scale = 1.6
    if not circulation_hub:
        hub_area += hub_kind.area * scale
    zones = {
        zid: z if room_kind(z.hub).role == "circulation" else Zone(z.id, z.hub, zone_hub_area(z) * scale)
        for zid, z in zones.items()
    }
    expanded = [(r, k) for r in active for k in range(counts[id(r)])]
    rooms = [(r.room_type, (r.area or room_kind(r.room_type).area) * scale, r.zone) for r, _ in expanded]
    hub_area, rooms, zones = _plan_corridors(
        template.hub, hub_area, rooms, zones, building_type, cores, spine
    )
    # Dropped first when the floor cannot hold every room at its minimum: optional rooms, then
    # the fill rooms beyond their count, last listed first.
    order = [i for i in reversed(range(len(expanded))) if expanded[i][0].optional]
    order += [
        i for i in reversed(range(len(expanded)))
        if expanded[i][0].fill and expanded[i][1] >= expanded[i][0].count
    ]
    keep, areas, missing = fit_minimums(
        [(t, a) for t, a, _ in rooms], sum(a for _, a, _ in rooms), order
    )
    relaxations = _dropped([t for t, _, _ in rooms], keep)
    rooms = [(rooms[i][0], a, rooms[i][2]) for i, a in zip(keep, areas)]
    served = {zid: sum(1 for _, _, z in rooms if z == zid) for zid in zones}

    def hub_least(z: Zone) -> float:
        least = min_target(z.hub)
        if z.hub == TOILET_LOBBY:
            least = max(least, LOBBY_PER_ROOM * served.get(z.id, 0))
        return least

    zones = {
        zid: z if z.hub_area is None or z.hub_area >= hub_least(z) else Zone(z.id, z.hub, hub_least(z))
        for zid, z in zones.items()
    }
    if missing > 0:
        # Rooms that must stay (the template's and the description's) take it from the hub,
        # down to its spine: the layout keeps that for the hub whatever the program says.
        if hub_area - missing < max(min_target(template.hub), spine):
            raise PlannerError(
                f"{where}: {free:.0f} m² of free area cannot hold its rooms at their minimum "
                f"areas ({missing:.0f} m² short); give a larger area or fewer rooms"
            )
        hub_area -= missing
        relaxations.append(f"the {template.hub.replace('_', ' ')} gave {missing:.0f} m² to rooms at their minimum")
    return template.hub, hub_area, rooms, zones, relaxations


def _is_corridor(room_type: str) -> bool:
    return design_key(room_type) in CORRIDOR_TYPES


def _plan_corridors(
    hub: str,
    hub_area: float,
    rooms: list[tuple[str, float, str | None]],
    zones: dict[str, Zone],
    building_type: str,
    cores: int,
    spine: float = 0.0,
) -> tuple[float, list[tuple[str, float, str | None]], dict[str, Zone]]:
    """Corridors sized as length × width (:func:`planned_corridor`) instead of what is left over,
    the hub at least its ``spine``; the area they free or take is shared by the rooms (room-like
    sub-hubs included) in proportion."""
    if not building_type:
        return hub_area, rooms, zones
    new_zones = dict(zones)
    delta = 0.0
    for zid, z in zones.items():
        served = [a for _, a, zz in rooms if zz == zid]
        if served and _is_corridor(z.hub) and z.hub_area is not None:
            area = planned_corridor(building_type, served)
            new_zones[zid] = Zone(z.id, z.hub, area)
            delta += z.hub_area - area
    if _is_corridor(hub):
        used = {zz for _, _, zz in rooms if zz is not None}
        served = [a for _, a, zz in rooms if zz is None]
        # A sub-hub meets the hub along about 3 m, as a 9 m² room would.
        served += [9.0 if _is_corridor(new_zones[z].hub) else (new_zones[z].hub_area or 9.0) for z in used]
        area = planned_corridor(building_type, served, cores)
        delta += hub_area - area
        hub_area = area
    if spine > hub_area:
        delta += hub_area - spine
        hub_area = spine
    total = sum(a for _, a, _ in rooms) + sum(
        z.hub_area or 0.0 for z in new_zones.values() if not _is_corridor(z.hub)
        and room_kind(z.hub).role != "circulation"
    )
    if total <= 0 or abs(delta) < 1e-9:
        return hub_area, rooms, new_zones
    k = max(0.0, (total + delta) / total)
    rooms = [(t, a * k, zz) for t, a, zz in rooms]
    new_zones = {
        zid: z if room_kind(z.hub).role == "circulation" or z.hub_area is None else Zone(z.id, z.hub, z.hub_area * k)
        for zid, z in new_zones.items()
    }
    return hub_area, rooms, new_zones


def _join_corridors(
    hub: str,
    hub_area: float,
    rooms: list[tuple[str, float, str | None]],
    zones: dict[str, Zone],
) -> tuple[float, list[tuple[str, float, str | None]], dict[str, Zone]]:
    """A zone whose sub-hub is a corridor, and whose rooms all want a door to a corridor (the
    design table's), opens onto a corridor hub directly when the hub can take its rooms (at most
    :data:`MAX_HUB_CHILDREN`): one double-loaded corridor, its area the
    two corridors', instead of a branch the floor's first round must cut as one block. (A block
    that large is laid short: the hub's spine to the cores splits the floor, and the block's
    rooms take the loss; issue 14.)"""
    if not _is_corridor(hub):
        return hub_area, rooms, zones
    children = {zz for _, _, zz in rooms if zz is not None}
    direct = sum(1 for _, _, zz in rooms if zz is None)
    out = list(rooms)
    zones = dict(zones)
    for zid in sorted(children, key=lambda z: sum(zz == z for _, _, zz in rooms)):
        zone = zones[zid]
        mine = sum(zz == zid for _, _, zz in out)
        if (
            not _is_corridor(zone.hub) or direct + len(children) - 1 + mine > MAX_HUB_CHILDREN
            # a suite's hallway (a master bedroom's ensuite and closet) stays the suite's
            or not all(room_design(t).corridor for t, _, zz in out if zz == zid)
        ):
            continue
        hub_area += zone.hub_area if zone.hub_area is not None else room_kind(zone.hub).area
        out = [(t, a, None if zz == zid else zz) for t, a, zz in out]
        del zones[zid]
        children.discard(zid)
        direct += mine
    return hub_area, out, zones


def _split_wings(
    hub_area: float,
    rooms: list[tuple[str, float, str | None]],
    zones: dict[str, Zone],
    building_type: str = "",
    spine: float = 0.0,
) -> tuple[float, list[tuple[str, float, str | None]], dict[str, Zone]]:
    """Split zones with more than MAX_ZONE_ROOMS rooms into wings, and give a hub with too many
    children corridor wings for its most repeated room type, so every cut round stays small.
    With ``building_type`` given, a wing corridor is planned (:func:`planned_corridor`) for the
    rooms it serves. The hub keeps at least its ``spine``; what the wing takes beyond that comes
    out of the rooms when the floor is fitted."""
    zones = dict(zones)
    out: list[tuple[str, float, str | None]] = []
    by_zone: dict[str, list[tuple[str, float, str | None]]] = {}
    direct = [r for r in rooms if r[2] is None]
    for room in rooms:
        if room[2] is not None:
            by_zone.setdefault(room[2], []).append(room)
    n_children = len(direct) + len(by_zone)
    if n_children > MAX_HUB_CHILDREN:
        counts = Counter(t for t, _, _ in direct)
        common, _ = counts.most_common(1)[0]
        moved = [r for r in direct if r[0] == common]
        keep = [r for r in direct if r[0] != common]
        if len(moved) >= 2:
            direct = keep
            by_zone["wing"] = [(t, a, "wing") for t, a, _ in moved]
            share = min(0.35 * hub_area, 4.0 * len(moved))
            if building_type:
                share = min(0.5 * hub_area, planned_corridor(building_type, [a for _, a, _ in moved]))
            zones["wing"] = Zone("wing", "corridor", share)
            hub_area = max(hub_area - share, spine)
    for zid, zrooms in by_zone.items():
        zone = zones[zid]
        n_wings = math.ceil(len(zrooms) / MAX_ZONE_ROOMS)
        if n_wings == 1:
            out += zrooms
            continue
        hub = zone.hub_area if zone.hub_area is not None else room_kind(zone.hub).area
        del zones[zid]
        # Rooms of the commonest type spread over the wings; the others stay in the first wing.
        wings = [[r for i, r in enumerate(zrooms) if i % n_wings == k] for k in range(n_wings)]
        for k in range(n_wings):
            size = max(hub / n_wings * 1.3, 6.0)
            if building_type and _is_corridor(zone.hub):
                size = planned_corridor(building_type, [a for _, a, _ in wings[k]])
            zones[f"{zid}_{k + 1}"] = Zone(f"{zid}_{k + 1}", zone.hub, size)
        for i, (t, a, _) in enumerate(zrooms):
            out.append((t, a, f"{zid}_{i % n_wings + 1}"))
    return hub_area, direct + out, zones


def _floor_program(
    index: int,
    requirement: str,
    outline: Outline,
    hub: str,
    hub_area: float,
    rooms: list[tuple[str, float, str | None]],
    zones: dict[str, Zone],
    palette: Palette,
    free: float,
    circulation: float,
    names: list[FloorRequest] = (),  # type: ignore[assignment]
) -> FloorProgram:
    """Assemble the program: the hub first, then each zone's sub-hub followed by its rooms."""
    def card(
        rid: str, room_type: str, area: float, zone: str | None, notes: str = "",
        parent: str | None = None,
    ) -> ProgramRoom:
        floor, wall = room_materials(palette, room_type)
        return ProgramRoom(
            id=rid, room_type=room_type, area=round(area, 2), zone=zone, parent=parent,
            floor_material=floor, wall_material=wall, notes=notes,
        )

    ordered: list[tuple[str, float, str | None]] = [r for r in rooms if r[2] is None]
    for zid in zones:
        ordered += [r for r in rooms if r[2] == zid]
    ids = _room_ids(ordered)
    program = [card(hub if hub not in ids else f"{hub}_hub", hub, hub_area, None, "circulation hub")]
    taken = {program[0].id, *ids}
    for zid, zone in zones.items():
        if not any(r[2] == zid for r in rooms):
            continue
        zone_hub_area = zone.hub_area if zone.hub_area is not None else room_kind(zone.hub).area
        rid = zid if zid not in taken else f"{zid}_zone"
        taken.add(rid)
        program.append(card(rid, zone.hub, zone_hub_area, zid, f"sub-hub of zone {zid}"))
        program += [card(i, t, a, z) for i, (t, a, z) in zip(ids, ordered) if z == zid]
    program[1:1] = [card(i, t, a, z) for i, (t, a, z) in zip(ids, ordered) if z is None]
    program = _with_ensuites(_name_rooms(program, list(names)), card)
    gross = Polygon(*outline).area
    return FloorProgram(
        index=index, requirement=requirement, outline=outline[0], holes=outline[1],
        gross_floor_area=gross, rooms=program, reserve_ratio=round(circulation / free, 4),
    )


def _with_ensuites(program: list[ProgramRoom], card: Callable[..., ProgramRoom]) -> list[ProgramRoom]:
    """Every room the design table gives a bathroom of its own (a guest room, a ward) is split
    into the room and its ensuite, entered from the room and listed right after it."""
    out: list[ProgramRoom] = []
    taken = {r.id for r in program}
    for i, room in enumerate(program):
        if i == 0 or not room_design(room.room_type).own_bathroom:
            out.append(room)
            continue
        least = AREA_MARGIN * room_design(ENSUITE).min_area
        bath = max(least, min(ENSUITE_SHARE * room.area, room.area - AREA_MARGIN * room_design(room.room_type).min_area))
        rid = f"{room.id}_{ENSUITE}"
        while rid in taken:
            rid += "_"
        taken.add(rid)
        out.append(room.model_copy(update={"area": round(room.area - bath, 2)}))
        out.append(card(rid, ENSUITE, bath, room.zone, f"ensuite of {room.id}", parent=room.id))
    return out


#: How far a floor's program may exceed its free area before it is shrunk: the solver scales the
#: targets to the cut region, and rejects programs more than 10 % over it.
FLOOR_OVERFILL = 1.005


def _fit_floor(
    program: FloorProgram, free: float, where: str, spine: float = 0.0
) -> tuple[FloorProgram, list[str]]:
    """``program`` within its floor's ``free`` m² (up to :data:`FLOOR_OVERFILL`): rooms above
    their minimum (the hub above its ``spine``) give area in proportion to what they have above
    it (:func:`fit_minimums`); a program that cannot fit even at the minimums is a
    :class:`PlannerError`."""
    budget = free
    total = sum(r.area for r in program.rooms)
    if total <= budget * FLOOR_OVERFILL:
        return program, []
    rooms = [(r.room_type, r.area) for r in program.rooms]
    _, areas, missing = fit_minimums(rooms, budget, [], [spine])
    if missing > 0:
        raise PlannerError(
            f"{where}: its rooms need {total - missing:.0f} m² at their minimum areas but the floor "
            f"has {budget:.0f} m²; give a larger area or fewer rooms"
        )
    rooms_out = [r.model_copy(update={"area": round(a, 2)}) for r, a in zip(program.rooms, areas)]
    note = f"rooms shrunk by {total - budget:.0f} m² to fit the floor's {free:.0f} m² of free area"
    return program.model_copy(update={"rooms": rooms_out}), [note]


def _circulation(program_rooms: list[ProgramRoom]) -> float:
    return sum(r.area for i, r in enumerate(program_rooms) if i == 0 or room_kind(r.room_type).role == "circulation" and r.notes.startswith("sub-hub"))


def _fit_bay(rooms: list[tuple[str, float]]) -> list[float]:
    """Areas of a bay's rooms with each at its minimum where the bay's area allows
    (:func:`fit_minimums` within the bay's total; nothing is dropped from a bay)."""
    _, areas, _ = fit_minimums(rooms, sum(a for _, a in rooms), [])
    return areas


def _bay_floor(
    plan: BayPlan, role: str, rules_extra: list[Rm], n_bays: int, bay_area: float,
    services_area: float, hub_area: float, rng: random.Random,
) -> tuple[str, float, list[tuple[str, float, str | None]], dict[str, Zone]]:
    """A bay floor: the row of bays, each with the use its role and size call for."""
    uses: list[BayProgram] = list(plan.leading.get(role, ()))[:n_bays]
    while len(uses) < n_bays:
        fitting = [p for p in plan.default if p.min_area <= bay_area] or [plan.default[0]]
        uses.append(rng.choice(fitting))
    # The description's rooms go into the general bays, round-robin (into the last bay when the
    # floor's bays all have a leading use); a room type a leading bay already has is there.
    present = {t for use in uses[: len(plan.leading.get(role, ()))] for t in (use.hub, *(r.room_type for r in use.rooms))}
    general = list(range(len(plan.leading.get(role, ())), n_bays)) or [n_bays - 1]
    assigned: dict[int, list[Rm]] = {}
    for j, r in enumerate(x for x in rules_extra if x.room_type not in present):
        assigned.setdefault(general[j % len(general)], []).append(r)
    rooms: list[tuple[str, float, str | None]] = []
    zones: dict[str, Zone] = {}
    for k, use in enumerate(uses):
        zid = f"bay_{k + 1}"
        own = [(r.room_type, r.area or room_kind(r.room_type).area) for r in use.rooms for _ in range(r.count)]
        for r in assigned.get(k, []):
            own = [o for o in own if o[0] != r.room_type]
            own += [(r.room_type, r.area or room_kind(r.room_type).area)] * r.count
        hub_share = 0.12 if room_kind(use.hub).role == "circulation" else 0.4
        scale = bay_area * (1 - hub_share) / sum(a for _, a in own)
        # Rooms (the sub-hub too) below their minimum take area from the bay's others; the bay
        # keeps its area, so its walls still stand on the floor below's.
        sub_hub, *areas = _fit_bay([(use.hub, bay_area * hub_share), *((t, a * scale) for t, a in own)])
        zones[zid] = Zone(zid, use.hub, sub_hub)
        rooms += [(t, a, zid) for (t, _), a in zip(own, areas)]
    if plan.services is not None:
        zid = f"bay_{n_bays + 1}"
        own = [(r.room_type, r.area or room_kind(r.room_type).area) for r in plan.services.rooms]
        scale = services_area * 0.8 / sum(a for _, a in own)
        sub_hub, *areas = _fit_bay(
            [(plan.services.hub, services_area * 0.2), *((t, a * scale) for t, a in own)]
        )
        zones[zid] = Zone(zid, plan.services.hub, sub_hub)
        rooms += [(t, a, zid) for (t, _), a in zip(own, areas)]
    return plan.floor_hub[role], hub_area, rooms, zones


def sample_outlines(
    typ: Typology,
    floors: int,
    area: float,
    options: ProgramOptions,
    rng: random.Random,
    *,
    attempt: int = 0,
    min_arm: float,
) -> list[Outline]:
    """Every floor's outline: the caller's, else a shape and stack the type uses, sized to
    ``area`` (a small floor's first attempt is a plain rectangle)."""
    if options.outline is not None:
        return [options.outline] * floors
    shape = rng.choice(typ.shapes) if area >= 120 or attempt else "rectangle"
    if shape == "courtyard" and area < 350:
        shape = "rectangle"
    stack = rng.choice(typ.stacks) if floors > 1 else "uniform"
    state = rng.getstate()
    outlines = stack_outlines(shape, stack, floors, area, rng, min_arm=min_arm)
    # Outlines are whole metres, so one sized to the cap can overshoot it by a few m²: sample
    # the same shape (same draws) a little smaller until every floor is within the cap.
    target = area
    for _ in range(8):
        largest = max(Polygon(*o).area for o in outlines)
        if largest <= options.max_floor_area + 1e-9:
            break
        target *= options.max_floor_area / largest * 0.99
        rng.setstate(state)
        outlines = stack_outlines(shape, stack, floors, target, rng, min_arm=min_arm)
    return outlines


def min_arm(typ: Typology, building_type: str) -> float:
    """The narrowest wing an outline of this type may have, in metres."""
    return 4.0 if typ.family == "residential" and building_type not in BAY_TYPOLOGIES else 8.0


#: The generator's floor-wide clear width (``mansion.building.steps.MIN_CLEAR_WIDTH``): no
#: hub's spine is narrower.
FLOOR_WIDTH = 1.5


def hub_spine(outline: Outline, cores: list[BuildingCore], hub: str, building_type: str) -> float:
    """The area (m²) the layout keeps for the path of a hub of type ``hub`` to ``cores`` (those
    on the floor): :func:`spine_area` at the hub's width rule."""
    width = max(FLOOR_WIDTH, min_width(hub, math.inf, building_type))
    return spine_area(outline, cores, width)


def _free_area(outline: Outline, cores: list[BuildingCore], index: int) -> float:
    on_floor = [c for c in cores if index in c.floors]
    return Polygon(*outline).area - sum((c.x[1] - c.x[0]) * (c.y[1] - c.y[0]) for c in on_floor)


def _move_requests(
    typ: Typology, floors: int, outlines: list[Outline], cores: list[BuildingCore],
    wants: list[FloorRequest], reserve: float, building_type: str, options: ProgramOptions,
    has_type: Callable[[int, str], bool], why_not: dict[int, str],
) -> list[FloorRequest]:
    """The requests of a floor that cannot hold them at their minimum areas move to the nearest
    floor that can (floors with such rooms first); ``why_not`` records each move by request."""

    def holds(index: int, mine: list[FloorRequest]) -> bool:
        template = _template(typ, _role(typ, index, floors))
        base = [r for r in template.rooms if not (options.relax and r.optional)]
        on_floor = [c for c in cores if index in c.floors]
        for rules in (base, [r for r in base if not r.optional]):
            try:
                _generic_rooms(
                    template, _apply_placements(rules, mine, index),
                    _free_area(outlines[index], cores, index), reserve, "", building_type,
                    len(on_floor), hub_spine(outlines[index], on_floor, template.hub, building_type),
                )
                return True
            except PlannerError:
                continue
        return False

    out = list(wants)
    for index in range(floors):
        here = [w for w in out if w.floor == index]
        if not here or holds(index, out):
            continue
        for w in here:
            others = sorted(
                (j for j in range(floors) if j != index),
                key=lambda j: (not has_type(j, w.room_type), abs(j - index), j),
            )
            for j in others:
                moved = [x if x is not w else FloorRequest(w.room_type, w.count, j, w.name, w.source) for x in out]
                if holds(j, moved):
                    out = moved
                    why_not[w.source] = (
                        f"floor {index} cannot hold it at its minimum area with the rest of its "
                        f"program; it is on floor {j} instead"
                    )
                    break
            if holds(index, out):
                break
    return out


def plan_program(
    request: Request,
    building_type: str,
    options: ProgramOptions,
    palette: Palette,
    rng: random.Random,
) -> BuildingProgram:
    """The whole building program; see the module doc."""
    typ = typology(building_type)
    bay_plan = BAY_TYPOLOGIES[building_type][1] if building_type in BAY_TYPOLOGIES else None
    floors, area = resolve_constraints(request, typ, options, rng)
    arm = min_arm(typ, building_type)

    method, n_stairs, n_elevators = connectivity(request, typ, floors)
    requests = core_requests(typ, n_stairs, n_elevators)
    cores: list[BuildingCore] = []
    outlines: list[Outline] = []
    for attempt in range(12):
        outlines = sample_outlines(typ, floors, area, options, rng, attempt=attempt, min_arm=arm)
        try:
            cores = place_cores(outlines, requests, list(range(floors)), rng) if requests else []
            break
        except PlannerError:
            if options.outline is not None or attempt == 11:
                raise

    load_bearing = typ.load_bearing if options.load_bearing is None else options.load_bearing
    reserve = rng.uniform(*typ.reserve) * (1 + 0.25 * options.relax)
    floor_programs: list[FloorProgram | FloorCopy] = []
    originals: list[tuple[tuple, int]] = []

    # A bay typology keeps one row of bays for the whole building, sized on the smallest floor.
    n_bays, bay_area = 0, 0.0
    if bay_plan is not None:
        smallest = min(Polygon(*o).area for o in outlines) - sum(
            (c.x[1] - c.x[0]) * (c.y[1] - c.y[0]) for c in cores
        )
        rooms_area = smallest * (1 - reserve) - bay_plan.services_area
        n_bays = max(2, min(6, round(rooms_area / rng.uniform(*bay_plan.bay_area))))
        bay_area = rooms_area / n_bays

    def has_type(index: int, room_type: str) -> bool:
        if bay_plan is not None:
            uses = [*bay_plan.leading.get(_role(typ, index, floors), ()), *bay_plan.default]
            return any(room_type == u.hub or any(r.room_type == room_type for r in u.rooms) for u in uses)
        template = _template(typ, _role(typ, index, floors))
        return room_type == template.hub or any(r.room_type == room_type for r in template.rooms) or any(
            z.hub == room_type for z in template.zones
        )

    wants, records = place_requests(request, floors, has_type)
    asked = list(wants)
    why_not: dict[int, str] = {}
    if bay_plan is None:
        wants = _move_requests(typ, floors, outlines, cores, wants, reserve, building_type, options, has_type, why_not)
    placed = list(wants)
    for index in range(floors):
        role = _role(typ, index, floors)
        outline = outlines[index]
        on_floor = [c for c in cores if index in c.floors]
        free = Polygon(*outline).area - sum((c.x[1] - c.x[0]) * (c.y[1] - c.y[0]) for c in on_floor)
        where = f"floor {index} of the {building_type.replace('_', ' ')}"
        here = [w for w in wants if w.floor == index]
        spine = 0.0 if bay_plan is not None else hub_spine(
            outline, on_floor, _template(typ, role).hub, building_type
        )
        if bay_plan is not None:
            extras = [Rm(w.room_type, w.count) for w in here]
            used = n_bays * bay_area + bay_plan.services_area
            hub, hub_area, rooms, zones = _bay_floor(
                bay_plan, role, extras, n_bays, bay_area, bay_plan.services_area, free - used, rng
            )
            relax: list[str] = []
        else:
            template = _template(typ, role)
            base = [r for r in template.rooms if not (options.relax and r.optional)]
            # A floor too small for its program leaves the template's optional rooms out
            # (what the description asks for comes before them).
            # A floor too small for its program leaves the template's optional rooms out, then
            # keeps one of each fill room (what the description asks for comes before them).
            attempts = [base]
            if any(r.optional for r in base):
                attempts.append([r for r in base if not r.optional])
            if any(r.fill and r.count > 1 for r in base):
                attempts.append([
                    Rm(r.room_type, 1, r.area, True, False, r.zone) if r.fill else r
                    for r in base if not r.optional
                ])
            for k, rules in enumerate(attempts):
                try:
                    hub, hub_area, rooms, zones, relax = _generic_rooms(
                        template, _apply_placements(rules, wants, index), free, reserve, where,
                        building_type, len(on_floor), spine,
                    )
                    if k:
                        relax = [*relax, "optional rooms left out" + (" and one of each repeated room" if k > 1 else "")
                                 + ": the floor cannot hold them at their minimum areas"]
                    break
                except PlannerError as exc:
                    error = exc
            else:
                if not here:
                    raise error
                # The floor cannot hold what the description asks on it: it keeps its own
                # program, and the request is reported as not honoured.
                for w in here:
                    why_not[w.source] = f"the floor cannot hold it at its minimum area ({error})"
                wants = [w for w in wants if w.floor != index]
                here = []
                hub, hub_area, rooms, zones, relax = _generic_rooms(
                    template, _apply_placements(base, wants, index), free, reserve, where,
                    building_type, len(on_floor), spine,
                )
                relax = [*relax, "rooms the description asked for here left out: the floor cannot hold them"]
            hub_area, rooms, zones = _join_corridors(hub, hub_area, rooms, zones)
            hub_area, rooms, zones = _split_wings(hub_area, rooms, zones, building_type, spine)
        requirement = f"{role} floor of a {building_type.replace('_', ' ')}: {typ.description}"
        program = _floor_program(
            index, requirement, outline, hub, hub_area, rooms, zones, palette, free, 0.0, here
        )
        program, fitted = _fit_floor(program, free, where, spine)
        program = program.model_copy(
            update={
                "reserve_ratio": round(min(1.0, _circulation(program.rooms) / free), 4),
                "relaxations": relax + fitted,
            }
        )
        # Identical floors (same outline, same rooms) are written as the paper's copies.
        key = (tuple(map(tuple, outline[0])), tuple((r.id, r.room_type, r.area, r.zone) for r in program.rooms))
        source = next((i for k, i in originals if k == key), None)
        if source is not None and index > 0 and (typ.copies or bay_plan is not None):
            floor_programs.append(FloorCopy(index=index, copy=source))
        else:
            originals.append((key, index))
            floor_programs.append(program)

    reasoning = (
        f"{typ.key.replace('_', ' ')}: {typ.description}. {floors} floor(s) of about {area:.0f} m²; "
        f"{method or 'no vertical core'}; circulation reserve about {reserve:.0%}."
    )
    return BuildingProgram(
        building_type=building_type, reasoning=reasoning, floor_count=floors, area_per_floor=area,
        method=method, cores=cores, floors=floor_programs, load_bearing_walls=load_bearing,
        requests=record_requests(records, asked, placed, floor_programs, why_not),
    )

