"""Stairs and elevators, which AI2-THOR has no asset for: flights of real steps, landings, the
slab openings above them and an elevator car, built from the cores' records (box, floors served,
the door on each floor).

A stair flight climbs one floor height in risers of at most ``MAX_RISE`` and treads of at least
``MIN_GOING`` (the usual building-code bounds). When one straight run fits the core's length it
runs along the lane away from the door, every floor's flight stacked above the last (so the
headroom is a full floor height everywhere) and the lane by the door stays floor to walk along;
in a shorter core the flight turns once: a run up one lane to a half landing and back down the
other, beside a floor landing at the end nearest the door.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from shapely.geometry import Polygon
from shapely.geometry import box as rect

from mansion.exceptions import InvalidInputError
from mansion.export.looks import CAR, STEP
from mansion.export.meshes import Mesh, box, merge, transformed
from mansion.export.model import Node

__all__ = ["MAX_RISE", "MIN_GOING", "CorePlan", "car_node", "flight_node", "plan_core"]

MAX_RISE = 0.18
MIN_GOING = 0.25
_MAX_GOING = 0.30
_WAIST = 0.15  # concrete under each tread's nosing line
_CAR_HEIGHT = 2.4


@dataclass(frozen=True)
class CorePlan:
    """A core's box in its own frame: u along its long side from the end it starts at, v across
    from the lane by the door; ``matrix`` maps (u, y, v) to the floor's (x, y, z)."""

    id: str
    kind: str
    box: tuple[float, float, float, float]
    length: float
    width: float
    matrix: np.ndarray
    #: The door is on a short end (u = 0) rather than on a long side (v = 0).
    door_on_end: bool = False

    def world(self, shape: Polygon) -> Polygon:
        """A (u, v) polygon in the floor's (x, z)."""
        m = self.matrix
        pts = [(m[0, 0] * u + m[0, 2] * v + m[0, 3], m[2, 0] * u + m[2, 2] * v + m[2, 3]) for u, v in shape.exterior.coords]
        return Polygon(pts)


def plan_core(core_id: str, kind: str, box_: tuple[float, float, float, float], door: tuple[float, float] | None) -> CorePlan:
    """The frame of a core: long axis, the start end and the door lane chosen from where its door
    is (``door``: the door's centre on the floor plane, None when the core has none)."""
    x0, z0, x1, z1 = box_
    along_x = (x1 - x0) >= (z1 - z0)
    length, width = (x1 - x0, z1 - z0) if along_x else (z1 - z0, x1 - x0)
    cx, cz = (x0 + x1) / 2, (z0 + z1) / 2
    du, dv = (0.0, 0.0) if door is None else ((door[0] - cx, door[1] - cz) if along_x else (door[1] - cz, door[0] - cx))
    # u runs from the end nearer the door (a turning stair lands there), v away from the door.
    su = -1.0 if du > 1e-6 else 1.0
    sv = -1.0 if dv > 1e-6 else 1.0
    ax_u = np.array([su, 0.0, 0.0]) if along_x else np.array([0.0, 0.0, su])
    ax_v = np.array([0.0, 0.0, sv]) if along_x else np.array([sv, 0.0, 0.0])
    origin = np.array([x0 if su > 0 else x1, 0.0, 0.0]) if along_x else np.array([0.0, 0.0, z0 if su > 0 else z1])
    if along_x:
        origin[2] = z0 if sv > 0 else z1
    else:
        origin[0] = x0 if sv > 0 else x1
    m = np.eye(4)
    m[:3, 0], m[:3, 1], m[:3, 2], m[:3, 3] = ax_u, [0.0, 1.0, 0.0], ax_v, origin
    on_end = door is not None and abs(du) / max(length, 1e-9) > abs(dv) / max(width, 1e-9)
    return CorePlan(core_id, kind, box_, length, width, m, on_end)


@dataclass(frozen=True)
class Flight:
    risers: int
    rise: float
    going: float
    straight: bool
    #: (u0, u1, v0, v1, top) of each tread, bottom to top.
    treads: list[tuple[float, float, float, float, float]]
    #: (u0, u1, v0, v1, top) of the half landing pieces (a turning flight only).
    landings: list[tuple[float, float, float, float, float]]
    #: The slab opening the flight needs in the floor it arrives at, in (u, v).
    opening: tuple[float, float, float, float]


