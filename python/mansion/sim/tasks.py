"""Tasks in a building: the spec (pydantic, JSON), the sampler and the paper's three settings.

A task is the paper's object retrieval plus delivery (its Table "Task Settings and Prompts"):
start somewhere, find the target object(s) where they are, bring them to a destination (a room,
or a receptacle to put them on) on some floor, within a step budget. The sampler keeps only valid
tasks: the target can be picked up and is named unambiguously (the only one of its type in its
room), the agent can walk from the start to it and from there to the destination, through the
cores when the floors differ, and the destination receptacle has room for it. It counts every
candidate it rejects by reason.
"""

from __future__ import annotations

import json
import os
import random
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

from mansion._io import atomic_write_text
from mansion.exceptions import InvalidInputError
from mansion.scene.house import AgentPose
from mansion.sim.grid import CELL
from mansion.sim.planner import BuildingMap, Route
from mansion.sim.world import Building, FloorState, ObjectInfo

__all__ = [
    "SETTINGS",
    "Destination",
    "SampleReport",
    "Setting",
    "Start",
    "TargetObject",
    "TaskSet",
    "TaskSpec",
    "sample_tasks",
]

#: Receptacles a task may name as its destination (ones a person would put a thing on).
DEST_RECEPTACLES = frozenset({
    "DiningTable", "CoffeeTable", "SideTable", "Desk", "CounterTop", "Sofa", "ArmChair", "Bed",
    "Dresser", "TVStand",
})


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)


class Start(_Model):
    floor: int = Field(ge=0)
    pose: AgentPose | None = Field(default=None, description="Where the agent starts (else in `room`).")
    room: str | None = Field(default=None, description="Start at this room's landmark (when no pose).")

    @model_validator(mode="after")
    def _one(self) -> Start:
        if self.pose is None and self.room is None:
            raise ValueError("a start needs a pose or a room")
        return self


class TargetObject(_Model):
    object_id: str
    object_type: str
    floor: int = Field(ge=0)
    room: str
    room_type: str
    receptacle: str | None = Field(default=None, description="What it lies on or in.")
    receptacle_type: str | None = None


class Destination(_Model):
    floor: int = Field(ge=0)
    room: str
    room_type: str
    receptacle: str | None = Field(default=None, description="Put the objects on this; else bring them into the room.")
    receptacle_type: str | None = None


class TaskSpec(_Model):
    id: str
    building: str
    instruction: str
    start: Start
    targets: list[TargetObject] = Field(min_length=1)
    destination: Destination
    max_steps: int = Field(gt=0, description="Step budget: every skill call is a step.")

    @property
    def floors(self) -> set[int]:
        return {self.start.floor, self.destination.floor, *(t.floor for t in self.targets)}

    @property
    def crosses_floors(self) -> bool:
        return len(self.floors) >= 2


class TaskSet(_Model):
    """A file of tasks (``mansion tasks sample --out``)."""

    schema_version: str = "1.0"
    building: str
    seed: int | None = None
    tasks: list[TaskSpec]
    candidates: int = Field(default=0, description="Candidate tasks drawn.")
    rejected: dict[str, int] = Field(default_factory=dict, description="Candidates rejected, by reason.")
    excluded: dict[str, int] = Field(default_factory=dict, description="Objects never offered as targets, by reason.")

    def to_json(self, path: str | os.PathLike[str]) -> Path:
        return atomic_write_text(path, self.model_dump_json(indent=1) + "\n")

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> TaskSet:
        from mansion.models._validation import load_written

        return load_written(cls, path, "task set")


@dataclass(frozen=True)
class Setting:
    """One of the paper's task settings (Table "Task Settings and Prompts")."""

    name: str
    description: str
    floors: int
    seed: int
    start_floor: int
    target_floor: int
    destination_floor: int
    destination: Literal["room", "receptacle"]
    target_types: tuple[str, ...] = ()
    receptacle_types: tuple[str, ...] = ()
    room_types: tuple[str, ...] = ()
    destination_types: tuple[str, ...] = ()
    prompt: str = ""


SETTINGS: dict[str, Setting] = {
    s.name: s for s in (
        Setting("single-floor", "a one-storey family apartment", 1, 0, 0, 0, 0, "room",
                ("Box",), ("Bed",), (), ("Bathroom",),
                "Find a box on the bed and bring it to the bathroom."),
        Setting("two-floor", "a two-storey office", 2, 2, 0, 0, 1, "receptacle",
                ("CellPhone",), ("Sofa",), (), ("DiningTable", "CoffeeTable", "SideTable"),
                "Find a cellphone on a blue couch on the first floor and bring it to the round "
                "table on the second floor."),
        Setting("four-floor", "a four-storey office with an elevator", 4, 0, 0, 2, 3, "room",
                ("Laptop",), ("Desk",), ("MeetingRoom",), ("Toilet", "ToiletLobby", "Bathroom"),
                "Go to the third floor, find a laptop on the desk in the meeting room on the third "
                "floor, and take it to the restroom on the fourth floor."),
    )
}


