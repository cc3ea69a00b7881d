"""The headless building environment (issue 10): every skill's success and each of its failure
reasons (a failure changes nothing), the Gymnasium API, objects carried between floor scenes,
the task sampler, the oracle and baseline agents, the CLI end to end, the AI2-THOR backend
against a recording stand-in controller."""

from __future__ import annotations

import copy
import json
import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env
from typer.testing import CliRunner

from mansion.building import generate_building
from mansion.cli import app
from mansion.exceptions import InvalidInputError
from mansion.scene import write_scenes
from mansion.sim import BuildingEnv
from mansion.sim.agents import BaselineAgent, OracleAgent, load_agent
from mansion.sim.env import INTERACT, LANDING_RADIUS
from mansion.sim.evaluate import run_task, score
from mansion.sim.tasks import SETTINGS, TaskSet, TaskSpec, load_tasks, sample_tasks
from mansion.sim.thor import ThorBackend
from mansion.sim.world import HELD_KEY

runner = CliRunner()


def _build(root: Path, description: str, floors: int, seed: int = 0) -> Path:
    b = generate_building(description, floors=floors, seed=seed)
    write_scenes(b, root / "scenes")
    return root


@pytest.fixture(scope="session")
def apartment(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return _build(tmp_path_factory.mktemp("apartment"), "a one-storey family apartment", 1)


@pytest.fixture(scope="session")
def office(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Four floors, a stair and an elevator serving all of them."""
    return _build(tmp_path_factory.mktemp("office"), "a four-storey office", 4)


def snapshot(env: BuildingEnv) -> Any:
    return (env.floor, round(env.x, 6), round(env.z, 6), round(env.yaw, 6),
            json.dumps([env.house(f) for f in env.building.floors], sort_keys=True),
            {k: (c.floor, c.door_open) for k, c in env.cars.items()}, env.path_length)


def fails(env: BuildingEnv, skill: str, *args: Any, reason: str) -> None:
    """The skill fails with ``reason`` in its message and changes nothing but the step count."""
    before = snapshot(env)
    steps = env.steps
    res = getattr(env, skill)(*args)
    assert not res.success, res
    assert reason in res.reason, res.reason
    assert snapshot(env) == before
    assert env.steps == steps + 1


def carried(env: BuildingEnv, smallest: bool = False) -> str:
    """Pick up a small object on the agent's floor that it can reach; returns its id."""
    key = (lambda i: (i.props.width * i.props.depth, i.id)) if smallest else (lambda i: i.id)
    for info in sorted(env.state.objects.values(), key=key):
        if info.parent and info.props.pickupable and not info.obj.children and env.state.inside(info) is None:
            if env.GoToObject(info.id).success and env.PickUp(info.id).success:
                return info.id
    raise AssertionError("nothing to carry")


def find(env: BuildingEnv, pred: Any) -> Any:
    return next(i for i in sorted(env.state.objects.values(), key=lambda i: i.id) if pred(i))


# -- the gymnasium API ---------------------------------------------------------------------------

def test_check_env_passes(office: Path) -> None:
    check_env(BuildingEnv(office, image=True, render_mode="rgb_array"), skip_render_check=False)


def test_reset_observation_and_actions(office: Path) -> None:
    env = BuildingEnv(office, image=True)
    obs, info = env.reset(seed=1)
    assert env.observation_space.contains(obs)
    # the agent starts inside the front door (ProcTHOR's outside door: room0 == room1)
    front = next(d for d in env.house(0)["doors"] if d["id"] == env.building.manifest.floors[0].entrance)
    assert obs["floor"] == 0 and obs["room"] == front["room0"] == front["room1"]
    assert obs["image"].shape == (192, 192, 3) and obs["image"].dtype == np.uint8
    assert {lm["id"] for lm in obs["landmarks"]} == set(env.state.rooms)
    # the three action forms
    core = next(c for c in env.building.cores_on(0) if c.kind == "elevator")
    obs, reward, term, trunc, info = env.step({"skill": 0, "target": core.id, "floor": 0, "direction": 0})
    assert info["success"] and info["skill"] == "GoToRoom"
    assert env.step("CallElevator()")[4]["success"]
    obs, *_ , info = env.step(("UseElevator", 2))
    assert info["success"] and obs["floor"] == 2 and env.floor_changes == 1
    assert not env.step("Fly(3)")[4]["success"]
    # a random start is reproducible from the seed
    a = env.reset(seed=5, options={"random_start": True})[0]["pose"]
    b = env.reset(seed=5, options={"random_start": True})[0]["pose"]
    assert np.array_equal(a, b)
    with pytest.raises(InvalidInputError):
        env.reset(options={"floor": 9})


def test_visible_objects_are_in_the_agents_room_and_near(office: Path) -> None:
    env = BuildingEnv(office)
    obs, _ = env.reset()
    for o in obs["objects"]:
        info = env.state.objects[o["id"]]
        assert info.room == env.room and info.distance(env.x, env.z) <= env.view_radius
        assert math.isclose(float(o["distance"][0]), info.distance(env.x, env.z), rel_tol=1e-5)


# -- navigation ----------------------------------------------------------------------------------

def test_go_to_room_and_object(office: Path) -> None:
    env = BuildingEnv(office)
    env.reset()
    room = next(r for r in sorted(env.state.rooms) if r not in env.state.core_ids and r != env.room)
    res = env.GoToRoom(room)
    assert res.success and env.room == room and env.path_length > 0
    assert env.state.grid.free[env.state.grid.cell_of(env.x, env.z)]
    target = find(env, lambda i: i.parent is None and i.room == room)
    walked = env.path_length
    assert env.GoToObject(target.id).success
    assert target.distance(env.x, env.z) <= INTERACT and env.path_length >= walked
    # the walk is on free cells all along, and its length is the polyline's
    pts = env.trace[-1][1]
    assert all(env.state.grid.visible(a, b) for a, b in zip(pts, pts[1:]))
    fails(env, "GoToRoom", "no_such_room", reason="no room 'no_such_room'")
    fails(env, "GoToObject", "no_such_object", reason="no object 'no_such_object'")


def test_go_to_core_stands_at_its_landing(office: Path) -> None:
    env = BuildingEnv(office)
    env.reset()
    for core in env.building.cores_on(0):
        assert env.GoToRoom(core.id).success
        landing = env.building.landing(core, 0)
        assert math.dist((env.x, env.z), (landing.pose.position.x, landing.pose.position.z)) <= LANDING_RADIUS


def test_closed_door_blocks_the_way(apartment: Path) -> None:
    env = BuildingEnv(apartment)
    env.reset()
    # a room with one door: shut it from outside and the room is out of reach
    graph = env.state.room_graph()
    door = next(d for d in env.state.house.doors
                if d.openable and len(graph[d.room1]) == 1 and d.room0 != env.room and d.room1 != env.room)
    assert env.GoToObject(door.id).success
    assert env.Close(door.id).success
    fails(env, "GoToRoom", door.room1, reason="closed door(s) on this floor: " + door.id)
    fails(env, "Close", door.id, reason="already closed")
    assert env.Open(door.id).success
    assert env.GoToRoom(door.room1).success
    fails(env, "Open", door.id, reason="already open")


def test_closing_a_door_on_oneself_fails(apartment: Path) -> None:
    env = BuildingEnv(apartment)
    env.reset()
    door = next(d for d in env.state.house.doors if d.openable)
    a, b = env._door_segment(door.id)
    env.x, env.z = (a[0] + b[0]) / 2, (a[1] + b[1]) / 2
    fails(env, "Close", door.id, reason="stands in the doorway")


def test_rotate(apartment: Path) -> None:
    env = BuildingEnv(apartment)
    env.reset()
    yaw = env.yaw
    assert env.Rotate("Left", 90).success and math.isclose(env.yaw, (yaw - 90) % 360)
    assert env.Rotate("Right").success and math.isclose(env.yaw, yaw % 360)
    fails(env, "Rotate", "Sideways", reason="Left or Right")
    fails(env, "Rotate", "Left", float("nan"), reason="degrees must lie in")
    fails(env, "Rotate", "Left", "a lot", reason="degrees must be a number")


# -- objects -------------------------------------------------------------------------------------

def test_pick_up_and_put(apartment: Path) -> None:
    env = BuildingEnv(apartment)
    env.reset()
    small = find(env, lambda i: i.parent and i.props.pickupable and not i.obj.children)
    parent = small.parent
    fails(env, "Put", parent, reason="hands empty")
    assert env.GoToObject(small.id).success
    assert env.PickUp(small.id).success
    assert env.held.id == small.id and small.id not in {c.id for c in env.state.objects[parent].obj.children}
    held_json = next(o for o in env.house(0)["objects"] if o["id"] == small.id)
    assert held_json[HELD_KEY] == "agent"
    fails(env, "GoToObject", small.id, reason="holding")
    other = find(env, lambda i: i.parent and i.props.pickupable and i.id != small.id)
    fails(env, "PickUp", other.id, reason="hands full")
    table = find(env, lambda i: i.parent is None and i.props.receptacle and not i.props.openable
                 and i.props.object_type in ("Desk", "DiningTable", "CounterTop", "SideTable", "Dresser", "Bed", "TVStand"))
    # out of reach: the first other room whose spawn is beyond arm's length of it
    for room in (r for r in env.state.rooms if r != table.room and r not in env.state.core_ids):
        if env.distance_to(table.id) > INTERACT:
            break
        env.GoToRoom(room)
    assert env.distance_to(table.id) > INTERACT
    fails(env, "Put", table.id, reason="m away")
    assert env.GoToObject(table.id).success
    # a top taken whole: nowhere to put it
    table.obj.children.append(table.obj.model_copy(update={"id": "test|cover", "children": []}))
    env.state.reindex()
    fails(env, "Put", table.id, reason="no free space on")
    table.obj.children.pop()
    env.state.reindex()
    res = env.Put(table.id)
    assert res.success, res
    info = env.state.objects[small.id]
    assert info.parent == table.id and env.held is None
    top = table.obj.position.y + table.props.height / 2
    assert math.isclose(info.obj.position.y - info.props.height / 2, top, abs_tol=1e-6)
    assert HELD_KEY not in (info.obj.model_extra or {})
    lamp = find(env, lambda i: i.parent is None and not i.props.receptacle)
    assert env.GoToObject(small.id).success and env.PickUp(small.id).success
    fails(env, "Put", lamp.id, reason="is not a receptacle")
    fails(env, "Put", "nothing_here", reason="no receptacle")


def test_pick_up_failures(apartment: Path) -> None:
    env = BuildingEnv(apartment)
    env.reset()
    furniture = find(env, lambda i: i.parent is None and not i.props.pickupable)
    fails(env, "PickUp", furniture.id, reason="cannot be picked up")
    fails(env, "PickUp", "nothing_here", reason="no object")
    far = max((i for i in env.state.objects.values() if i.parent and i.props.pickupable and not i.obj.children),
              key=lambda i: i.distance(env.x, env.z))
    fails(env, "PickUp", far.id, reason="m away")
    # a pickupable receptacle with something on it
    plate = find(env, lambda i: i.props.pickupable and i.props.receptacle and i.parent)
    plate.obj.children.append(copy.deepcopy(far.obj))
    plate.obj.children[-1].id = "test|spoon"
    env.state.reindex()
    fails(env, "PickUp", plate.id, reason="holds other objects")


def test_open_close_and_containers(apartment: Path) -> None:
    env = BuildingEnv(apartment)
    env.reset()
    box = find(env, lambda i: i.props.openable and i.props.receptacle and not i.props.pickupable and i.parent is None)
    fails(env, "Open", box.id, reason="m away") if box.distance(env.x, env.z) > INTERACT else None
    fails(env, "Open", find(env, lambda i: not i.props.openable).id, reason="cannot be opened")
    fails(env, "Open", "nothing_here", reason="no object or door")
    small = carried(env, smallest=True)
    assert env.GoToObject(box.id).success
    fails(env, "Put", box.id, reason="is closed: Open it first")
    assert env.Open(box.id).success and env.state.is_open(box.id)
    assert env.Put(box.id).success
    info = env.state.objects[small]
    assert info.parent == box.id and env.state.inside(info) is None
    assert env.Close(box.id).success
    assert env.state.inside(env.state.objects[small]) == box.id
    assert small not in {o["id"] for o in env._observe()["objects"]}
    fails(env, "PickUp", small, reason="which is closed: Open it first")
    assert env.Open(box.id).success and env.PickUp(small).success
    assert env.Close(box.id).success
    fails(env, "Close", box.id, reason="already closed")


# -- cross-floor skills --------------------------------------------------------------------------

def test_elevator_carries_the_object_to_the_target_floor_house(office: Path, tmp_path: Path) -> None:
    env = BuildingEnv(office)
    env.reset()
    lift = next(c for c in env.building.cores_on(0) if c.kind == "elevator")
    obj = carried(env)
    fails(env, "CallElevator", reason="not at an elevator landing")
    fails(env, "UseElevator", 2, reason="not at an elevator landing")
    assert env.GoToRoom(lift.id).success
    fails(env, "UseElevator", 2, reason="CallElevator first")
    assert env.CallElevator().success and env.cars[lift.id].door_open
    fails(env, "UseElevator", 9, reason="no floor 9")
    fails(env, "UseElevator", 0, reason="already on floor 0")
    fails(env, "UseElevator", "roof", reason="must be a floor number")
    res = env.UseElevator(2)
    assert res.success, res
    landing = env.building.landing(lift, 2)
    assert env.floor == 2 and env.yaw == landing.pose.rotation.y  # at the landing, facing outward
    assert math.dist((env.x, env.z), (landing.pose.position.x, landing.pose.position.z)) <= 0.6
    assert env.held.id == obj
    assert obj in {o["id"] for o in env.house(2)["objects"]}
    assert obj not in json.dumps(env.house(0))
    # the state written out: the target floor's house JSON holds the object
    manifest = env.save(tmp_path / "after")
    house2 = json.loads((manifest.parent / "floor_2.json").read_text())
    assert obj in {o["id"] for o in house2["objects"]}
    again = BuildingEnv(manifest.parent)
    again.reset(options={"floor": 2})
    assert obj in again.state.objects
    # an elevator that does not serve a floor
    lift.floors = [0, 1, 2]
    fails(env, "UseElevator", 3, reason="does not serve floor 3")
    # object ids are unique in a house: a floor holding one of the same id refuses the object
    twin = env.state.objects[obj].obj.model_copy(update={"id": obj})
    env.building.house(1).objects.append(twin)
    fails(env, "UseElevator", 1, reason=f"already has an object {obj!r}")


def test_stairs(office: Path) -> None:
    env = BuildingEnv(office)
    env.reset()
    stair = next(c for c in env.building.cores_on(0) if c.kind == "stair")
    # away from every stair landing first (the spawn may be next to one)
    landings = [env.building.landing(c, 0).pose.position for c in env.building.cores_on(0) if c.kind == "stair"]
    far = max(env.state.landmarks, key=lambda r: min(math.dist(env.state.landmarks[r], (p.x, p.z)) for p in landings))
    assert env.GoToRoom(far).success
    fails(env, "TakeStairs", "Up", reason="not at a stair landing")
    assert env.GoToRoom(stair.id).success
    fails(env, "TakeStairs", "Down", reason="no floor below floor 0")
    fails(env, "TakeStairs", "Sideways", reason="Up or Down")
    assert env.TakeStairs("Up").success and env.floor == 1
    assert env.TakeStairs("up").success and env.floor == 2  # the same stair's landing: no walk
    stair = next(c for c in env.building.manifest.cores if c.kind == "stair")
    stair.floors = [0, 1, 2]
    fails(env, "TakeStairs", "Up", reason="does not serve floor 3")
    assert env.TakeStairs("Down").success and env.floor == 1


def test_a_floor_without_cores(apartment: Path) -> None:
    env = BuildingEnv(apartment)
    env.reset()
    fails(env, "CallElevator", reason="floor 0 has no elevator")
    fails(env, "TakeStairs", "Up", reason="floor 0 has no stair")


# -- tasks and agents ----------------------------------------------------------------------------

def test_sampled_tasks_are_valid_deterministic_and_cross_floors(office: Path, tmp_path: Path) -> None:
    report = sample_tasks(office, 8, seed=3)
    assert len(report.tasks) == 8
    assert sum(t.crosses_floors for t in report.tasks) >= 4
    assert report.candidates >= 8 and report.candidates == 8 + sum(report.rejected.values())
    again = sample_tasks(office, 8, seed=3)
    assert [t.model_dump() for t in again.tasks] == [t.model_dump() for t in report.tasks]
    path = TaskSet(building="x", tasks=report.tasks).to_json(tmp_path / "t.json")
    assert load_tasks(path) == report.tasks
    env = BuildingEnv(office)
    oracle = [run_task(env, t, OracleAgent) for t in report.tasks]
    assert all(o.success and o.retrieved and o.navigated for o in oracle), [o for o in oracle if not o.success]
    assert all(o.steps <= t.max_steps for o, t in zip(oracle, report.tasks))
    base = score([run_task(env, t, BaselineAgent) for t in report.tasks])
    assert base.success <= score(oracle).success == 100.0


def test_apartment_tasks_and_budget(apartment: Path) -> None:
    tasks = sample_tasks(apartment, 4, seed=0).tasks
    assert tasks and not any(t.crosses_floors for t in tasks)
    env = BuildingEnv(apartment)
    assert all(run_task(env, t, OracleAgent).success for t in tasks)
    tight = tasks[0].model_copy(update={"max_steps": 1})
    env.reset(options={"task": tight})
    env.Rotate()
    fails_budget = env.Rotate()
    assert not fails_budget.success and "budget" in fails_budget.reason
    obs, reward, term, trunc, info = env.step("Rotate()")
    assert trunc and not term and reward == 0.0


def test_success_reward_and_progress(office: Path) -> None:
    task = sample_tasks(office, 1, seed=11).tasks[0]
    env = BuildingEnv(office)
    obs, info = env.reset(options={"task": task})
    assert info["progress"] == {"retrieved": False, "navigated": False}
    agent = OracleAgent(env, task)
    rewards, term = [], False
    while not term:
        action = agent(obs, info)
        assert action is not None
        obs, r, term, trunc, info = env.step(action)
        rewards.append(r)
    assert rewards[-1] == 1.0 and sum(rewards) == 1.0
    assert info["progress"]["retrieved"] and info["progress"]["navigated"]


def test_task_spec_rejects_bad_input() -> None:
    with pytest.raises(ValueError):
        TaskSpec.model_validate({"id": "t", "building": "b", "instruction": "", "start": {"floor": 0},
                                 "targets": [], "destination": {"floor": 0, "room": "r", "room_type": "R"},
                                 "max_steps": 3})


def test_load_agent() -> None:
    assert load_agent("oracle") is OracleAgent
    assert load_agent("mansion.sim.agents:BaselineAgent") is BaselineAgent
    for bad in ("nobody", "no_such_module_x:f", "mansion.sim.agents:nothing"):
        with pytest.raises(InvalidInputError):
            load_agent(bad)


# -- AI2-THOR backend ----------------------------------------------------------------------------

class RecordingController:
    """Stands in for ``ai2thor.controller.Controller``: records every call, refuses on demand."""

    def __init__(self) -> None:
        self.calls: list[tuple[str, dict[str, Any]]] = []
        self.refuse: set[str] = set()

    def _event(self, action: str) -> Any:
        ok = action not in self.refuse
        return type("Event", (), {"metadata": {"lastActionSuccess": ok, "errorMessage": "" if ok else "refused"}})()

    def reset(self, scene: dict[str, Any]) -> Any:
        self.calls.append(("reset", {"scene": scene}))
        return self._event("reset")

    def step(self, action: str, **kwargs: Any) -> Any:
        self.calls.append((action, kwargs))
        return self._event(action)


def test_thor_backend_mirrors_the_skills(office: Path) -> None:
    ctrl = RecordingController()
    env = BuildingEnv(office, backend=ThorBackend(ctrl))
    env.reset()
    lift = next(c for c in env.building.cores_on(0) if c.kind == "elevator")
    ctrl.calls.clear()
    obj = carried(env)
    assert env.GoToRoom(lift.id).success and env.CallElevator().success and env.UseElevator(1).success
    names = [c[0] for c in ctrl.calls]
    assert names[-4:] == ["TeleportFull", "reset", "TeleportFull", "PickupObject"]
    scene = ctrl.calls[-3][1]["scene"]
    assert scene["metadata"]["mansion"]["floor"] == 1 and obj in {o["id"] for o in scene["objects"]}
    tele = ctrl.calls[-2][1]
    assert tele["position"] == {"x": env.x, "y": 0.95, "z": env.z} and tele["rotation"]["y"] == env.yaw
    assert ("PickupObject", {"objectId": obj, "forceAction": True}) in ctrl.calls
    # a refusal by the simulator fails the skill and changes nothing
    ctrl.refuse.add("RotateLeft")
    fails(env, "Rotate", "Left", reason="simulator refused")
    ctrl.refuse.add("TeleportFull")
    room = next(r for r in env.state.rooms if r not in env.state.core_ids and r != env.room)
    fails(env, "GoToRoom", room, reason="simulator refused")


# -- command line --------------------------------------------------------------------------------

def test_cli_sample_and_eval(office: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.syspath_prepend(str(Path(__file__).resolve().parents[1] / "examples"))
    out = tmp_path / "tasks.json"
    r = runner.invoke(app, ["tasks", "sample", str(office), "--n", "4", "--seed", "2", "--out", str(out)])
    assert r.exit_code == 0, r.output
    ts = TaskSet.load(out)
    assert len(ts.tasks) == 4 and ts.candidates >= 4
    scores = tmp_path / "s.json"
    r = runner.invoke(app, ["eval", "tasks", str(office), "--tasks", str(out), "--agent", "oracle",
                            "--json", str(scores), "--pictures", str(tmp_path / "pics")])
    assert r.exit_code == 0, r.output
    s = json.loads(scores.read_text())
    assert s["tasks"] == 4 and s["success"] == 100.0 and s["cross_floor"] >= 2
    assert set(s) >= {"tasks", "success", "retrieved", "navigated", "cross_floor", "per_task"}
    assert len(list((tmp_path / "pics").glob("*.png"))) == 4
    r = runner.invoke(app, ["eval", "tasks", str(office), "--n", "2", "--agent", "room_guided_agent:RoomGuided",
                            "--json", str(scores)])
    assert r.exit_code == 0, r.output
    assert json.loads(scores.read_text())["tasks"] == 2


def test_cli_errors(office: Path, tmp_path: Path) -> None:
    r = runner.invoke(app, ["eval", "tasks", str(office), "--n", "2", "--tasks", "x.json"])
    assert r.exit_code == 2 and "not both" in r.output
    r = runner.invoke(app, ["eval", "tasks", str(office), "--n", "1", "--agent", "nobody"])
    assert r.exit_code == 2 and "module:callable" in r.output
    r = runner.invoke(app, ["tasks", "sample", str(tmp_path), "--out", str(tmp_path / "t.json")])
    assert r.exit_code == 2 and "manifest.json" in r.output


def test_cli_paper_setting(tmp_path: Path) -> None:
    r = runner.invoke(app, ["eval", "setting", "single-floor", "--n", "3", "--out", str(tmp_path),
                            "--json", str(tmp_path / "s.json")])
    assert r.exit_code == 0, r.output
    s = json.loads((tmp_path / "s.json").read_text())["single-floor"]
    assert s["tasks"] == 3 and s["success"] == 100.0 and s["cross_floor"] == 0
    assert SETTINGS["four-floor"].floors == 4


def test_remaining_failure_reasons(office: Path, apartment: Path) -> None:
    env = BuildingEnv(office)
    env.reset()
    lift = next(c for c in env.building.cores_on(0) if c.kind == "elevator")
    stair = next(c for c in env.building.cores_on(0) if c.kind == "stair")
    # a skill called without its argument
    res = env.call("PickUp")
    assert not res.success and "bad arguments" in res.reason
    # an unreachable room (its free cells taken away), with no closed door to blame
    room = next(r for r in sorted(env.state.rooms) if r not in env.state.core_ids and r != env.room)
    g = env.state.grid
    g.free[g.label == g.room_ids.index(room)] = False
    g._dist_cache.clear()
    fails(env, "GoToRoom", room, reason="(unreachable)")
    env.state.invalidate()
    # standing nowhere an agent can move from
    x, z = env.x, env.z
    env.x, env.z = -100.0, -100.0
    fails(env, "GoToRoom", room, reason="cannot move")
    env.x, env.z = x, z
    # the top floor has no floor above; a core without a landing on a floor
    assert env.GoToRoom(lift.id).success and env.CallElevator().success
    saved = list(lift.landings)
    lift.landings = [l for l in saved if l.floor != 3]
    fails(env, "UseElevator", 3, reason="has no landing on floor 3")
    lift.landings = saved
    assert env.UseElevator(3).success
    assert env.GoToRoom(stair.id).success
    fails(env, "TakeStairs", "Up", reason="no floor above floor 3")
    saved = list(stair.landings)
    stair.landings = [l for l in saved if l.floor != 3]
    fails(env, "GoToRoom", stair.id, reason="has no landing on floor 3")
    stair.landings = saved

    env = BuildingEnv(apartment)
    env.reset()
    door = next(d for d in env.state.house.doors if d.openable)
    door.openable = False
    fails(env, "Open", door.id, reason="an opening without a door leaf")
    door.openable = True
    far = max((d for d in env.state.house.doors if d.openable), key=lambda d: env.distance_to(d.id))
    fails(env, "Close", far.id, reason="m away")
    # an openable thing in hand
    laptop = find(env, lambda i: i.props.openable and i.props.pickupable and i.parent and not i.obj.children)
    assert env.GoToObject(laptop.id).success and env.PickUp(laptop.id).success
    fails(env, "Open", laptop.id, reason="put")


def test_task_starting_in_a_room(apartment: Path) -> None:
    task = sample_tasks(apartment, 1, seed=4).tasks[0]
    env = BuildingEnv(apartment)
    room = task.targets[0].room
    spec = task.model_copy(update={"start": task.start.model_copy(update={"pose": None, "room": room})})
    env.reset(options={"task": spec})
    assert env.room == room and env.floor == spec.start.floor
    assert run_task(env, spec, OracleAgent).success
    with pytest.raises(InvalidInputError):
        env.reset(options={"task": spec.model_copy(update={"start": spec.start.model_copy(update={"room": "nowhere"})})})
