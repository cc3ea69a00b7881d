"""``mansion eval placement``: the paper's object-placement benchmark on its four rooms.

The metrics are computed here from the placed objects alone, independently of the engine:

- #OB: floor objects whose footprint leaves the room by more than 1 cm;
- #CN: pairs of floor objects whose footprints overlap by more than 1e-4 m², except a chair or
  stool tucked under the table or desk it is paired with;
- #Rch: the share of floor objects with a cell of the agent's free space, connected to the door,
  within 0.5 m of the footprint (on its front side when it has one). The free space is rebuilt
  here with shapely and flooded with numpy: a cell is free when its centre is in the room and at
  least the agent's radius from every wall (the outline without the door openings) and object.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np
import shapely
from shapely.geometry import LineString, MultiLineString, Polygon, box
from shapely.affinity import rotate, translate

from mansion.models.objects import ObjectPlan, PlacedObject, RoomPlacement
from mansion.placement.assets import TUCKABLE
from mansion.placement.offline import plan_objects
from mansion.placement.place import PlaceOptions, RoomSpec, furnish_room

__all__ = ["PAPER", "ROOMS", "RoomScore", "evaluate_placement", "footprint", "reachable", "score_room"]

#: The paper's four rooms (issue 6), one 1 m door on the bottom wall of each.
ROOMS: dict[str, RoomSpec] = {
    "bedroom": RoomSpec("bedroom", [(0, 0), (4, 0), (4, 4), (0, 4)], [((0.3, 0.0), (1.3, 0.0))]),
    "classroom": RoomSpec("classroom", [(0, 0), (8, 0), (8, 8), (0, 8)], [((0.5, 0.0), (1.5, 0.0))]),
    "restaurant": RoomSpec(
        "restaurant", [(0, 0), (14, 0), (14, 6), (9, 6), (9, 10), (0, 10)], [((6.0, 0.0), (7.0, 0.0))]
    ),
    "library": RoomSpec(
        "library",
        [(0, 0), (18, 0), (18, 14), (12, 14), (12, 9), (6, 9), (6, 14), (0, 14)],
        [((8.5, 0.0), (9.5, 0.0))],
    ),
}

#: The paper's figures (Table "object placement quantitative comparison", ours): floor and small
#: objects (#Obj minus the small ones in parentheses).
PAPER: dict[str, tuple[float, float]] = {
    "bedroom": (13.4, 9.2), "classroom": (37.5, 19.8), "restaurant": (52.5, 25.6), "library": (54.3, 34.3),
}

_TABLES = frozenset({"Desk", "DiningTable", "CoffeeTable", "SideTable", "CounterTop"})


def footprint(o: PlacedObject) -> Polygon:
    """The object's footprint in plan coordinates (yaw 0 faces +y, 90 faces +x)."""
    w, d = o.size[0], o.size[1]
    shape = rotate(box(-w / 2, -d / 2, w / 2, d / 2), -o.yaw, origin=(0, 0))
    return translate(shape, o.center[0], o.center[1])


def _walls(room: RoomSpec) -> MultiLineString:
    outline = LineString([*room.polygon, room.polygon[0]])
    solid = outline
    for a, b in room.doors:
        solid = solid.difference(LineString([a, b]).buffer(1e-9, cap_style="flat"))
    parts = [g for g in getattr(solid, "geoms", [solid]) if g.length > 0]
    return MultiLineString([list(g.coords) for g in parts])


def _zones(room: RoomSpec) -> list[Polygon]:
    poly = Polygon(room.polygon)
    out = []
    for a, b in room.doors:
        ax, ay = a
        dx, dy = b[0] - ax, b[1] - ay
        w = math.hypot(dx, dy)
        nx, ny = -dy / w, dx / w
        mid = ((ax + b[0]) / 2 + nx * 1e-3, (ay + b[1]) / 2 + ny * 1e-3)
        if not poly.contains(shapely.Point(mid)):
            nx, ny = -nx, -ny
        out.append(Polygon([a, b, (b[0] + nx * w, b[1] + ny * w), (ax + nx * w, ay + ny * w)]))
    return out


