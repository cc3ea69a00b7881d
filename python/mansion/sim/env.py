"""``BuildingEnv``: a headless multi-floor environment over the house JSONs ``mansion generate``
writes, with the paper's skills (its AI2-THOR extension: ``CallElevator``, ``UseElevator``,
``TakeStairs``) and the usual ones (``GoToRoom``, ``GoToObject``, ``PickUp``, ``Put``, ``Open``,
``Close``, ``Rotate``).

One floor is loaded at a time, as in the paper: its house, navigation grid, room landmarks and
room graph. Changing floors writes the held object out of the current floor's house and into the
target floor's, loads that floor and stands the agent at the core's landing there, facing away
from the core. Every skill returns a :class:`SkillResult` (success and a reason) and changes
nothing when it fails; every call counts as a step.

It is a ``gymnasium.Env``: actions are dicts (``skill``, ``target``, ``floor``, ``direction``),
observations structured dicts (floor, room, pose, held object, objects in view, landmarks) with
an optional top-down image. ``step`` also takes ``"GoToObject(lobby|sofa_0)"`` or
``("UseElevator", 2)``.
"""

from __future__ import annotations

import math
import re
import string
from dataclasses import dataclass
from pathlib import Path
from typing import Any, NamedTuple

import gymnasium as gym
import numpy as np
from gymnasium import spaces

from mansion.exceptions import InvalidInputError
from mansion.scene.house import HouseObject, Vec3
from mansion.scene.poses import AGENT_Y, yaw_of
from mansion.scene.validate import REACH
from mansion.sim.grid import CELL, Path as Walk, _segment_distance, box_distance
from mansion.sim.world import HELD_KEY, Building, FloorState, ObjectInfo, variant_folder

__all__ = ["SKILLS", "BuildingEnv", "SkillResult"]

#: The skills, in the order of the action space's ``skill`` index.
SKILLS = ("GoToRoom", "GoToObject", "PickUp", "Put", "Open", "Close", "Rotate", "CallElevator",
          "UseElevator", "TakeStairs")
#: The agent interacts with what lies this close to its centre (AI2-THOR's default
#: visibilityDistance, within which the simulator lets agents act on objects), m.
INTERACT = 1.5
#: The agent is at a core's landing when this close to the landing pose, m.
LANDING_RADIUS = 1.0
#: Objects of the agent's room this close are in its structured observation, m.
VIEW_RADIUS = 4.0
_CHARSET = frozenset(string.ascii_letters + string.digits + string.punctuation + " ")
_TEXT = 128


class SkillResult(NamedTuple):
    success: bool
    reason: str


@dataclass
class _Car:
    floor: int
    door_open: bool = False


def _text(s: str) -> str:
    return "".join(ch if ch in _CHARSET else "?" for ch in s)[:_TEXT]


