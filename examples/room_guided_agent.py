"""An example agent for ``mansion eval tasks --agent room_guided_agent:RoomGuided``.

An agent is a factory ``(env, task) -> policy``; the policy gets each observation and info dict
and returns the next skill call (``"GoToRoom(kitchen)"``, ``("UseElevator", 2)`` or a gym action
dict), or None to stop. This one reads the task the way a person reads the instruction (the
target's type, room and floor, the destination) and sees only what the observation shows: the
landmarks of the floor it is on and the objects of the room it stands in. It rides the nearest
elevator (else the stairs, floor by floor) to the right floor, walks to the named room, takes
the first object of the named type it sees and delivers it.

Run it (from this folder, or with it on PYTHONPATH):

    mansion eval tasks out/office --n 10 --agent room_guided_agent:RoomGuided
"""

from __future__ import annotations

import math
from typing import Any


class RoomGuided:
    def __init__(self, env: Any, task: Any):
        target = task.targets[0]
        self.want_type, self.want_room, self.want_floor = target.object_type, target.room, target.floor
        self.dest = task.destination
        self.plan: list[Any] = []
        self.tried: set[str] = set()

    def _go_to_floor(self, obs: dict[str, Any], floor: int) -> list[Any]:
        here = int(obs["floor"])
        x, z = float(obs["pose"][0]), float(obs["pose"][1])
        cores = sorted(
            (lm for lm in obs["landmarks"] if lm["type"] in ("Elevator", "Stair")),
            key=lambda lm: (lm["type"] != "Elevator", math.dist((x, z), tuple(map(float, lm["position"])))),
        )
        for lm in cores:
            if f"{here}:{lm['id']}" in self.tried:
                continue
            self.tried.add(f"{here}:{lm['id']}")
            if lm["type"] == "Elevator":
                return [f"GoToRoom({lm['id']})", "CallElevator()", ("UseElevator", floor)]
            return [f"GoToRoom({lm['id']})", ("TakeStairs", "Up" if floor > here else "Down")]
        return []

    def __call__(self, obs: dict[str, Any], info: dict[str, Any]) -> Any:
        if not info.get("success", True):
            self.plan = []
        if self.plan:
            return self.plan.pop(0)
        floor = int(obs["floor"])
        if not obs["held"]:
            if floor != self.want_floor:
                self.plan = self._go_to_floor(obs, self.want_floor)
            elif obs["room"] != self.want_room:
                if f"room:{self.want_room}" in self.tried:
                    return None
                self.tried.add(f"room:{self.want_room}")
                self.plan = [f"GoToRoom({self.want_room})"]
            else:
                seen = [o["id"] for o in obs["objects"] if o["type"] == self.want_type and o["id"] not in self.tried]
                if not seen:
                    return None
                self.tried.add(seen[0])
                self.plan = [("GoToObject", seen[0]), ("PickUp", seen[0])]
        elif floor != self.dest.floor:
            self.plan = self._go_to_floor(obs, self.dest.floor)
        elif self.dest.receptacle and "put" not in self.tried:
            self.tried.add("put")
            self.plan = [("GoToObject", self.dest.receptacle), ("Put", self.dest.receptacle)]
        elif not self.dest.receptacle and obs["room"] != self.dest.room and "dest" not in self.tried:
            self.tried.add("dest")
            self.plan = [("GoToRoom", self.dest.room)]
        return self.plan.pop(0) if self.plan else None