def _flight(plan: CorePlan, height: float) -> Flight:
    n = math.ceil(height / MAX_RISE - 1e-9)
    rise = height / n
    length, width = plan.length, plan.width
    if (n - 1) * MIN_GOING <= length + 1e-9:
        going = max(MIN_GOING, min(_MAX_GOING, (length - 1.2) / max(n - 1, 1)))
        if (n - 1) * going > length:
            going = MIN_GOING
        run = (n - 1) * going
        start = (length - run) / 2
        v0, v1 = width / 2, width  # the lane away from the door
        treads = [(start + (i - 1) * going, start + i * going, v0, v1, i * rise) for i in range(1, n)]
        return Flight(n, rise, going, True, treads, [], (start, start + run, v0, v1))
    # Turning flight: up the far lane to a half landing at the far end, back down the door lane.
    n1 = (n + 1) // 2
    n2 = n - n1
    going = MIN_GOING
    room = length - (n1 - 1) * going
    if room < 0.6:
        raise InvalidInputError(
            f"stair core {plan.id} is {length:.2f} m long: too short for a flight of {height:.2f} m "
            f"(needs {(n1 - 1) * going + 0.6:.2f} m with one turn)"
        )
    start = min(1.0, room / 2)
    half = width / 2
    treads = [(start + (i - 1) * going, start + i * going, half, width, i * rise) for i in range(1, n1)]
    top1 = start + (n1 - 1) * going
    low2 = start + (n2 - 1) * going
    landings = [(top1, length, half, width, n1 * rise), (low2, length, 0.0, half, n1 * rise)]
    treads += [(low2 - j * going, low2 - (j - 1) * going, 0.0, half, (n1 + j) * rise) for j in range(1, n2)]
    return Flight(n, rise, going, False, treads, landings, (start, length, 0.0, width))


def _block(u0: float, u1: float, v0: float, v1: float, top: float, rise: float) -> Mesh:
    return box((u0, max(0.0, top - rise - _WAIST), v0), (u1, top, v1))


def flight_node(plan: CorePlan, height: float, lower: int, upper: int, floor: str) -> tuple[Node, Polygon]:
    """The flight from floor ``lower`` up to ``upper`` (``height`` apart), in the lower floor's
    frame, one child node per step and landing; and the opening it needs in the upper floor."""
    f = _flight(plan, height)
    name = f"{floor}/{plan.id}/flight_{lower}_{upper}"
    node = Node(
        name, "flight",
        info={"core": plan.id, "from_floor": lower, "to_floor": upper, "risers": f.risers,
              "rise": round(f.rise, 6), "going": round(f.going, 6), "height": round(height, 6),
              "turns": 0 if f.straight else 1},
    )
    for i, (u0, u1, v0, v1, top) in enumerate(f.treads, start=1):
        node.add(Node(f"{name}/step_{i:02d}", "step", mesh=transformed(_block(u0, u1, v0, v1, top, f.rise), plan.matrix),
                      look=STEP, physics="collider", info={"top": round(top, 6)}))
    for i, (u0, u1, v0, v1, top) in enumerate(f.landings, start=1):
        node.add(Node(f"{name}/landing_{i}", "landing", mesh=transformed(_block(u0, u1, v0, v1, top, f.rise), plan.matrix),
                      look=STEP, physics="collider", info={"top": round(top, 6)}))
    u0, u1, v0, v1 = f.opening
    return node, plan.world(rect(u0, v0, u1, v1))


def car_node(plan: CorePlan, floor: str) -> Node:
    """The elevator car parked at the lowest floor it serves, open toward its door."""
    inset, wall = 0.08, 0.05
    u0, u1, v0, v1 = inset, plan.length - inset, inset, plan.width - inset
    h, y0, y1 = _CAR_HEIGHT, 0.1, _CAR_HEIGHT - 0.08
    parts = [box((u0, 0.0, v0), (u1, y0, v1)), box((u0, y1, v0), (u1, h, v1))]  # floor, roof
    if plan.door_on_end:  # open at u = 0: back at u1, sides along v
        parts += [box((u1 - wall, y0, v0), (u1, y1, v1)), box((u0, y0, v0), (u1 - wall, y1, v0 + wall)),
                  box((u0, y0, v1 - wall), (u1 - wall, y1, v1))]
    else:  # open at v = 0: back at v1, sides at both ends
        parts += [box((u0, y0, v1 - wall), (u1, y1, v1)), box((u0, y0, v0), (u0 + wall, y1, v1 - wall)),
                  box((u1 - wall, y0, v0), (u1, y1, v1 - wall))]
    return Node(f"{floor}/{plan.id}/car", "elevator_car", mesh=transformed(merge(parts), plan.matrix), look=CAR,
                physics="collider", info={"core": plan.id})