class BuildingEnv(gym.Env[dict[str, Any], dict[str, Any]]):
    """A building a robot can work in. ``building_dir``: a ``mansion generate`` output folder,
    its ``scenes`` folder, a ``manifest.json``, or a MansionWorld folder (``floor_1.json`` …;
    :mod:`mansion.scene.mansionworld`; its floors keep their numbers 1, 2, …); ``variant``: load
    the building's task variant of that name instead (``mansion edit``)."""

    metadata = {"render_modes": ["rgb_array"], "render_fps": 4}

    def __init__(
        self, building_dir: str | Path, *, cell: float = CELL, image: bool = False,
        image_size: int = 192, view_radius: float = VIEW_RADIUS, render_mode: str | None = None,
        backend: Any = None, variant: str | None = None,
    ):
        super().__init__()
        self.path = Path(building_dir) if variant is None else variant_folder(building_dir, variant)
        self.cell = cell
        self.view_radius = view_radius
        self.image_size = image_size
        self.with_image = image
        self.render_mode = render_mode
        self.backend = backend
        self._pristine = Building(self.path)
        self.building = self._pristine
        floors = self.building.floors
        text = spaces.Text(_TEXT, min_length=0, charset=_CHARSET)
        self.action_space = spaces.Dict({
            "skill": spaces.Discrete(len(SKILLS)),
            "target": text,
            "floor": spaces.Discrete(max(floors) + 1),
            "direction": spaces.Discrete(2),
        })
        obs: dict[str, spaces.Space[Any]] = {
            "floor": spaces.Discrete(max(floors) + 1),
            "room": text,
            "pose": spaces.Box(-1e4, 1e4, (3,), np.float32),
            "held": text,
            "held_type": text,
            "objects": spaces.Sequence(spaces.Dict({
                "id": text, "type": text, "distance": spaces.Box(0.0, 1e4, (1,), np.float32),
            })),
            "landmarks": spaces.Sequence(spaces.Dict({
                "id": text, "type": text, "position": spaces.Box(-1e4, 1e4, (2,), np.float32),
            })),
            "success": spaces.Discrete(2),
        }
        if image:
            obs["image"] = spaces.Box(0, 255, (image_size, image_size, 3), np.uint8)
        self.observation_space = spaces.Dict(obs)
        self.task: Any = None
        self._renderer: Any = None
        self.state: FloorState
        self.floor: int = 0
        self._start(self.building.floors[0], None)

    # -- episode --------------------------------------------------------------------------------
    def _start(self, floor: int, pose: Any) -> None:
        self.building = self._pristine.fresh()
        self.cars = {c.id: _Car(min(c.floors)) for c in self.building.manifest.cores if c.kind == "elevator"}
        self.steps = 0
        self.path_length = 0.0
        self.floor_changes = 0
        self.trace: list[tuple[int, list[tuple[float, float]]]] = []
        self.last = SkillResult(True, "reset")
        self.retrieved = False
        self.navigated = False
        self._held_targets: set[str] = set()
        self._load(floor, leaving=False)
        spec = pose if pose is not None else self.building.manifest.floors[
            [f.index for f in self.building.manifest.floors].index(floor)].spawn
        self.x, self.z, self.yaw = spec.position.x, spec.position.z, spec.rotation.y
        self._settle()
        self.trace.append((floor, [(self.x, self.z)]))

    def _load(self, floor: int, leaving: bool = True) -> None:
        if leaving and self.state.changed_grid:
            self.building.dirty.add(self.floor)
        self.floor = floor
        self.state = self.building.floor_state(floor, self.cell)
        self._renderer = None
        if self.backend is not None:
            self.backend.load_floor(self.building.house(floor).to_dict())

    def _settle(self) -> None:
        """Stand on the nearest free cell (a pose written a few centimetres off the grid)."""
        rc = self.state.grid.snap(self.x, self.z, within=0.6)
        if rc is not None:
            self.x, self.z = self.state.grid.centre(rc)

    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None) -> tuple[dict[str, Any], dict[str, Any]]:
        """Start an episode from the building as written. ``options``: ``{"task": TaskSpec}``
        starts the task (its start floor and pose or room), ``{"floor": k}`` the spawn of
        floor k, ``{"random_start": True}`` a random room landmark (from ``seed``)."""
        super().reset(seed=seed)
        options = options or {}
        self.task = options.get("task")
        if self.task is not None:
            from mansion.sim.tasks import TaskSpec

            self.task = TaskSpec.model_validate(self.task)
            start = self.task.start
            self._start(start.floor, start.pose)
            if start.room is not None and start.pose is None:
                self._place_in_room(start.room)
        else:
            floor = int(options.get("floor", self.building.floors[0]))
            if floor not in self.building.floors:
                raise InvalidInputError(f"the building has no floor {floor}")
            self._start(floor, None)
            if options.get("random_start"):
                rooms = sorted(r for r in self.state.rooms if r not in self.state.core_ids)
                self._place_in_room(rooms[int(self.np_random.integers(len(rooms)))])
        if self.backend is not None:
            self.backend.teleport(self.x, self.z, self.yaw)
        self.trace = [(self.floor, [(self.x, self.z)])]
        self._progress()
        return self._observe(), self._info("reset")

    def _place_in_room(self, room: str) -> None:
        if room not in self.state.rooms:
            raise InvalidInputError(f"no room {room!r} on floor {self.floor}")
        g = self.state.grid
        k = g.room_ids.index(room)
        cells = np.argwhere(g.free & (g.label == k))
        if cells.size == 0:
            raise InvalidInputError(f"room {room!r} on floor {self.floor} has no free cell to start in")
        lx, lz = self.state.landmarks[room]
        px = g.origin[0] + (cells[:, 1] + 0.5) * g.cell
        pz = g.origin[1] + (cells[:, 0] + 0.5) * g.cell
        i = int(np.argmin(np.hypot(px - lx, pz - lz)))
        self.x, self.z = float(px[i]), float(pz[i])

    def step(self, action: Any) -> tuple[dict[str, Any], float, bool, bool, dict[str, Any]]:
        skill, args = self.parse_action(action)
        was = self._success()
        result = self.call(skill, *args)
        now = self._success()
        reward = 1.0 if now and not was else 0.0
        terminated = bool(now)
        truncated = bool(self.task is not None and not now and self.steps >= self.task.max_steps)
        return self._observe(), reward, terminated, truncated, self._info(skill)

    def parse_action(self, action: Any) -> tuple[str, tuple[Any, ...]]:
        """A gym action dict, ``"Skill(arg)"`` or ``(skill, *args)`` → (skill, args)."""
        if isinstance(action, dict):
            k = int(action.get("skill", -1))
            if not 0 <= k < len(SKILLS):
                return ("?", (k,))
            skill = SKILLS[k]
            target = str(action.get("target", ""))
            if skill in ("GoToRoom", "GoToObject", "PickUp", "Put", "Open", "Close"):
                return (skill, (target,))
            if skill == "UseElevator":
                return (skill, (int(action.get("floor", 0)),))
            if skill == "TakeStairs":
                return (skill, (("Up", "Down")[int(action.get("direction", 0)) % 2],))
            if skill == "Rotate":
                return (skill, (("Left", "Right")[int(action.get("direction", 0)) % 2],))
            return (skill, ())
        if isinstance(action, str):
            m = re.fullmatch(r"\s*(\w+)\s*(?:\((.*)\))?\s*", action)
            if m is None:
                return ("?", (action,))
            arg = (m.group(2) or "").strip().strip("'\"")
            if m.group(1) == "UseElevator" and re.fullmatch(r"-?\d+", arg):
                return (m.group(1), (int(arg),))
            return (m.group(1), (arg,) if arg else ())
        if isinstance(action, (tuple, list)) and action:
            return (str(action[0]), tuple(action[1:]))
        return ("?", (action,))

    def call(self, skill: str, *args: Any) -> SkillResult:
        """Run a skill by name; counts a step (an unknown skill or bad arguments too)."""
        if self.task is not None and self.steps >= self.task.max_steps:
            self.last = SkillResult(False, f"the task's step budget ({self.task.max_steps}) is used up")
            return self.last
        fn = getattr(self, f"_{skill}", None) if skill in SKILLS else None
        self.steps += 1
        if fn is None:
            self.last = SkillResult(False, f"no skill {skill!r}; skills: {', '.join(SKILLS)}")
            return self.last
        try:
            self.last = fn(*args)
        except TypeError as exc:
            self.last = SkillResult(False, f"{skill}: bad arguments {args!r} ({exc})")
        self._progress()
        return self.last

    # Skills as methods, in the paper's names.
    def GoToRoom(self, room: str) -> SkillResult:  # noqa: N802
        return self.call("GoToRoom", room)

    def GoToObject(self, object_id: str) -> SkillResult:  # noqa: N802
        return self.call("GoToObject", object_id)

    def PickUp(self, object_id: str) -> SkillResult:  # noqa: N802
        return self.call("PickUp", object_id)

    def Put(self, receptacle_id: str) -> SkillResult:  # noqa: N802
        return self.call("Put", receptacle_id)

    def Open(self, object_id: str) -> SkillResult:  # noqa: N802
        return self.call("Open", object_id)

    def Close(self, object_id: str) -> SkillResult:  # noqa: N802
        return self.call("Close", object_id)

    def Rotate(self, direction: str = "Right", degrees: float = 90.0) -> SkillResult:  # noqa: N802
        return self.call("Rotate", direction, degrees)

    def CallElevator(self) -> SkillResult:  # noqa: N802
        return self.call("CallElevator")

    def UseElevator(self, target_floor: int) -> SkillResult:  # noqa: N802
        return self.call("UseElevator", target_floor)

    def TakeStairs(self, direction: str) -> SkillResult:  # noqa: N802
        return self.call("TakeStairs", direction)

    # -- where things are -----------------------------------------------------------------------
    @property
    def room(self) -> str | None:
        return self.state.room_of(self.x, self.z)

    @property
    def held(self) -> ObjectInfo | None:
        return self.state.held()

    def house(self, floor: int) -> dict[str, Any]:
        """The current state of a floor's house JSON (what a later visit finds)."""
        return self.building.house_json(floor)

    def save(self, folder: str | Path) -> Path:
        """Write the building as the agent left it (a new building folder); returns its manifest."""
        return self.building.write(folder)

    def _agent_cell(self) -> tuple[int, int] | None:
        return self.state.grid.snap(self.x, self.z, within=0.6)

    def _walk(self, goal: tuple[int, int], walk: Walk, yaw: float | None = None) -> SkillResult | None:
        """Move along ``walk`` (already planned); None on success, else the backend's refusal."""
        x, z = self.state.grid.centre(goal)
        if yaw is None:
            pts = walk.points
            yaw = yaw_of(pts[-1][0] - pts[-2][0], pts[-1][1] - pts[-2][1]) if len(pts) >= 2 else self.yaw
        if self.backend is not None:
            ok, msg = self.backend.teleport(x, z, yaw)
            if not ok:
                return SkillResult(False, f"the simulator refused the move: {msg}")
        self.x, self.z, self.yaw = x, z, yaw
        self.path_length += walk.length
        self.trace[-1][1].extend(walk.points[1:])
        return None

    def _reach(self, near: np.ndarray, close: np.ndarray | None, what: str) -> tuple[tuple[int, int], Walk] | SkillResult:
        """The best reachable cell among ``near`` (nearest by path), else among ``close``."""
        start = self._agent_cell()
        if start is None:
            return SkillResult(False, "the agent stands where it cannot move (no free cell within 0.6 m)")
        g = self.state.grid
        dist = g.distances(start)
        for mask in (near, close):
            if mask is None:
                continue
            cand = mask & (dist >= 0)
            if cand.any():
                d = np.where(cand, dist, np.iinfo(np.int32).max)
                rc = np.unravel_index(int(np.argmin(d)), d.shape)
                goal = (int(rc[0]), int(rc[1]))
                walk = g.path(start, goal)
                assert walk is not None
                return goal, walk
        closed = [d.id for d in self.state.house.doors if d.openable and d.openness <= 0.0]
        if closed:
            return SkillResult(False, f"no path from here to {what}; closed door(s) on this floor: {', '.join(closed)}")
        return SkillResult(False, f"no path from here to {what} (unreachable)")

    def _distance_field(self, target: str) -> np.ndarray | None:
        g = self.state.grid
        px, pz = g.centres()
        if target in self.state.doors:
            a, b = self._door_segment(target)
            return _segment_distance(px, pz, a, b)
        info = self.state.objects.get(target)
        if info is None:
            return None
        p = info.props
        return box_distance(px, pz, info.centre, p.width, p.depth, info.obj.rotation.y)

    def _door_segment(self, door_id: str) -> tuple[tuple[float, float], tuple[float, float]]:
        d = self.state.doors[door_id]
        wall = next(w for w in self.state.house.walls if w.id == d.wall0)
        (ax, az), (bx, bz) = wall.segment()
        n = math.dist((ax, az), (bx, bz))
        lo, hi = d.hole_polygon[0].x, d.hole_polygon[1].x
        return ((ax + (bx - ax) * lo / n, az + (bz - az) * lo / n), (ax + (bx - ax) * hi / n, az + (bz - az) * hi / n))

    def distance_to(self, target: str) -> float:
        """From the agent's centre to an object's footprint or a door's hole (m)."""
        if target in self.state.doors:
            a, b = self._door_segment(target)
            return float(_segment_distance(np.array([self.x]), np.array([self.z]), a, b)[0])
        return self.state.objects[target].distance(self.x, self.z)

    # -- navigation skills ----------------------------------------------------------------------
    def _GoToRoom(self, room: str) -> SkillResult:  # noqa: N802
        st = self.state
        # a core by its id, or by its room on this floor (a MansionWorld building's F2_stair)
        core = self.building.core_named(self.floor, room)
        if room not in st.rooms and core is None:
            return SkillResult(False, f"no room {room!r} on floor {self.floor}")
        g = st.grid
        px, pz = g.centres()
        if core is not None:
            landing = self.building.landing(core, self.floor)
            if landing is None:
                return SkillResult(False, f"{room} has no landing on floor {self.floor}")
            lx, lz = landing.pose.position.x, landing.pose.position.z
            d = np.hypot(px - lx, pz - lz)
            # nearest the landing pose first: stand where the skill card's "entrance" is
            for within in (0.15, 0.3, 0.5, LANDING_RADIUS):
                found = self._reach(d <= within, None, f"the landing of {room}")
                if not isinstance(found, SkillResult):
                    break
            if isinstance(found, SkillResult):
                return found
            goal, walk = found
            face = (landing.pose.rotation.y + 180.0) % 360.0
            refused = self._walk(goal, walk, face)
            return refused or SkillResult(True, f"at the landing of {room} ({walk.length:.1f} m)")
        k = g.room_ids.index(room)
        inroom = g.label == k
        lx, lz = st.landmarks[room]
        d = np.hypot(px - lx, pz - lz)
        # the reachable cell of the room nearest its landmark: several rings so the walk stops at
        # the landmark when it can, and at the room's reachable part when it cannot
        for within in (0.3, 1.0, 2.0, np.inf):
            found = self._reach(inroom & (d <= within), None, f"room {room}")
            if not isinstance(found, SkillResult):
                break
        if isinstance(found, SkillResult):
            return found
        goal, walk = found
        refused = self._walk(goal, walk)
        return refused or SkillResult(True, f"in {room} ({walk.length:.1f} m)")

    def _GoToObject(self, object_id: str) -> SkillResult:  # noqa: N802
        held = self.held
        if held is not None and held.id == object_id:
            return SkillResult(False, f"the agent is holding {object_id}")
        field = self._distance_field(object_id)
        if field is None:
            return SkillResult(False, f"no object {object_id!r} on floor {self.floor}")
        found = self._reach(field <= REACH, field <= INTERACT - self.cell, object_id)
        if isinstance(found, SkillResult):
            return found
        goal, walk = found
        gx, gz = self.state.grid.centre(goal)
        if object_id in self.state.doors:
            a, b = self._door_segment(object_id)
            cx, cz = (a[0] + b[0]) / 2, (a[1] + b[1]) / 2
        else:
            cx, cz = self.state.objects[object_id].centre
        yaw = yaw_of(cx - gx, cz - gz) if math.dist((cx, cz), (gx, gz)) > 1e-6 else self.yaw
        refused = self._walk(goal, walk, yaw)
        return refused or SkillResult(True, f"next to {object_id} ({walk.length:.1f} m)")

    def _Rotate(self, direction: str = "Right", degrees: float = 90.0) -> SkillResult:  # noqa: N802
        d = str(direction).capitalize()
        if d not in ("Left", "Right"):
            return SkillResult(False, f"direction must be Left or Right, not {direction!r}")
        try:
            deg = float(degrees)
        except (TypeError, ValueError):
            return SkillResult(False, f"degrees must be a number, not {degrees!r}")
        if not math.isfinite(deg) or not 0.0 < deg <= 360.0:
            return SkillResult(False, f"degrees must lie in (0, 360], not {degrees!r}")
        yaw = (self.yaw + (deg if d == "Right" else -deg)) % 360.0
        if self.backend is not None:
            ok, msg = self.backend.rotate(d, deg)
            if not ok:
                return SkillResult(False, f"the simulator refused: {msg}")
        self.yaw = yaw
        return SkillResult(True, f"facing {yaw:.0f}°")

    # -- manipulation skills --------------------------------------------------------------------
    def _near(self, target: str) -> SkillResult | None:
        d = self.distance_to(target)
        if d > INTERACT:
            return SkillResult(False, f"{target} is {d:.1f} m away; come within {INTERACT} m (GoToObject)")
        return None

    def _PickUp(self, object_id: str) -> SkillResult:  # noqa: N802
        st = self.state
        held = self.held
        if held is not None:
            return SkillResult(False, f"hands full: holding {held.id}")
        info = st.objects.get(object_id)
        if info is None:
            return SkillResult(False, f"no object {object_id!r} on floor {self.floor}")
        if not info.props.pickupable:
            return SkillResult(False, f"{object_id} ({info.props.object_type}) cannot be picked up")
        if info.obj.children:
            return SkillResult(False, f"{object_id} holds other objects ({', '.join(c.id for c in info.obj.children)})")
        shut = st.inside(info)
        if shut is not None:
            return SkillResult(False, f"{object_id} is inside {shut}, which is closed: Open it first")
        far = self._near(object_id)
        if far is not None:
            return far
        if self.backend is not None:
            ok, msg = self.backend.pickup(object_id)
            if not ok:
                return SkillResult(False, f"the simulator refused: {msg}")
        obj = st.detach(object_id)
        obj.position = Vec3(x=self.x, y=AGENT_Y, z=self.z)
        obj.room = self.room
        setattr(obj, HELD_KEY, "agent")
        st.attach(obj, None)
        self._mark_retrieved(object_id)
        return SkillResult(True, f"holding {object_id}")

    def _Put(self, receptacle_id: str) -> SkillResult:  # noqa: N802
        st = self.state
        held = self.held
        if held is None:
            return SkillResult(False, "hands empty: nothing to put")
        rec = st.objects.get(receptacle_id)
        if rec is None or receptacle_id == held.id:
            return SkillResult(False, f"no receptacle {receptacle_id!r} on floor {self.floor}")
        if not rec.props.receptacle:
            return SkillResult(False, f"{receptacle_id} ({rec.props.object_type}) is not a receptacle")
        into = rec.props.openable
        if into and not st.is_open(receptacle_id):
            return SkillResult(False, f"{receptacle_id} is closed: Open it first")
        shut = st.inside(rec)
        if shut is not None:
            return SkillResult(False, f"{receptacle_id} is inside {shut}, which is closed")
        far = self._near(receptacle_id)
        if far is not None:
            return far
        spot = _free_spot(rec, held, into)
        if spot is None:
            return SkillResult(False, f"no free space {'in' if into else 'on'} {receptacle_id} for {held.id}")
        if self.backend is not None:
            ok, msg = self.backend.put(held.id, receptacle_id)
            if not ok:
                return SkillResult(False, f"the simulator refused: {msg}")
        obj = st.detach(held.id)
        (obj.model_extra or {}).pop(HELD_KEY, None)
        obj.position = Vec3(x=spot[0], y=spot[1], z=spot[2])
        obj.rotation = Vec3(x=0.0, y=rec.obj.rotation.y, z=0.0)
        obj.room = rec.room
        st.attach(obj, receptacle_id)
        return SkillResult(True, f"put {obj.id} {'in' if into else 'on'} {receptacle_id}")

    def _openable(self, object_id: str) -> SkillResult | None:
        st = self.state
        if object_id in st.doors:
            if not st.doors[object_id].openable:
                return SkillResult(False, f"{object_id} is an opening without a door leaf")
            return None
        info = st.objects.get(object_id)
        if info is None:
            return SkillResult(False, f"no object or door {object_id!r} on floor {self.floor}")
        if not info.props.openable:
            return SkillResult(False, f"{object_id} ({info.props.object_type}) cannot be opened or closed")
        held = self.held
        if held is not None and held.id == object_id:
            return SkillResult(False, f"put {object_id} down first")
        return None

    def _set_open(self, object_id: str, opened: bool) -> SkillResult:
        st = self.state
        bad = self._openable(object_id)
        if bad is not None:
            return bad
        if st.is_open(object_id) == opened:
            return SkillResult(False, f"{object_id} is already {'open' if opened else 'closed'}")
        far = self._near(object_id)
        if far is not None:
            return far
        value = 1.0 if opened else 0.0
        if object_id in st.doors:
            if not opened and self.distance_to(object_id) < st.radius:
                return SkillResult(False, f"the agent stands in the doorway of {object_id}")
            st.doors[object_id].openness = value
            st.invalidate()
        else:
            st.objects[object_id].obj.openness = value
        if self.backend is not None:
            ok, msg = (self.backend.open if opened else self.backend.close)(object_id)
            if not ok:
                if object_id in st.doors:
                    st.doors[object_id].openness = 1.0 - value
                    st.invalidate()
                else:
                    st.objects[object_id].obj.openness = 1.0 - value
                return SkillResult(False, f"the simulator refused: {msg}")
        return SkillResult(True, f"{object_id} is {'open' if opened else 'closed'}")

    def _Open(self, object_id: str) -> SkillResult:  # noqa: N802
        return self._set_open(object_id, True)

    def _Close(self, object_id: str) -> SkillResult:  # noqa: N802
        return self._set_open(object_id, False)

    # -- cross-floor skills ---------------------------------------------------------------------
    def _at_landing(self, kind: str) -> tuple[Any, str]:
        """The core of ``kind`` whose landing on this floor the agent stands at, else why not."""
        best, best_d = None, math.inf
        for core in self.building.cores_on(self.floor):
            if core.kind != kind:
                continue
            landing = self.building.landing(core, self.floor)
            if landing is None:
                continue
            d = math.dist((self.x, self.z), (landing.pose.position.x, landing.pose.position.z))
            if d < best_d:
                best, best_d = core, d
        if best is None:
            return None, f"floor {self.floor} has no {kind} landing"
        if best_d > LANDING_RADIUS:
            return None, (f"not at {'an' if kind == 'elevator' else 'a'} {kind} landing: the nearest, {best.id}'s, is {best_d:.1f} m away "
                          f"(GoToRoom({best.id}) first)")
        return best, ""

    def _CallElevator(self) -> SkillResult:  # noqa: N802
        core, why = self._at_landing("elevator")
        if core is None:
            return SkillResult(False, why)
        car = self.cars[core.id]
        if car.floor == self.floor and car.door_open:
            return SkillResult(True, f"{core.id}'s car is here, its door open")
        car.floor, car.door_open = self.floor, True
        return SkillResult(True, f"{core.id}'s car came to floor {self.floor}; its door is open")

    def _floor_ok(self, target: int) -> str | None:
        floors = self.building.floors
        if target not in floors:
            return f"no floor {target} in this building (floors {floors[0]}–{floors[-1]})"
        if target == self.floor:
            return f"already on floor {target}"
        return None

    def _UseElevator(self, target_floor: Any) -> SkillResult:  # noqa: N802
        try:
            target = int(target_floor)
        except (TypeError, ValueError):
            return SkillResult(False, f"target_floor must be a floor number, not {target_floor!r}")
        core, why = self._at_landing("elevator")
        if core is None:
            return SkillResult(False, why)
        car = self.cars[core.id]
        if car.floor != self.floor or not car.door_open:
            return SkillResult(False, f"{core.id}'s car is not here with its door open: CallElevator first")
        bad = self._floor_ok(target)
        if bad is not None:
            return SkillResult(False, bad)
        if target not in core.floors:
            return SkillResult(False, f"{core.id} does not serve floor {target} (it serves {', '.join(map(str, core.floors))})")
        res = self._change_floor(core, target)
        if res.success:
            car.floor, car.door_open = target, True
        return res

    def _TakeStairs(self, direction: Any) -> SkillResult:  # noqa: N802
        d = str(direction).capitalize()
        if d not in ("Up", "Down"):
            return SkillResult(False, f"direction must be Up or Down, not {direction!r}")
        core, why = self._at_landing("stair")
        if core is None:
            return SkillResult(False, why)
        target = self.floor + (1 if d == "Up" else -1)
        if target not in self.building.floors:
            return SkillResult(False, f"no floor {'above' if d == 'Up' else 'below'} floor {self.floor}")
        if target not in core.floors:
            return SkillResult(False, f"{core.id} does not serve floor {target} (it serves {', '.join(map(str, core.floors))})")
        return self._change_floor(core, target)

    def _change_floor(self, core: Any, target: int) -> SkillResult:
        """The paper's ``update_floor``: the held object leaves this floor's house for the
        target floor's, that floor is loaded and the agent stands at the core's landing there."""
        landing = self.building.landing(core, target)
        if landing is None:
            return SkillResult(False, f"{core.id} has no landing on floor {target}")
        held = self.held
        pose = landing.pose
        obj: HouseObject | None = None
        if held is not None and _holds_id(self.building.house(target).objects, held.id):
            # a house's object ids are unique (the simulator's object ids): a copied floor has
            # an object of the same id already
            return SkillResult(False, f"floor {target} already has an object {held.id!r}; "
                               "the held object cannot go there")
        if held is not None:
            obj = self.state.detach(held.id)
            obj.position = Vec3(x=pose.position.x, y=AGENT_Y, z=pose.position.z)
            obj.room = landing.room
            self.building.house(target).objects.append(obj)
        old = self.floor
        self._load(target)
        self.x, self.z, self.yaw = pose.position.x, pose.position.z, pose.rotation.y
        self._settle()
        if self.backend is not None:
            ok, msg = self.backend.teleport(self.x, self.z, self.yaw)
            if ok and obj is not None:
                ok, msg = self.backend.pickup(obj.id)
            if not ok:  # undo: back to the floor we left, holding what we held
                self._undo_floor(old, core, obj)
                return SkillResult(False, f"the simulator refused the landing: {msg}")
        self.floor_changes += 1
        self.trace.append((target, [(self.x, self.z)]))
        return SkillResult(True, f"took {core.id} to floor {target}")

    def _undo_floor(self, old: int, core: Any, obj: HouseObject | None) -> None:
        back = self.building.landing(core, old)
        if obj is not None:
            house = self.building.house(self.floor)
            house.objects[:] = [o for o in house.objects if o.id != obj.id]
            self.building.house(old).objects.append(obj)
        self._load(old)
        self.x, self.z, self.yaw = back.pose.position.x, back.pose.position.z, back.pose.rotation.y
        self._settle()

    # -- task progress --------------------------------------------------------------------------
    def _mark_retrieved(self, object_id: str) -> None:
        if self.task is not None and (self.floor, object_id) in {(t.floor, t.object_id) for t in self.task.targets}:
            self._held_targets.add(object_id)
            if self._held_targets >= {t.object_id for t in self.task.targets}:
                self.retrieved = True

    def _progress(self) -> None:
        if self.task is None:
            return
        if self._at_destination():
            self.navigated = True

    def _at_destination(self) -> bool:
        dest = self.task.destination
        if self.floor != dest.floor:
            return False
        if dest.receptacle is not None:
            return dest.receptacle in self.state.objects and self.distance_to(dest.receptacle) <= INTERACT
        return self.room == dest.room

    def _success(self) -> bool:
        """Every target object at the destination: on (in) its receptacle, or in its room (put
        down there, or held by the agent standing in it)."""
        if self.task is None:
            return False
        dest = self.task.destination
        if self.floor != dest.floor:
            return False
        for t in self.task.targets:
            info = self.state.objects.get(t.object_id)
            if info is None:
                return False
            if dest.receptacle is not None:
                if info.parent != dest.receptacle:
                    return False
            elif info.parent is None and (info.obj.model_extra or {}).get(HELD_KEY):
                if self.room != dest.room:
                    return False
            elif info.room != dest.room:
                return False
        return True

    def task_result(self) -> dict[str, Any]:
        return {
            "success": self._success(), "retrieved": self.retrieved, "navigated": self.navigated,
            "steps": self.steps, "path_length": round(self.path_length, 3),
            "floor_changes": self.floor_changes,
        }

    # -- observations ---------------------------------------------------------------------------
    def _info(self, skill: str) -> dict[str, Any]:
        info = {"skill": skill, "success": self.last.success, "reason": self.last.reason,
                "steps": self.steps, "path_length": self.path_length, "floor_changes": self.floor_changes}
        if self.task is not None:
            info["task"] = self.task.id
            info["instruction"] = self.task.instruction
            info["progress"] = {"retrieved": self.retrieved, "navigated": self.navigated}
        return info

    def visible_objects(self) -> list[ObjectInfo]:
        """Objects of the agent's room within the view radius, nearest first (the held one and
        those shut in closed receptacles left out)."""
        room = self.room
        held = self.held
        out = []
        for info in self.state.objects.values():
            if held is not None and info.id == held.id:
                continue
            if info.room != room or self.state.inside(info) is not None:
                continue
            if info.distance(self.x, self.z) <= self.view_radius:
                out.append(info)
        out.sort(key=lambda i: (round(i.distance(self.x, self.z), 6), i.id))
        return out

    def landmarks(self) -> list[tuple[str, str, tuple[float, float]]]:
        """(room id, room type, position) per room of the floor; a core's is its landing."""
        out = []
        for rid, room in self.state.rooms.items():
            pos = self.state.landmarks[rid]
            core = self.building.core_named(self.floor, rid)
            if core is not None:
                landing = self.building.landing(core, self.floor)
                if landing is not None:
                    pos = (landing.pose.position.x, landing.pose.position.z)
            out.append((rid, room.room_type, pos))
        return out

    def _observe(self) -> dict[str, Any]:
        held = self.held
        obs: dict[str, Any] = {
            "floor": int(self.floor),
            "room": _text(self.room or ""),
            "pose": np.array([self.x, self.z, self.yaw], dtype=np.float32),
            "held": _text(held.id if held else ""),
            "held_type": _text(held.props.object_type if held else ""),
            "objects": tuple(
                {"id": _text(i.id), "type": _text(i.props.object_type),
                 "distance": np.array([i.distance(self.x, self.z)], dtype=np.float32)}
                for i in self.visible_objects()
            ),
            "landmarks": tuple(
                {"id": _text(rid), "type": _text(kind), "position": np.array(pos, dtype=np.float32)}
                for rid, kind, pos in self.landmarks()
            ),
            "success": int(self.last.success),
        }
        if self.with_image:
            obs["image"] = self.top_down()
        return obs

    def top_down(self, size: int | None = None) -> np.ndarray:
        """A picture of the agent's surroundings (north up, ``size`` px square, RGB)."""
        from mansion.sim.render import FloorPainter

        if self._renderer is None or self._renderer.stale(self.state):
            self._renderer = FloorPainter(self.state)
        return self._renderer.view(self.x, self.z, self.yaw, size or self.image_size,
                                   held=self.held is not None)

    def render(self) -> np.ndarray | None:  # type: ignore[override]
        if self.render_mode == "rgb_array":
            return self.top_down()
        return None


