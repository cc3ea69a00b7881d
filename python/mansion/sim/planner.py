"""Routes across a building: walks on each floor's grid joined by the cores.

The planner sees every floor (it is the map an oracle has): a Dijkstra search over (floor, core
landing) states whose edges are walks on a floor (BFS on its grid, in metres) and rides (an
elevator to any floor it serves, a stair one floor up or down), ending where a goal mask of the
goal's floor is reached. A route comes back as the skill calls that walk it. The task sampler
uses it to keep only tasks whose objects and destination are reachable, the oracle to solve them.
"""

from __future__ import annotations

import heapq
import itertools
from dataclasses import dataclass
from typing import Any, Callable

import numpy as np

from mansion.sim.env import INTERACT, LANDING_RADIUS
from mansion.sim.grid import NavGrid, box_distance
from mansion.sim.world import Building, FloorState

__all__ = ["BuildingMap", "Route"]

#: What a ride costs in the search, in metres of walking: rides are cheap but not free, so a
#: route takes no needless detour through a core.
RIDE_COST = 5.0

Cell = tuple[int, int]
GoalMask = Callable[[FloorState], np.ndarray]


@dataclass(frozen=True)
class Route:
    actions: tuple[tuple[Any, ...], ...]  # skill calls up to (not including) the goal's own
    floor: int  # the goal's floor
    cell: Cell  # where the walk ends on it
    metres: float  # walking length estimate (BFS steps × cell)


class BuildingMap:
    """Every floor's state and grid, built on demand; ``states`` overrides floors (the env's
    loaded floor)."""

    def __init__(self, building: Building, cell: float, states: dict[int, FloorState] | None = None):
        self.building = building
        self.cell = cell
        self.states: dict[int, FloorState] = dict(states or {})

    def floor(self, f: int) -> FloorState:
        if f not in self.states:
            self.states[f] = self.building.floor_state(f, self.cell)
        return self.states[f]

    def grid(self, f: int) -> NavGrid:
        # a floor only ridden through needs its grid, not its objects: the building's grids of
        # unchanged floors spare parsing their houses
        if f not in self.states and f not in self.building.dirty:
            cached = self.building.grids.get(f)
            if cached is not None and cached.cell == self.cell:
                return cached
        return self.floor(f).grid

    def landing_mask(self, f: int, core: Any) -> np.ndarray | None:
        landing = self.building.landing(core, f)
        if landing is None:
            return None
        g = self.grid(f)
        px, pz = g.centres()
        return np.hypot(px - landing.pose.position.x, pz - landing.pose.position.z) <= LANDING_RADIUS

    def route(self, start_floor: int, start: Cell, goal_floor: int, goal: GoalMask) -> Route | None:
        """The cheapest way from ``start`` on ``start_floor`` to a cell of ``goal`` on
        ``goal_floor``, or None when no core connects them or the goal is not reached."""
        tie = itertools.count()
        # (cost, tie, floor, cell, actions, arrived_by_stair_core)
        heap: list[Any] = [(0.0, next(tie), start_floor, start, (), None)]
        done: set[tuple[int, Cell]] = set()
        cores = self.building.manifest.cores
        while heap:
            cost, _, f, cell, actions, via = heapq.heappop(heap)
            if f == -1:
                return Route(actions, goal_floor, cell, cost)
            if (f, cell) in done:
                continue
            done.add((f, cell))
            g = self.grid(f)
            dist = g.distances(cell)
            if f == goal_floor:
                best = _nearest(dist, goal(self.floor(f)))
                if best is not None:
                    heapq.heappush(heap, (cost + best[1] * self.cell, next(tie), -1, best[0], actions, None))
            for core in cores:
                if f not in core.floors:
                    continue
                mask = self.landing_mask(f, core)
                if mask is None:
                    continue
                here = _nearest(dist, mask)
                if here is None:
                    continue
                walk = () if via == core.id else (("GoToRoom", core.id),)
                # rides toward the goal only: straight to its floor when the core serves it,
                # else to the floors where another core may take over; stairs a floor closer
                if core.kind == "elevator":
                    ks = [goal_floor] if goal_floor in core.floors else core.floors
                    hops = [(k, walk + (("CallElevator",), ("UseElevator", k))) for k in ks if k != f]
                else:
                    hops = [(k, walk + (("TakeStairs", "Up" if k > f else "Down"),))
                            for k in (f + 1, f - 1) if k in core.floors and abs(k - goal_floor) < abs(f - goal_floor)]
                for k, acts in hops:
                    if self.building.landing(core, k) is None:
                        continue
                    arrive = self._arrival(k, core)
                    if arrive is None or (k, arrive) in done:
                        continue
                    heapq.heappush(heap, (cost + here[1] * self.cell + RIDE_COST, next(tie), k, arrive,
                                          actions + acts, core.id if core.kind == "stair" else None))
        return None

    def _arrival(self, f: int, core: Any) -> Cell | None:
        landing = self.building.landing(core, f)
        return self.grid(f).snap(landing.pose.position.x, landing.pose.position.z, within=0.6)

    # -- goal masks -----------------------------------------------------------------------------
    @staticmethod
    def object_goal(object_id: str) -> GoalMask:
        """Where ``GoToObject`` may end: within reach of the object, else within interaction."""

        def mask(st: FloorState) -> np.ndarray:
            info = st.objects.get(object_id)
            g = st.grid
            if info is None:  # not on that floor (a task for an edited variant of the building)
                return np.zeros(g.free.shape, dtype=bool)
            px, pz = g.centres()
            d = box_distance(px, pz, info.centre, info.props.width, info.props.depth, info.obj.rotation.y)
            # GoToObject stands within reach when it can, else within interaction distance
            return d <= INTERACT - g.cell

        return mask

    @staticmethod
    def room_goal(room: str) -> GoalMask:
        def mask(st: FloorState) -> np.ndarray:
            g = st.grid
            return g.label == g.room_ids.index(room)

        return mask


def _nearest(dist: np.ndarray, mask: np.ndarray) -> tuple[Cell, int] | None:
    cand = mask & (dist >= 0)
    if not cand.any():
        return None
    d = np.where(cand, dist, np.iinfo(np.int32).max)
    k = int(np.argmin(d))
    rc = np.unravel_index(k, d.shape)
    return (int(rc[0]), int(rc[1])), int(d.flat[k])
