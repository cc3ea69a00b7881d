"""Agents for the tasks, and how to plug in one's own.

An agent is a factory ``agent(env, task) -> policy``; the policy is called with each observation
and info dict and returns an action (``"GoToObject(id)"``, ``("UseElevator", 2)`` or a gym action
dict), or None when it is done. A class with ``__init__(self, env, task)`` and
``__call__(self, obs, info)`` is one. ``mansion eval tasks --agent module:callable`` loads one.

- ``OracleAgent`` knows the building (every floor's grid, every object): it plans over the floors
  and cores with :class:`BuildingMap` and walks the plan, replanning once if a skill fails.
- ``BaselineAgent`` has no map of the objects: it knows the rooms and cores of the floor it is on
  (the observation's landmarks) and the instruction's object type and floors; it takes the cores
  to the target floor, explores rooms nearest first until it sees an object of the type, takes
  the first it sees and delivers it.
"""

from __future__ import annotations

import importlib
import math
from typing import Any, Callable

from mansion.exceptions import InvalidInputError
from mansion.sim.planner import BuildingMap

__all__ = ["AGENTS", "BaselineAgent", "OracleAgent", "load_agent"]

Policy = Callable[[dict[str, Any], dict[str, Any]], Any]


class OracleAgent:
    def __init__(self, env: Any, task: Any, replans: int = 2):
        self.env, self.task = env, task
        self.replans = replans
        self.queue: list[tuple[Any, ...]] = []
        self.planned = False

    def plan(self) -> list[tuple[Any, ...]]:
        env, task = self.env, self.task
        bmap = BuildingMap(env.building, env.cell, {env.floor: env.state})
        cell = env.state.grid.snap(env.x, env.z, within=0.6)
        if cell is None:
            return []
        floor = env.floor
        actions: list[tuple[Any, ...]] = []
        dest = task.destination
        held = env.held
        for t in task.targets:
            if held is None or held.id != t.object_id:
                where = t.floor
                leg = bmap.route(floor, cell, where, BuildingMap.object_goal(t.object_id))
                if leg is None:
                    return actions
                actions += [*leg.actions, ("GoToObject", t.object_id), ("PickUp", t.object_id)]
                floor, cell = leg.floor, leg.cell
            goal = BuildingMap.object_goal(dest.receptacle) if dest.receptacle else BuildingMap.room_goal(dest.room)
            leg = bmap.route(floor, cell, dest.floor, goal)
            if leg is None:
                return actions
            if dest.receptacle:
                actions += [*leg.actions, ("GoToObject", dest.receptacle), ("Put", dest.receptacle)]
            else:
                actions += [*leg.actions, ("GoToRoom", dest.room)]
                if len(task.targets) > 1:
                    return actions  # one at a time: a room is reached holding the first
            floor, cell = leg.floor, leg.cell
            held = None
        return actions

    def __call__(self, obs: dict[str, Any], info: dict[str, Any]) -> Any:
        if self.planned and not info.get("success", True):
            if self.replans <= 0:
                return None
            self.replans -= 1
            self.queue = []
            self.planned = False
        if not self.planned:
            self.queue = self.plan()
            self.planned = True
        return self.queue.pop(0) if self.queue else None


class BaselineAgent:
    """Explores rooms nearest first; no map of the objects."""

    def __init__(self, env: Any, task: Any):
        self.task = task
        self.target_type = task.targets[0].object_type
        self.target_floor = task.targets[0].floor
        self.dest = task.destination
        self.visited: set[tuple[int, str]] = set()
        self.tried_cores: set[tuple[int, str]] = set()
        self.pending: list[tuple[Any, ...]] = []
        self.holding: str | None = None
        self.failed_objects: set[str] = set()

    def _to_floor(self, obs: dict[str, Any], floor: int) -> list[tuple[Any, ...]]:
        here = int(obs["floor"])
        cores = [(lm["id"], lm["type"], lm["position"]) for lm in obs["landmarks"] if lm["type"] in ("Elevator", "Stair")]
        x, z = float(obs["pose"][0]), float(obs["pose"][1])
        cores.sort(key=lambda c: (c[1] != "Elevator", math.dist((x, z), (float(c[2][0]), float(c[2][1]))), c[0]))
        for cid, kind, _ in cores:
            if (here, cid) in self.tried_cores:
                continue
            self.tried_cores.add((here, cid))
            if kind == "Elevator":
                return [("GoToRoom", cid), ("CallElevator",), ("UseElevator", floor)]
            return [("GoToRoom", cid), ("TakeStairs", "Up" if floor > here else "Down")]
        return []

    def __call__(self, obs: dict[str, Any], info: dict[str, Any]) -> Any:
        if not info.get("success", True):
            self.pending = []
        if self.pending:
            return self.pending.pop(0)
        here = int(obs["floor"])
        self.holding = obs["held"] or None
        if self.holding is None:
            if here != self.target_floor:
                self.pending = self._to_floor(obs, self.target_floor)
                return self.pending.pop(0) if self.pending else None
            for o in obs["objects"]:
                if o["type"] == self.target_type and o["id"] not in self.failed_objects:
                    self.failed_objects.add(o["id"])
                    self.pending = [("PickUp", o["id"])]
                    return ("GoToObject", o["id"])
            room = self._next_room(obs)
            if room is None:
                return None
            self.visited.add((here, room))
            return ("GoToRoom", room)
        if here != self.dest.floor:
            self.pending = self._to_floor(obs, self.dest.floor)
            return self.pending.pop(0) if self.pending else None
        if self.dest.receptacle:
            if self.holding and (here, "put") not in self.visited:
                self.visited.add((here, "put"))
                self.pending = [("Put", self.dest.receptacle)]
                return ("GoToObject", self.dest.receptacle)
            return None
        if obs["room"] != self.dest.room:
            if (here, "dest") in self.visited:
                return None
            self.visited.add((here, "dest"))
            return ("GoToRoom", self.dest.room)
        return None

    def _next_room(self, obs: dict[str, Any]) -> str | None:
        here = int(obs["floor"])
        x, z = float(obs["pose"][0]), float(obs["pose"][1])
        rooms = [(math.dist((x, z), (float(lm["position"][0]), float(lm["position"][1]))), lm["id"])
                 for lm in obs["landmarks"] if lm["type"] not in ("Elevator", "Stair")
                 and (here, lm["id"]) not in self.visited and lm["id"] != obs["room"]]
        if obs["room"]:
            self.visited.add((here, obs["room"]))
        return min(rooms)[1] if rooms else None


AGENTS: dict[str, Callable[..., Policy]] = {"oracle": OracleAgent, "baseline": BaselineAgent}


def load_agent(name: str) -> Callable[..., Policy]:
    """``oracle``, ``baseline`` or ``module:callable`` (a factory ``(env, task) -> policy``)."""
    if name in AGENTS:
        return AGENTS[name]
    if ":" not in name:
        raise InvalidInputError(f"agent {name!r}: give oracle, baseline or module:callable")
    module, attr = name.split(":", 1)
    try:
        obj: Any = importlib.import_module(module)
    except ImportError as exc:
        raise InvalidInputError(f"agent {name!r}: cannot import {module!r} ({exc})") from exc
    for part in attr.split("."):
        obj = getattr(obj, part, None)
        if obj is None:
            raise InvalidInputError(f"agent {name!r}: {module!r} has no {attr!r}")
    if not callable(obj):
        raise InvalidInputError(f"agent {name!r} is not callable")
    return obj  # type: ignore[no-any-return]