def _free_spot(rec: ObjectInfo, held: ObjectInfo, into: bool) -> tuple[float, float, float] | None:
    """Where the held object goes on (or in) the receptacle: the first spot of a grid over its
    top, nearest the centre, that its footprint fits without overlapping what already lies there."""
    from mansion.placement.check import footprint

    p, h = rec.props, held.props
    yaw = rec.obj.rotation.y
    top = footprint(rec.centre, p.width, p.depth, yaw)
    taken = [footprint((c.position.x, c.position.z), _wd(c)[0], _wd(c)[1], c.rotation.y) for c in rec.obj.children]
    if into:
        y = rec.obj.position.y - p.height / 2 + 0.02 + h.height / 2
    else:
        y = rec.obj.position.y + p.height / 2 + h.height / 2
    spots = []
    steps = 5
    for i in range(steps):
        for j in range(steps):
            u = (i / (steps - 1) - 0.5) * max(p.width - h.width, 0.0)
            v = (j / (steps - 1) - 0.5) * max(p.depth - h.depth, 0.0)
            spots.append((abs(u) + abs(v), u, v))
    t = math.radians(yaw)
    for _, u, v in sorted(spots):
        cx = rec.centre[0] + u * math.cos(t) + v * math.sin(t)
        cz = rec.centre[1] - u * math.sin(t) + v * math.cos(t)
        fp = footprint((cx, cz), h.width, h.depth, yaw)
        if fp.difference(top.buffer(0.01)).area > 1e-6:
            continue
        if any(fp.intersection(o).area > 1e-6 for o in taken) and not into:
            continue
        return (cx, y, cz)
    return None


def _holds_id(objects: list[HouseObject], oid: str) -> bool:
    return any(o.id == oid or _holds_id(o.children, oid) for o in objects)


def _wd(obj: HouseObject) -> tuple[float, float]:
    from mansion.sim.world import props

    p = props(obj.asset_id)
    return (p.width, p.depth)
