"""Where a robot can go on one floor: the navigability checks of a house JSON (issue 17).

An agent of radius ``radius`` keeps ``margin`` from everything solid, so its centre stays at least
``clearance = radius + margin`` from every solid wall and every object, and a passage lets it
through when it is at least ``2 · clearance`` wide (0.6 m for AI2-THOR's 0.25 m agent with a
0.05 m margin). The geometry is exact (shapely), not a grid:

- the floor's free space is the union of its rooms, shrunk by the clearance from the outside,
  minus every solid wall piece (a non-empty wall without its door holes) grown by the clearance.
  Door holes cut both sides of a wall (wall1's hole is wall0's mirrored, as the loader cuts it);
  a stretch is open only where both of its walls are ``empty``;
- :func:`unreachable_rooms`: with every object removed, the rooms (stair and elevator cores
  among them) with no free space connected to the spawn pose;
- :func:`disconnected_entrances`: inside one room, with its floor objects in place, the doors and
  openings that the agent cannot walk between without leaving the room (a strip narrower than the
  agent, or furniture, cuts them apart).

The ``sim`` helpers and the measurements use the same functions, so a figure quoted in the README
and an error of ``mansion validate`` are the same test.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np
import shapely
from shapely.geometry import LineString, MultiLineString, MultiPolygon, Point, Polygon
from shapely.geometry.base import BaseGeometry
from shapely.strtree import STRtree

from mansion.placement import check
from mansion.scene.databases import asset_ids
from mansion.scene.entrances import RoomEntrance, room_entrances
from mansion.scene.house import AgentPose, Door, House, Wall

__all__ = [
    "AGENT_RADIUS",
    "MARGIN",
    "Obstacles",
    "RoomCut",
    "disconnected_entrances",
    "blocked_entrances",
    "floor_objects",
    "free_space",
    "open_space",
    "reached_rooms",
    "without",
    "wall_pieces",
    "solid_wall_pieces",
    "spawn_pose",
    "unreachable_rooms",
]

#: AI2-THOR's agents fit in a circle of this radius (m).
AGENT_RADIUS = 0.25
#: Room kept between the agent and anything solid (m): passages must be 2 · (0.25 + 0.05) wide.
MARGIN = 0.05
#: Geometry tolerance (m): a passage exactly 2 · clearance wide still lets the agent through.
_TOL = 5e-3
#: Free space this close to a door or opening (beyond the clearance) counts as its doorstep (m).
_DOORSTEP = 0.05
#: A room counts as reached when this much of its floor is reached free space (m²).
_AREA = 1e-4
#: Objects whose bottom is higher than this do not block the agent (wall-mounted pictures) (m).
_OVERHEAD = 1.6
#: Objects lower than this (rugs, dog beds) the agent's collider steps over (m).
_UNDERFOOT = 0.2

Pt = tuple[float, float]


def _ring(points: Iterable[object]) -> Polygon:
    return Polygon([(p.x, p.z) for p in points])  # type: ignore[attr-defined]


def _room_polygons(house: House) -> dict[str, Polygon]:
    out = {}
    for room in house.rooms:
        poly = _ring(room.floor_polygon)
        if not poly.is_valid:
            poly = poly.buffer(0)
        if poly.area > 0:
            out[room.id] = poly
    return out


def _cut(span: tuple[float, float], holes: list[tuple[float, float]]) -> list[tuple[float, float]]:
    pieces = [span]
    for lo, hi in holes:
        nxt = []
        for a, b in pieces:
            if hi <= a or lo >= b:
                nxt.append((a, b))
                continue
            if lo > a:
                nxt.append((a, lo))
            if hi < b:
                nxt.append((hi, b))
        pieces = nxt
    return [(a, b) for a, b in pieces if b - a > 1e-6]


def solid_wall_pieces(house: House) -> list[LineString]:
    """Every piece of wall the agent cannot cross: each non-empty wall minus its door holes (a
    stretch whose two walls are both empty is an opening and has no piece)."""
    return wall_pieces(house.walls, house.doors)


def wall_pieces(all_walls: list[Wall], doors: list[Door]) -> list[LineString]:
    """:func:`solid_wall_pieces` of these walls and doors (a house still being built)."""
    holes: dict[str, list[tuple[float, float]]] = {}
    walls = {w.id: w for w in all_walls}
    for door in doors:
        if len(door.hole_polygon) < 2:
            continue
        lo, hi = door.hole_polygon[0].x, door.hole_polygon[-1].x
        holes.setdefault(door.wall0, []).append((lo, hi))
        w1 = walls.get(door.wall1)
        if w1 is not None and door.wall1 != door.wall0:
            (a, b) = w1.segment()
            n = math.dist(a, b)
            holes.setdefault(door.wall1, []).append((n - hi, n - lo))
    ends = []
    for wall in all_walls:
        if wall.empty:
            continue
        a, b = wall.segment()
        n = math.dist(a, b)
        if n <= 0:
            continue
        for t0, t1 in _cut((0.0, n), holes.get(wall.id, [])):
            p = (a[0] + (b[0] - a[0]) * t0 / n, a[1] + (b[1] - a[1]) * t0 / n)
            q = (a[0] + (b[0] - a[0]) * t1 / n, a[1] + (b[1] - a[1]) * t1 / n)
            ends.append((p, q))
    # made in one call: a floor has a few hundred pieces
    return list(shapely.linestrings(ends)) if ends else []


def free_space(house: House, clearance: float, obstacles: Iterable[Polygon] = ()) -> BaseGeometry:
    """Where the agent's centre may stand on the floor: at least ``clearance`` from the outside,
    every solid wall piece and every ``obstacles`` footprint."""
    return open_space(_room_polygons(house).values(), solid_wall_pieces(house), clearance, obstacles)


def open_space(
    rooms: Iterable[Polygon], pieces: list[LineString], clearance: float,
    obstacles: Iterable[Polygon] = (),
) -> BaseGeometry:
    """:func:`free_space` of these room polygons and solid wall pieces."""
    c = clearance - _TOL
    floor = shapely.union_all(list(rooms))
    space = floor.buffer(-c)
    inner = _inner_pieces(pieces, floor)
    if inner:
        # the pieces grown as one geometry: the same region as each grown and then unioned (no
        # difference in area on fifteen dataset buildings' floors), in half the time; merged
        # into polylines first, whose round joins are the round caps they replace (the same
        # region to 1e-9 m² on 185 dataset floors), in 60 % of that
        space = space.difference(shapely.line_merge(MultiLineString(inner)).buffer(c))
    return without(space, obstacles, clearance)


def without(space: BaseGeometry, obstacles: Iterable[Polygon], clearance: float) -> BaseGeometry:
    """``space`` less every point within ``clearance`` of an obstacle: the free space with them
    standing in it (equal to building it with them, without redoing the walls)."""
    blocked = _grow(list(obstacles), clearance)
    return space.difference(blocked) if blocked is not None else space


def _grow(footprints: list[Polygon], clearance: float) -> BaseGeometry | None:
    """Where ``footprints`` keep the agent's centre: grown by the clearance (less the tolerance)
    as one geometry, the union of each grown with round corners of 16 segments a quarter (as
    :meth:`Polygon.buffer` grows it: the validator's answers on the real houses hang on it) in
    40 % of the time. None for no footprint."""
    return MultiPolygon(footprints).buffer(clearance - _TOL) if footprints else None


def _inner_pieces(pieces: list[LineString], floor: BaseGeometry) -> list[LineString]:
    """The wall pieces that shape the free space: each once (the two walls of a pair give the
    same pieces), and not those on the floor's outline (its inward buffer already keeps the agent
    off them). The union of the buffers is the same; measured on a seven-storey hospital's
    floors, the free space takes 0.18 s instead of 0.43 s."""
    if not pieces:
        return []
    seen: dict[tuple[tuple[float, float], ...], LineString] = {}
    # every piece's points read in one call (a floor has a few hundred pieces)
    coords = shapely.get_coordinates(pieces).tolist()
    starts = np.cumsum([0, *shapely.get_num_coordinates(pieces).tolist()]).tolist()
    for k, piece in enumerate(pieces):
        ends = sorted((round(x, 6), round(y, 6)) for x, y in coords[starts[k]:starts[k + 1]])
        seen.setdefault(tuple(ends), piece)
    outline = floor.boundary.buffer(1e-6)
    shapely.prepare(outline)
    kept = list(seen.values())
    on_outline = shapely.covers(outline, kept)
    return [s for s, out in zip(kept, on_outline.tolist(), strict=True) if not out]


def reached_rooms(space: BaseGeometry, rooms: dict[str, Polygon], start: Pt) -> set[str]:
    """The rooms the piece of ``space`` nearest ``start`` (within 0.5 m) reaches."""
    p = Point(start)
    parts = _parts(space)
    if not parts:
        return set()
    near = min(parts, key=lambda g: g.distance(p))
    if near.distance(p) > 0.5:
        return set()
    return {rid for rid, poly in rooms.items() if _clip(near, poly).area > _AREA}


def _clip(space: BaseGeometry, poly: Polygon) -> BaseGeometry:
    """``space.intersection(poly)``, with ``space`` first cut to the polygon's box by GEOS's fast
    rectangle clipping: the overlay then sees only the room's share of a floor-wide space (a
    third of the time on dataset floors). The fast clipping promises no valid output; should
    the overlay reject it, the plain intersection answers."""
    try:
        return shapely.intersection(shapely.clip_by_rect(space, *poly.bounds), poly)
    except shapely.errors.GEOSException:
        return space.intersection(poly)


def _parts(geom: BaseGeometry) -> list[Polygon]:
    return [g for g in getattr(geom, "geoms", [geom]) if isinstance(g, Polygon) and not g.is_empty]


def spawn_pose(house: House) -> AgentPose | None:
    """The agent's start: ``metadata.agentPoses`` (its ``default``, else its first) or the older
    ProcTHOR ``metadata.agent``."""
    poses = house.metadata.agent_poses
    if poses:
        return poses.get("default") or next(iter(poses.values()))
    older = (house.metadata.model_extra or {}).get("agent")
    if isinstance(older, dict):
        try:
            return AgentPose.model_validate(older)
        except ValueError:
            return None
    return None


def unreachable_rooms(
    house: House, *, radius: float = AGENT_RADIUS, margin: float = MARGIN,
    start: Pt | None = None, space: BaseGeometry | None = None,
) -> list[str] | None:
    """The rooms (cores included) an agent of ``radius`` keeping ``margin`` cannot reach from the
    spawn pose (or ``start``) with every object removed, in the house's order. None when the
    house has no spawn pose or the agent cannot stand anywhere near it (0.5 m). ``space``: the
    house's :func:`free_space` at ``radius + margin``, when the caller has it already."""
    if start is None:
        pose = spawn_pose(house)
        if pose is None:
            return None
        start = (pose.position.x, pose.position.z)
    if space is None:
        space = free_space(house, radius + margin)
    p = Point(start)
    parts = _parts(space)
    if not parts:
        return None
    near = min(parts, key=lambda g: g.distance(p))
    if near.distance(p) > 0.5:
        return None
    return [rid for rid, poly in _room_polygons(house).items()
            if _clip(near, poly).area <= _AREA]