@dataclass
class SampleReport:
    tasks: list[TaskSpec]
    candidates: int = 0
    rejected: Counter[str] = field(default_factory=Counter)
    excluded: Counter[str] = field(default_factory=Counter)


def _words(s: str) -> str:
    out: list[str] = []
    for ch in s:
        if ch.isupper() and out and out[-1] != " ":
            out.append(" ")
        out.append(ch.lower())
    return "".join(out).replace("_", " ")


def _targets(st: FloorState) -> tuple[list[ObjectInfo], Counter[str]]:
    """Objects a task may ask for on a floor, and why the others may not."""
    why: Counter[str] = Counter()
    per_room: Counter[tuple[str | None, str]] = Counter(
        (i.room, i.props.object_type) for i in st.objects.values()
    )
    out = []
    for info in st.objects.values():
        if info.parent is None or not info.props.pickupable:
            continue  # the furniture, and what no one can carry, are no candidates at all
        if info.obj.children:
            why["target holds other objects"] += 1
        elif st.inside(info) is not None:
            why["target shut in a closed receptacle"] += 1
        elif per_room[(info.room, info.props.object_type)] > 1:
            why["target ambiguous: another of its type in its room"] += 1
        else:
            out.append(info)
    return sorted(out, key=lambda i: i.id), why


def _receptacles(st: FloorState) -> list[ObjectInfo]:
    return sorted((i for i in st.objects.values() if i.parent is None and i.props.receptacle
                   and not i.props.openable and i.props.object_type in DEST_RECEPTACLES), key=lambda i: i.id)


def _rooms(st: FloorState) -> list[str]:
    return sorted(r for r in st.rooms if r not in st.core_ids)


def _prefer(items: list[Any], key: Any, wanted: tuple[str, ...], rng: random.Random) -> Any:
    """A random item, of a wanted type when there is one."""
    good = [i for i in items if key(i) in wanted] if wanted else []
    return rng.choice(good or items)


def _pick_target(pool: list[ObjectInfo], st: FloorState, setting: Setting | None, rng: random.Random,
                 used: set[str]) -> ObjectInfo:
    """A random target not yet used (when there is one), matching as many of the setting's
    wishes (object type, receptacle type, room type) as any candidate does."""
    fresh = [o for o in pool if o.id not in used] or pool
    if setting is None:
        return rng.choice(fresh)

    def wishes(o: ObjectInfo) -> int:
        rec = st.objects[o.parent].props.object_type if o.parent else ""
        room = st.rooms[o.room].room_type if o.room in st.rooms else ""
        return ((o.props.object_type in setting.target_types) + (rec in setting.receptacle_types)
                + (room in setting.room_types))

    best = max(wishes(o) for o in fresh)
    return rng.choice([o for o in fresh if wishes(o) == best])


def plan_task(bmap: BuildingMap, start_floor: int, start_cell: tuple[int, int], target: ObjectInfo,
              target_floor: int, dest_floor: int, dest_room: str, dest_rec: str | None) -> tuple[Route, Route] | str:
    """The two legs of a task (to the target; from there to the destination), or why not."""
    to_target = bmap.route(start_floor, start_cell, target_floor, BuildingMap.object_goal(target.id))
    if to_target is None:
        where = "on its floor" if start_floor == target_floor else "through the cores"
        return f"target unreachable from the start ({where})"
    goal = BuildingMap.object_goal(dest_rec) if dest_rec else BuildingMap.room_goal(dest_room)
    to_dest = bmap.route(target_floor, to_target.cell, dest_floor, goal)
    if to_dest is None:
        where = "on its floor" if target_floor == dest_floor else "through the cores"
        return f"destination unreachable from the target ({where})"
    return to_target, to_dest