def reachable(result: RoomPlacement, cell: float = 0.05, reach: float = 0.5) -> list[bool]:
    """Per floor object, whether the agent reaches it (the definition in the module doc)."""
    room = RoomSpec(result.room_id, list(result.polygon), list(result.doors))
    poly = Polygon(room.polygon)
    x0, y0, x1, y1 = poly.bounds
    w, h = math.ceil((x1 - x0) / cell), math.ceil((y1 - y0) / cell)
    xs = x0 + (np.arange(w) + 0.5) * cell
    ys = y0 + (np.arange(h) + 0.5) * cell
    gx, gy = np.meshgrid(xs, ys)
    px, py = gx.ravel(), gy.ravel()
    inside = shapely.contains_xy(poly, px, py)
    pts = shapely.points(px, py)
    r = result.agent_radius
    free = inside & (shapely.distance(pts, _walls(room)) >= r)
    fps = [footprint(o) for o in result.objects]
    if fps:
        free &= shapely.distance(pts, shapely.union_all(fps)) >= r
    free = free.reshape(h, w)
    seeds = np.zeros_like(free)
    zones = _zones(room)
    if zones:
        seeds = (shapely.contains_xy(zones[0], px, py) | shapely.intersects_xy(zones[0], px, py)).reshape(h, w)
    reached = seeds & free
    # flood fill by repeated 4-neighbour dilation inside the free cells
    while True:
        grown = reached.copy()
        grown[1:, :] |= reached[:-1, :]
        grown[:-1, :] |= reached[1:, :]
        grown[:, 1:] |= reached[:, :-1]
        grown[:, :-1] |= reached[:, 1:]
        grown &= free
        if (grown == reached).all():
            break
        reached = grown
    flat = reached.ravel()
    out = []
    for o, fp in zip(result.objects, fps):
        near = flat & (shapely.distance(pts, fp) < reach)
        if o.has_front and near.any():
            yaw = math.radians(o.yaw)
            fx, fy = math.sin(yaw), math.cos(yaw)
            ahead = (px - o.center[0]) * fx + (py - o.center[1]) * fy >= o.size[1] / 2 - 1e-9
            near &= ahead
        out.append(bool(near.any()))
    return out


@dataclass
class RoomScore:
    floor_obj: int
    small_obj: int
    ob: int
    cn: int
    rch: float
    seconds: float
    unreachable: list[str] = field(default_factory=list)


def score_room(result: RoomPlacement) -> RoomScore:
    """#OB, #CN and #Rch of one placement (see the module doc)."""
    poly = Polygon(result.polygon).buffer(0.01, join_style="mitre")
    fps = [footprint(o) for o in result.objects]
    ob = sum(not poly.contains(f) for f in fps)
    cn = 0
    for i, a in enumerate(result.objects):
        for j in range(i + 1, len(result.objects)):
            b = result.objects[j]
            if fps[i].intersection(fps[j]).area <= 1e-4:
                continue
            tucked = (a.tucked_under == b.id and a.object_type in TUCKABLE and b.object_type in _TABLES) or (
                b.tucked_under == a.id and b.object_type in TUCKABLE and a.object_type in _TABLES
            )
            cn += not tucked
    reach = reachable(result)
    n = len(result.objects)
    return RoomScore(
        floor_obj=n,
        small_obj=result.small_count,
        ob=ob,
        cn=cn,
        rch=100.0 * sum(reach) / n if n else 100.0,
        seconds=result.stats.seconds,
        unreachable=[o.id for o, ok in zip(result.objects, reach) if not ok],
    )


def evaluate_placement(
    runs: int = 10,
    seed: int = 0,
    rooms: list[str] | None = None,
    planner: object | None = None,
    options: PlaceOptions | None = None,
) -> dict[str, dict[str, float]]:
    """Mean figures per room over ``runs`` seeds, in the issue's JSON layout (rch in %; ob and
    cn are means too, so any non-zero value means some run failed)."""
    out: dict[str, dict[str, float]] = {}
    for name in rooms or list(ROOMS):
        room = ROOMS[name]
        scores = []
        for run in range(runs):
            s = seed + run
            plan: ObjectPlan
            if planner is None:
                plan = plan_objects(name, name, room.polygon, "", seed=s)
            else:
                plan = planner.plan(name, name, room.polygon, "")  # type: ignore[attr-defined]
            t = time.perf_counter()
            result = furnish_room(room, plan, seed=s, options=options)
            elapsed = time.perf_counter() - t
            score = score_room(result)
            # asset choice, the engine and the conversions; not the scoring above
            score.seconds = elapsed
            scores.append(score)
        m = len(scores)
        out[name] = {
            "obj": sum(x.floor_obj + x.small_obj for x in scores) / m,
            "floor_obj": sum(x.floor_obj for x in scores) / m,
            "small_obj": sum(x.small_obj for x in scores) / m,
            "ob": sum(x.ob for x in scores) / m,
            "cn": sum(x.cn for x in scores) / m,
            "rch": sum(x.rch for x in scores) / m,
            "seconds": sum(x.seconds for x in scores) / m,
        }
    return out