@dataclass(frozen=True)
class RoomCut:
    """A room whose doors and openings fall apart inside it: ``groups`` of entrance ids the agent
    walks between (one group per piece of free space), ``blocked`` the entrances no free space
    reaches (``furniture``: blocked only once the room's objects stand in it)."""

    room: str
    groups: list[list[str]]
    blocked: list[str]
    furniture: bool


def floor_objects(house: House, room: str | None = None) -> list[Polygon]:
    """Footprints of the house's floor objects (of ``room`` when given) that stand in the agent's
    way: known assets (the loader skips the others) whose bottom is below the agent's head."""
    return [fp for rid, fp in _floor_objects(house) if room is None or rid is None or rid == room]


def _floor_objects(house: House) -> list[tuple[str | None, Polygon]]:
    """:func:`floor_objects` with the room each names, in the house's order."""
    db = asset_ids()
    out = []
    for obj in house.objects:
        rec = db.get(obj.asset_id)
        if rec is None:
            continue
        bb = rec["boundingBox"]
        if obj.position.y - bb["y"] / 2 > _OVERHEAD or obj.position.y + bb["y"] / 2 < _UNDERFOOT:
            continue
        fp = check.footprint((obj.position.x, obj.position.z), bb["x"], bb["z"], obj.rotation.y)
        out.append((obj.room, fp))
    return out


