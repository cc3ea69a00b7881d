"""``mansion eval placement``: the paper's object-placement benchmark on its four rooms.

The metrics are computed here from the placed objects alone, independently of the engine:

- #OB: floor objects whose footprint leaves the room by more than 1 cm;
- #CN: pairs of floor objects whose footprints overlap by more than 1e-4 m², except a chair or
  stool tucked under the table or desk it is paired with;
- #Rch: the share of floor objects with a cell of the agent's free space, connected to the door,
  within 0.5 m of the footprint (on its front side when it has one). The free space is rebuilt
  here with shapely and flooded with numpy (:mod:`mansion.placement.check`) from the cells within
  0.5 m in front of the door: a cell is free when its centre is in the room and at least the
  agent's radius from every wall (the outline without the door openings) and object.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np
from shapely.geometry import Polygon

from mansion.models.objects import ObjectPlan, PlacedObject, RoomPlacement
from mansion.placement import check
from mansion.placement.assets import TABLES, TUCKABLE
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

def footprint(o: PlacedObject) -> Polygon:
    """The object's footprint in plan coordinates (yaw 0 faces +y, 90 faces +x)."""
    return check.footprint((o.center[0], o.center[1]), o.size[0], o.size[1], o.yaw)


def reachable(result: RoomPlacement, cell: float = 0.05, reach: float = 0.5) -> list[bool]:
    """Per floor object, whether the agent reaches it (the definition in the module doc)."""
    room = RoomSpec(result.room_id, list(result.polygon), list(result.doors))
    fps = [footprint(o) for o in result.objects]
    space = check.FreeSpace.build(room.polygon, room.segments, fps, result.agent_radius, cell)
    # entered through the doorway: the cells just inside the first door
    seeds = np.zeros_like(space.free)
    if room.segments:
        seeds = space.in_front_of(*room.segments[0], reach)
    reached = space.flood(seeds)
    return [
        space.reaches(reached, fp, reach, ((o.center[0], o.center[1]), o.yaw, o.size[1]) if o.has_front else None)
        for o, fp in zip(result.objects, fps)
    ]


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
            tucked = (a.tucked_under == b.id and a.object_type in TUCKABLE and b.object_type in TABLES) or (
                b.tucked_under == a.id and b.object_type in TUCKABLE and a.object_type in TABLES
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