def sample_tasks(building_dir: str | Path, n: int, seed: int = 0, *, setting: Setting | None = None,
                 cell: float = CELL) -> SampleReport:
    """Up to ``n`` valid tasks (fewer when the building has too few); in a building of several
    floors every other task crosses floors (all of them when a ``setting`` says so)."""
    if n < 0:
        raise InvalidInputError(f"--n must be at least 0, not {n}")
    building = Building(Path(building_dir))
    floors = building.floors
    if setting is not None:
        for f in (setting.start_floor, setting.target_floor, setting.destination_floor):
            if f not in floors:
                raise InvalidInputError(f"setting {setting.name!r} needs floor {f}; the building has {floors}")
    bmap = BuildingMap(building, cell)
    rng = random.Random(seed)
    report = SampleReport([])
    seen: set[tuple[str, str, str, int]] = set()
    pools: dict[int, tuple[list[ObjectInfo], Counter[str]]] = {}
    attempts = 0
    building_ids: Counter[str] | None = None
    cross_failures = 0
    while len(report.tasks) < n and attempts < 40 * max(n, 1):
        attempts += 1
        report.candidates += 1
        i = len(report.tasks)
        forced = False
        if setting is not None:
            s, t, d = setting.start_floor, setting.target_floor, setting.destination_floor
        else:
            s, t, d = rng.choice(floors), rng.choice(floors), rng.choice(floors)
            # every other task crosses floors, while crossing ones can be found at all (a
            # building whose cores no one reaches still gets tasks on its floors)
            forced = len(floors) > 1 and i % 2 == 0 and cross_failures < 25
            if forced and s == t == d:
                d = rng.choice([f for f in floors if f != t])
        if t not in pools:
            pools[t] = _targets(bmap.floor(t))
            report.excluded.update(pools[t][1])
        pool = pools[t][0]
        if not pool:
            report.rejected[f"no object to fetch on floor {t}"] += 1
            continue
        if building_ids is None:
            building_ids = Counter(i for f in floors for i in bmap.floor(f).objects)
        pool = [o for o in pool if building_ids[o.id] == 1]
        if not pool:
            report.rejected[f"every object of floor {t} has its id on another floor too (a copied floor)"] += 1
            continue
        target = _pick_target(pool, bmap.floor(t), setting, rng, {k[0] for k in seen})
        dst = bmap.floor(d)
        kind = setting.destination if setting else rng.choice(("room", "receptacle"))
        dest_rec: ObjectInfo | None = None
        if kind == "receptacle":
            recs = [r for r in _receptacles(dst) if not (d == t and r.id == target.parent)]
            if not recs:
                report.rejected[f"no destination receptacle on floor {d}"] += 1
                continue
            dest_rec = _prefer(recs, lambda r: r.props.object_type, setting.destination_types if setting else (), rng)
            dest_room = dest_rec.room or ""
        else:
            rooms = [r for r in _rooms(dst) if not (d == t and r == target.room)]
            if not rooms:
                report.rejected[f"no destination room on floor {d}"] += 1
                continue
            dest_room = _prefer(rooms, lambda r: dst.rooms[r].room_type, setting.destination_types if setting else (), rng)
        key = (target.id, dest_rec.id if dest_rec else dest_room, str(d), s)
        if key in seen:
            report.rejected["duplicate of a sampled task"] += 1
            continue
        spawn = next(f.spawn for f in building.manifest.floors if f.index == s)
        start_cell = bmap.grid(s).snap(spawn.position.x, spawn.position.z, within=0.6)
        if start_cell is None:
            report.rejected["start pose not on a free cell"] += 1
            continue
        if dest_rec is not None:
            from mansion.sim.env import _free_spot

            if _free_spot(dest_rec, target, False) is None:
                report.rejected["no free space on the destination receptacle"] += 1
                continue
        legs = plan_task(bmap, s, start_cell, target, t, d, dest_room, dest_rec.id if dest_rec else None)
        if isinstance(legs, str):
            report.rejected[legs] += 1
            cross_failures += setting is None and forced
            continue
        seen.add(key)
        oracle_steps = len(legs[0].actions) + len(legs[1].actions) + 4
        src = bmap.floor(t)
        parent = src.objects[target.parent] if target.parent else None
        spec = TaskSpec(
            id=f"{building.manifest.id}-{seed}-{len(report.tasks)}",
            building=building.manifest.id,
            instruction=_instruction(target, parent, src, t, dest_rec, dest_room, dst, d),
            start=Start(floor=s, pose=spawn),
            targets=[TargetObject(
                object_id=target.id, object_type=target.props.object_type, floor=t,
                room=target.room or "", room_type=src.rooms[target.room or ""].room_type if target.room in src.rooms else "",
                receptacle=target.parent, receptacle_type=parent.props.object_type if parent else None,
            )],
            destination=Destination(
                floor=d, room=dest_room, room_type=dst.rooms[dest_room].room_type,
                receptacle=dest_rec.id if dest_rec else None,
                receptacle_type=dest_rec.props.object_type if dest_rec else None,
            ),
            # twice what the oracle's plan needs, and ten steps of slack
            max_steps=2 * oracle_steps + 10,
        )
        report.tasks.append(spec)
    return report


def _instruction(target: ObjectInfo, parent: ObjectInfo | None, src: FloorState, t: int,
                 dest_rec: ObjectInfo | None, dest_room: str, dst: FloorState, d: int) -> str:
    what = _words(target.props.object_type)
    on = f" on the {_words(parent.props.object_type)}" if parent else ""
    room = f" in {_words(target.room or '')}"
    goal = (f"the {_words(dest_rec.props.object_type)} in {_words(dest_room)}" if dest_rec
            else _words(dest_room))
    verb = "put it on" if dest_rec else "bring it to"
    return f"Find the {what}{on}{room} on floor {t} and {verb} {goal} on floor {d}."


def load_tasks(path: str | Path) -> list[TaskSpec]:
    p = Path(path)
    try:
        data = json.loads(p.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise InvalidInputError(f"cannot read tasks {str(p)!r}: {exc}") from exc
    if isinstance(data, list):
        from pydantic import TypeAdapter, ValidationError

        try:
            return TypeAdapter(list[TaskSpec]).validate_python(data)
        except ValidationError as exc:
            raise InvalidInputError(f"{p}: {exc}") from exc
    return TaskSet.load(p).tasks