@dataclass(frozen=True)
class Obstacles:
    """A floor's objects in the agent's way (:func:`floor_objects`) with the room each names, and
    the clearance they are grown by: what :func:`disconnected_entrances` and
    :func:`blocked_entrances` subtract from the free space, found once per floor for both."""

    rooms: list[str | None]
    footprints: list[Polygon]
    clearance: float

    @classmethod
    def of(cls, house: House, clearance: float) -> Obstacles:
        placed = _floor_objects(house)
        return cls([rid for rid, _ in placed], [fp for _, fp in placed], clearance)

    def in_room(self, room: str) -> list[Polygon]:
        """The footprints of the objects that name ``room`` or no room."""
        return [fp for rid, fp in zip(self.rooms, self.footprints, strict=True) if rid is None or rid == room]

    def grown(self, footprints: list[Polygon]) -> BaseGeometry | None:
        """:func:`_grow` at these obstacles' clearance."""
        return _grow(footprints, self.clearance)


def _obstacles(house: House, clearance: float, given: Obstacles | None) -> Obstacles:
    if given is None:
        return Obstacles.of(house, clearance)
    if abs(given.clearance - clearance) > 1e-12:
        raise ValueError(f"obstacles grown by {given.clearance} m, not by the clearance {clearance} m")
    return given


