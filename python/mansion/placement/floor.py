"""Furnishing every room of a floor of a :class:`mansion.Building`.

Until the scene stage (issue 5) writes the real doors, a floor's doors are derived from its room
graph: one 0.9 m door in the middle of the longest shared wall of every ``access`` edge whose
rooms realise it (shared boundary of at least 1 m). When the scenes land, pass their doors in.
"""

from __future__ import annotations

from shapely.geometry import LineString, MultiLineString, Polygon
from shapely.ops import linemerge

from mansion.exceptions import MansionError
from mansion.models.building import Building
from mansion.models.objects import RoomPlacement
from mansion.placement.offline import plan_objects, room_kind
from mansion.placement.place import PlaceOptions, RoomSpec, furnish_rooms

__all__ = ["furnish_floor", "layout_doors"]

Point = tuple[float, float]
DOOR_WIDTH = 0.9


def _longest_shared(a: Polygon, b: Polygon) -> LineString | None:
    shared = a.boundary.intersection(b.boundary)
    lines = [g for g in getattr(shared, "geoms", [shared]) if isinstance(g, LineString) and g.length > 0]
    if not lines:
        return None
    merged = linemerge(MultiLineString(lines)) if len(lines) > 1 else lines[0]
    parts = list(getattr(merged, "geoms", [merged]))
    # a merged run may bend round a corner; keep its longest straight segment
    segs = [LineString(s) for p in parts for s in zip(p.coords[:-1], p.coords[1:])]
    return max(segs, key=lambda s: s.length)


def layout_doors(building: Building, floor: int) -> dict[str, list[tuple[Point, Point]]]:
    """Door segments per room of a floor, derived from the floor's access edges."""
    f = building.floors[floor]
    polys = {r.id: Polygon(r.polygon) for r in f.layout.rooms}
    doors: dict[str, list[tuple[Point, Point]]] = {rid: [] for rid in polys}
    for e in f.graph.edges:
        if e.kind != "access" or e.source not in polys or e.target not in polys:
            continue
        seg = _longest_shared(polys[e.source], polys[e.target])
        if seg is None or seg.length < 1.0:
            continue
        mid = seg.length / 2
        a, b = seg.interpolate(mid - DOOR_WIDTH / 2), seg.interpolate(mid + DOOR_WIDTH / 2)
        door = ((a.x, a.y), (b.x, b.y))
        doors[e.source].append(door)
        doors[e.target].append(door)
    return doors


def furnish_floor(
    building: Building,
    floor: int,
    seed: int = 0,
    doors: dict[str, list[tuple[Point, Point]]] | None = None,
    options: PlaceOptions | None = None,
) -> dict[str, RoomPlacement | MansionError]:
    """Offline object plans and placements for every furnishable room of a floor (cores and
    circulation stay empty; a room without a door cannot be checked for reachability and is
    reported as an error, as is any room the engine rejects)."""
    f = building.floors[floor]
    doors = doors if doors is not None else layout_doors(building, floor)
    jobs = []
    for k, r in enumerate(f.layout.rooms):
        if r.type in ("stair", "elevator") or room_kind(r.room_type) == "circulation":
            continue
        ring = [(float(x), float(y)) for x, y in r.polygon]
        spec = RoomSpec(room_id=r.id, polygon=ring, doors=doors.get(r.id, []))
        plan = plan_objects(r.id, r.room_type, ring, building.program.building_type, seed=seed + k)
        jobs.append((spec, plan))
    results = furnish_rooms(jobs, seed=seed, options=options)
    return {spec.room_id: res for (spec, _), res in zip(jobs, results)}