def _groups(space: BaseGeometry, ways: list[RoomEntrance], reach: float) -> tuple[list[list[str]], list[str]]:
    """Entrances grouped by the pieces of ``space`` they open onto (an entrance touching two
    pieces joins them: the agent crosses through the doorway), and those touching none."""
    parts = _parts(space)
    root = list(range(len(parts)))

    def find(k: int) -> int:
        while root[k] != k:
            root[k] = root[root[k]]
            k = root[k]
        return k

    blocked: list[str] = []
    touches: list[tuple[str, int]] = []
    for e in ways:
        line = LineString([e.a, e.b])
        touching = [k for k, g in enumerate(parts) if g.distance(line) <= reach]
        if not touching:
            blocked.append(e.id)
            continue
        for k in touching[1:]:
            root[find(k)] = find(touching[0])
        touches.append((e.id, touching[0]))
    by_root: dict[int, list[str]] = {}
    for eid, k in touches:
        by_root.setdefault(find(k), []).append(eid)
    return list(by_root.values()), blocked


def _passable(ways: list[RoomEntrance], clearance: float) -> list[RoomEntrance]:
    """The ways an agent can go through: at least 2 · clearance wide, or part of a longer gap (an
    opening split into wall pieces at a neighbour's corner)."""
    def ends(e: RoomEntrance) -> set[tuple[float, float]]:
        return {(round(e.a[0], 4), round(e.a[1], 4)), (round(e.b[0], 4), round(e.b[1], 4))}

    return [e for e in ways if e.width >= 2 * clearance - _TOL
            or any(o is not e and ends(o) & ends(e) for o in ways)]


def disconnected_entrances(
    house: House, *, radius: float = AGENT_RADIUS, margin: float = MARGIN,
    objects: bool = True, space: BaseGeometry | None = None, obstacles: Obstacles | None = None,
) -> list[RoomCut]:
    """Every room whose doors and openings the agent cannot walk between inside it: a strip the
    agent cannot pass is not part of the walkable room, and (with ``objects``) the room's floor
    objects stand in the way. A room with one entrance is cut only when that entrance is blocked
    by its objects. ``space``: as for :func:`unreachable_rooms`; ``obstacles``: the floor's
    :class:`Obstacles` at this clearance, when the caller has them already."""
    c = radius + margin
    reach = c + _DOORSTEP
    polys = _room_polygons(house)
    # where the agent's centre may stand in the room: the floor's free space (the doorways
    # open, so an agent crossing a thin room from door to door facing it stays in it)
    floor = free_space(house, c) if space is None else space
    ways_by_room = room_entrances(house)
    placed = _obstacles(house, c, obstacles) if objects else None
    out = []
    for rid, poly in polys.items():
        ways = _passable(ways_by_room.get(rid, []), c)
        if not ways:
            continue
        bare = _clip(floor, poly)
        groups, blocked = _groups(bare, ways, reach)
        furniture = False
        if placed is not None and not blocked and len(groups) <= 1:
            grown = placed.grown(placed.in_room(rid))
            if grown is not None:
                space = bare.difference(grown)
                groups, blocked = _groups(space, ways, reach)
                furniture = True
        if len(ways) == 1 and not (furniture and blocked):
            continue
        if len(groups) > 1 or blocked:
            out.append(RoomCut(rid, groups, blocked, furniture))
    return out


def blocked_entrances(
    house: House, *, radius: float = AGENT_RADIUS, margin: float = MARGIN,
    start: Pt | None = None, space: BaseGeometry | None = None, obstacles: Obstacles | None = None,
) -> list[tuple[str, str]]:
    """(room, entrance id) of every door or opening the agent can pass (:func:`_passable`) whose
    doorstep in that room it reached from the spawn with the objects removed but no longer
    reaches with the floor objects in place (the furniture shuts it off). Empty when the house
    has no usable spawn. ``space``: as for :func:`unreachable_rooms` (the free space without
    objects); ``obstacles`` as for :func:`disconnected_entrances`."""
    if start is None:
        pose = spawn_pose(house)
        if pose is None:
            return []
        start = (pose.position.x, pose.position.z)
    c = radius + margin
    p = Point(start)

    def reached(parts: list[Polygon]) -> Polygon | None:
        if not parts:
            return None
        near = min(parts, key=lambda g: g.distance(p))
        return near if near.distance(p) <= 0.5 else None

    empty = free_space(house, c) if space is None else space
    bare = reached(_parts(empty))
    if bare is None:
        return []
    placed = _obstacles(house, c, obstacles)
    grown = placed.grown(placed.footprints)
    furnished = _parts(empty.difference(grown)) if grown is not None else _parts(empty)
    full = reached(furnished)
    # A doorstep that no grown object and no piece of furnished space other than the reached
    # one touches is reached with the objects as without them (there the furnished space is the
    # empty one, all of it reached), so only the others are measured. The test is generous: the
    # step's box (square caps hold the round-capped step), objects within the clearance of it.
    objects = STRtree(placed.footprints)
    pockets = STRtree([g for g in furnished if g is not full])
    polys = _room_polygons(house)
    out = []
    for rid, all_ways in room_entrances(house).items():
        # a gap narrower than the agent is no way in (as the furnishing and
        # :func:`disconnected_entrances` hold): its doorstep is not the agent's to reach
        ways = _passable(all_ways, c)
        poly = polys.get(rid)
        if poly is None or not ways:
            continue
        if full is not None:
            boxes = shapely.buffer(shapely.linestrings([[e.a, e.b] for e in ways]), c + _DOORSTEP, cap_style="square")
            touched = {*objects.query(boxes, predicate="dwithin", distance=c)[0].tolist(),
                       *pockets.query(boxes, predicate="intersects")[0].tolist()}
            ways = [e for k, e in enumerate(ways) if k in touched]
            if not ways:
                continue
        # each doorstep lies in the room: cut the floor-wide spaces to it once, not per door, and
        # measure the room's doorsteps in one call each
        steps = shapely.intersection(shapely.buffer(shapely.linestrings([[e.a, e.b] for e in ways]), c + _DOORSTEP), poly)
        seen = shapely.area(shapely.intersection(_clip(bare, poly), steps)) > _AREA
        kept = np.zeros(len(ways), dtype=bool)
        k = np.flatnonzero(seen)
        if full is not None and len(k):
            kept[k] = shapely.area(shapely.intersection(_clip(full, poly), steps[k])) > _AREA
        out += [(rid, e.id) for e, s, f in zip(ways, seen.tolist(), kept.tolist(), strict=True) if s and not f]
    return out
