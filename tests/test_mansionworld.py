"""Interoperation with the MANSION authors' ecosystem (issue 18): ``mansion export --format
mansionworld`` writes their layout (``floor_1.json`` …, ``metadata.agent``, ``F{n}_`` rooms,
``door|i|room0|room1``, ``F{n}_stair`` / ``F{n}_elevator`` with their fixtures), the reader gives
mansion's view of such a folder back (round trip), ``mansion_api``'s JSON-reading functions run on
the export, and a building written by hand in their layout runs in ``BuildingEnv`` with the
oracle solving a cross-floor task."""

from __future__ import annotations

import copy
import importlib
import importlib.util
import json
import re
import sys
import types
from pathlib import Path
from typing import Any

import pytest
from shapely.geometry import Point, Polygon
from typer.testing import CliRunner

from mansion.building import generate_building
from mansion.cli import app
from mansion.exceptions import InvalidInputError
from mansion.export.mansionworld import write_mansionworld
from mansion.scene import BuildingManifest, House, write_scenes
from mansion.scene.databases import asset_ids
from mansion.scene.mansionworld import door_centre, is_mansionworld, read_mansionworld
from mansion.scene.validate import errors, validate_path
from mansion.sim import BuildingEnv, OracleAgent, run_task
from mansion.sim.tasks import TaskSpec, sample_tasks
from mansion.sim.world import FloorState

runner = CliRunner()
DOOR_ID = re.compile(r"^door\|(\d+)\|([^|]+)\|([^|]+)$")


@pytest.fixture(scope="session")
def office(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Three floors, a stair and two elevators serving all of them."""
    root = tmp_path_factory.mktemp("mw_office")
    b = generate_building("a three-storey office with two elevators", floors=3, seed=0)
    write_scenes(b, root / "scenes")
    return root


@pytest.fixture(scope="session")
def exported(office: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("mw_export") / "office"
    r = runner.invoke(app, ["export", str(office), "--format", "mansionworld", "--out", str(out)])
    assert r.exit_code == 0, r.output
    return out


def _floors(folder: Path) -> dict[int, dict[str, Any]]:
    return {int(p.stem.split("_")[1]): json.loads(p.read_text()) for p in sorted(folder.glob("floor_*.json"))}


def _source(office: Path) -> tuple[BuildingManifest, dict[int, dict[str, Any]]]:
    file = next(p for p in (office / "scenes" / "manifest.json", office / "manifest.json") if p.is_file())
    m = BuildingManifest.load(file)
    return m, {f.index: json.loads((file.parent / f.house).read_text()) for f in m.floors}


def _walk(items: list[dict[str, Any]], parent: str | None = None) -> list[tuple[dict[str, Any], str | None]]:
    out = []
    for o in items:
        out.append((o, parent))
        out += _walk(o.get("children") or [], o["id"])
    return out


def _core_names(manifest: BuildingManifest) -> dict[str, str]:
    """Their core rooms' names: ``stair``, ``stair_2``, …, ``elevator``, ``elevator_2``, …"""
    out = {}
    for kind in ("stair", "elevator"):
        for k, cid in enumerate(sorted(c.id for c in manifest.cores if c.kind == kind), start=1):
            out[cid] = kind if k == 1 else f"{kind}_{k}"
    return out


def _expected_names(house: dict[str, Any], n: int, cores: dict[str, str]) -> dict[str, str]:
    """Their naming, from their documentation: ``F{n}_`` before every room id, the cores
    ``F{n}_stair`` / ``F{n}_elevator`` (``cores``: room id → that name); as the export documents,
    a part of a room (``corridor|1``) without the ``|`` their door ids split on, and the words
    ``stair`` / ``elevator`` out of the other rooms' ids."""
    out = {}
    for r in house["rooms"]:
        name = cores.get(r["id"])
        if name is None:
            name = re.sub(r"[^A-Za-z0-9_&]", "_", r["id"].replace("|", "__"))
            name = re.sub("elevator", "lift", re.sub("stairs?", "steps", name, flags=re.I), flags=re.I)
        out[r["id"]] = f"F{n}_{name}"
    assert len(set(out.values())) == len(out)
    return out


# -- the export ----------------------------------------------------------------------------------

def test_export_is_their_layout(office: Path, exported: Path) -> None:
    manifest, source = _source(office)
    floors = _floors(exported)
    assert sorted(floors) == [1, 2, 3] and not (exported / "manifest.json").exists()
    assert is_mansionworld(exported) and not is_mansionworld(office / "scenes")
    assert sorted(c.kind for c in manifest.cores) == ["elevator", "elevator", "stair"]
    for n, house in floors.items():
        meta = house["metadata"]
        assert meta["agent"] == meta["agentPoses"]["default"] == source[n - 1]["metadata"]["agentPoses"]["default"]
        rooms = {r["id"]: r for r in house["rooms"]}
        assert all(rid.startswith(f"F{n}_") for rid in rooms)
        assert {f"F{n}_stair", f"F{n}_elevator", f"F{n}_elevator_2"} <= set(rooms)
        outside = []
        for i, d in enumerate(house["doors"]):
            m = DOOR_ID.match(d["id"])
            assert m and int(m.group(1)) == i and (m.group(2), m.group(3)) == (d["room0"], d["room1"])
            if d["room1"] == "exterior":
                outside.append(d["id"])
            else:
                assert {d["room0"], d["room1"]} <= set(rooms)
            lift = next((r for r in (d["room0"], d["room1"]) if r.startswith(f"F{n}_elevator")), None)
            if lift is not None:
                assert d["room1"] == lift  # their CallElevator steps into room1
        assert len(outside) == (1 if n == 1 else 0)
        objects = _walk(house["objects"])
        assert all(o["roomId"] in rooms for o, _ in objects)
        fixtures = [o for o, _ in objects if o["id"].startswith("vertical_core_")]
        stair = {o["assetId"] for o in fixtures if o["assetId"].startswith("small_stair")}
        assert stair == {"small_stair", "small_stair_flat"} - ({"small_stair"} if n == 3 else set()) \
            - ({"small_stair_flat"} if n == 1 else set())
        # three floors: the smallest panel that has them, one in each elevator
        panels = sorted(o["roomId"] for o in fixtures if o["assetId"] == "elevator_panel_4")
        assert panels == [f"F{n}_elevator", f"F{n}_elevator_2"]
        for o in fixtures:
            room = o["roomId"]
            assert room.startswith(f"F{n}_elevator" if o["assetId"].startswith("elevator_panel") else f"F{n}_stair")
            assert o["id"].endswith(f"({room})")
            poly = Polygon([(p["x"], p["z"]) for p in rooms[room]["floorPolygon"]])
            assert poly.buffer(1e-6).contains(Point(o["position"]["x"], o["position"]["z"]))
        House.parse(house)
    assert not errors(validate_path(exported))


def test_round_trip(office: Path, exported: Path) -> None:
    """mansion building → their layout → read back: the same rooms, doors, cores and objects."""
    assert_round_trip(office, exported, exported.parent / "again")


def assert_round_trip(office: Path, exported: Path, again_dir: Path) -> None:
    """``exported`` (their layout, written from the mansion building ``office``) read back is
    ``office``'s rooms, doors, cores and objects; written again (into ``again_dir``) it is the
    same bytes. Raises AssertionError (benches/python/bench_mansionworld.py runs it too)."""
    manifest, source = _source(office)
    world = read_mansionworld(exported)
    assert [f.index for f in world.manifest.floors] == [f.index + 1 for f in manifest.floors]
    assert bool(world.fixtures[1]) == bool(manifest.cores)
    assert all(all(f.startswith("vertical_core_") for f in v) for v in world.fixtures.values())
    core_name = _core_names(manifest)
    all_names: dict[int, dict[str, str]] = {}
    for k, orig in source.items():
        n = k + 1
        back = world.houses[n]
        names = _expected_names(orig, n, {c.room_on(k): core_name[c.id] for c in manifest.cores if k in c.floors})
        all_names[k] = names
        # rooms: the same type and shape, with every corner they had and, added, the corners of
        # neighbours that meet their edges (see export.mansionworld._t_junctions)
        assert {names[r["id"]]: r["roomType"] for r in orig["rooms"]} == {r["id"]: r["roomType"] for r in back["rooms"]}
        corners = {(p["x"], p["z"]) for r in orig["rooms"] for p in r["floorPolygon"]}
        for r in orig["rooms"]:
            e = next(x for x in back["rooms"] if x["id"] == names[r["id"]])
            before = [(p["x"], p["z"]) for p in r["floorPolygon"]]
            after = [(p["x"], p["z"]) for p in e["floorPolygon"]]
            assert [q for q in after if q in before] == before and set(after) <= corners
            assert Polygon(after).equals(Polygon(before))
        # doors: same order, rooms, asset, state and hole, in the same place
        o_walls = {w.id: w for w in House.parse(orig).walls}
        b_walls = {w.id: w for w in House.parse(back).walls}
        assert len(orig["doors"]) == len(back["doors"])
        for i, (d, e) in enumerate(zip(orig["doors"], back["doors"], strict=True)):
            assert {names[d["room0"]], names[d["room1"]]} == {e["room0"], e["room1"]}
            assert e["id"].startswith(f"door|{i}|")
            assert (d["assetId"], d["openness"], d["openable"]) == (e["assetId"], e["openness"], e["openable"])
            (x, z), _ = door_centre(d, o_walls)
            (x2, z2), _ = door_centre(e, b_walls)
            assert abs(x - x2) < 1e-6 and abs(z - z2) < 1e-6
            lo, hi = d["holePolygon"]
            lo2, hi2 = e["holePolygon"]
            assert abs((hi["x"] - lo["x"]) - (hi2["x"] - lo2["x"])) < 1e-9 and (lo["y"], hi["y"]) == (lo2["y"], hi2["y"])
        # objects: every one, with its place, parent and room; the core fixtures are not objects
        want = {(o["assetId"], json.dumps(o["position"]), json.dumps(o["rotation"]), names[o["room"]],
                 p is not None) for o, p in _walk(orig["objects"])}
        got = {(o["assetId"], json.dumps(o["position"]), json.dumps(o["rotation"]), o["room"], p is not None)
               for o, p in _walk(back["objects"])}
        assert want == got
        ids = {o["id"] for o, _ in _walk(back["objects"])}
        for o, _ in _walk(orig["objects"]):
            assert o["id"].replace(f"{o['room']}|", f"{names[o['room']]}|", 1) in ids
        assert back["metadata"]["agentPoses"]["default"] == orig["metadata"]["agentPoses"]["default"]
    # cores: the same, linked by name and box across the floors, landings where mansion had them
    assert [c.id for c in world.manifest.cores] == [c.id for c in manifest.cores]
    for c, w in zip(manifest.cores, world.manifest.cores, strict=True):
        assert (w.kind, w.x, w.z, w.floors) == (c.kind, c.x, c.z, [k + 1 for k in c.floors])
        for lo, lw in zip(c.landings, w.landings, strict=True):
            assert lw.floor == lo.floor + 1 and lw.core_room == f"F{lw.floor}_{core_name[c.id]}"
            assert lw.room == all_names[lo.floor][lo.room] and lw.pose == lo.pose
            assert lw.door is not None and lw.door.startswith("door|")
    # their layout read and written again is the same bytes
    again = write_mansionworld(exported, again_dir)
    assert {p.name: p.read_bytes() for p in again.glob("*.json")} == {p.name: p.read_bytes() for p in exported.glob("*.json")}


def test_landings_found_without_mansion_records(exported: Path, tmp_path: Path) -> None:
    """A folder with no mansion records (as theirs): the cores are found by name and box, the
    landings from the core doors, and the oracle crosses floors through them."""
    bare = tmp_path / "bare"
    bare.mkdir()
    for p in exported.glob("floor_*.json"):
        house = json.loads(p.read_text())
        for r in house["rooms"]:
            r.pop("metadata", None)
            r["roomType"] = r["roomType"].lower()
        house["metadata"] = {k: v for k, v in house["metadata"].items() if k in ("agent", "schema")}
        (bare / p.name).write_text(json.dumps(house))
    world = read_mansionworld(bare)
    recorded = read_mansionworld(exported)
    assert [c.id for c in world.manifest.cores] == ["stair", "elevator", "elevator_2"]
    for c, r in zip(world.manifest.cores, recorded.manifest.cores, strict=True):
        assert (c.kind, c.x, c.z, c.floors) == (r.kind, r.x, r.z, r.floors)
        for a, b in zip(c.landings, r.landings, strict=True):
            assert (a.room, a.door, a.core_room) == (b.room, b.door, b.core_room)
            assert abs(a.pose.position.x - b.pose.position.x) + abs(a.pose.position.z - b.pose.position.z) < 1.0
    assert not errors(validate_path(bare))
    tasks = [t for t in sample_tasks(bare, 3, seed=2).tasks if t.crosses_floors]
    assert tasks
    env = BuildingEnv(bare)
    assert all(run_task(env, t, OracleAgent).success for t in tasks)


def test_export_refuses_bad_targets(office: Path, tmp_path: Path) -> None:
    r = runner.invoke(app, ["export", str(office), "--format", "mansionworld", "--out", str(tmp_path / "x.json")])
    assert r.exit_code != 0 and "folder" in r.output
    r = runner.invoke(app, ["export", str(office), "--format", "mansionworld", "--out", str(office / "scenes")])
    assert r.exit_code != 0 and "manifest.json" in r.output
    with pytest.raises(InvalidInputError, match="floor_1.json"):
        read_mansionworld(tmp_path)
    # floors of a taller building exported there before are removed
    (tmp_path / "out").mkdir()
    (tmp_path / "out" / "floor_4.json").write_text("{}")
    write_mansionworld(office, tmp_path / "out")
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["floor_1.json", "floor_2.json", "floor_3.json"]


def test_mansionworld_folder_exports_to_gltf(exported: Path, tmp_path: Path) -> None:
    pytest.importorskip("trimesh")
    out = tmp_path / "b.glb"
    r = runner.invoke(app, ["export", str(exported), "--format", "gltf", "--out", str(out)])
    assert r.exit_code == 0, r.output
    assert out.stat().st_size > 0 and "3 floors" in r.output


# -- their package on the export -----------------------------------------------------------------

def _mansion_api(name: str) -> Any:
    """A module of ``mansion_api`` that only reads the JSON. Its package ``__init__`` imports the
    simulator (``ai2thor.controller`` and ``ai2thor.hooks``, which no ai2thor on PyPI has), so the
    package is entered without it."""
    if "mansion_api" not in sys.modules:
        spec = importlib.util.find_spec("mansion_api")
        if spec is None or not spec.submodule_search_locations:
            pytest.skip("mansion-api is not installed (pip install 'mansion[mansionworld]')")
        pkg = types.ModuleType("mansion_api")
        pkg.__path__ = list(spec.submodule_search_locations)
        pkg.__spec__ = spec
        sys.modules["mansion_api"] = pkg
    return importlib.import_module(f"mansion_api.{name}")


def _thor_objects(house: dict[str, Any]) -> list[dict[str, Any]]:
    """The doors as AI2-THOR lists them in an event's metadata: the house's door id as
    ``objectId``, the asset's object type, open when its openness is above zero."""
    db = asset_ids()
    return [{"objectId": d["id"], "objectType": db[d["assetId"]]["objectType"],
             "isOpen": d.get("openness", 0) > 0, "visible": True} for d in house["doors"]]


def _gym(house: dict[str, Any], n: int) -> types.SimpleNamespace:
    """What their functions read of a ``MansionGym``: the floor's JSON, its agent start and the
    simulator's last event."""
    event = types.SimpleNamespace(metadata={"objects": _thor_objects(house),
                                            "agent": copy.deepcopy(house["metadata"]["agent"])})
    return types.SimpleNamespace(cur_json=house, init_info=copy.deepcopy(house["metadata"]["agent"]),
                                 controller=types.SimpleNamespace(last_event=event), current_floor=n,
                                 landmarks={}, graph=None, edge_doors={}, open_space_edges=set())


def check_with_mansion_api(folder: Path) -> dict[str, int]:
    """Their room polygons, landmarks, room graph and door lookup, current room, edge states and
    landmark floors on every floor of ``folder``; returns counts. Raises AssertionError."""
    import networkx as nx

    geometry = _mansion_api("gym_utils.geometry_utils")
    navigation = _mansion_api("gym_utils.navigation_utils")
    goto = _mansion_api("gym_skills.goto_landmark")
    world = read_mansionworld(folder)
    floors = _floors(folder)
    counts = {"floors": 0, "rooms": 0, "door edges": 0, "open-space edges": 0, "openings": 0,
              "openings their graph misses": 0, "floors their graph joins whole": 0}
    for n, house in floors.items():
        rooms = {r["id"]: Polygon([(p["x"], p["z"]) for p in r["floorPolygon"]]) for r in house["rooms"]}
        assert set(geometry.get_room_polygons(house)) == set(rooms)
        env = _gym(house, n)
        env.landmarks = navigation.generate_landmarks(env, house)
        assert set(env.landmarks) == set(rooms)
        for rid, lm in env.landmarks.items():
            assert rooms[rid].covers(Point(lm["x"], lm["z"])), rid
            assert lm["y"] == house["metadata"]["agent"]["position"]["y"]
        edges, edge_doors, open_edges = navigation.build_room_graph(env)
        inside = [d for d in house["doors"] if d["room1"] != "exterior"]
        for d in inside:
            key = tuple(sorted((d["room0"], d["room1"])))
            assert key in edges and d["id"] in edge_doors[key], d["id"]
        assert sum(len(v) for v in edge_doors.values()) == len(inside)
        # the cores as their floor change finds them: a door of each core room named for it
        for c in world.manifest.cores:
            if n in c.floors:
                room = c.room_on(n)
                assert room == f"F{n}_{c.id}" or room.startswith(f"F{n}_{c.kind}")
                assert any(room in k for k in edge_doors), room
                assert any(c.kind in did.lower() and "door" in did.lower()
                           for k, v in edge_doors.items() if room in k for did in v)
        # as their setup_scene does
        env.room_graph, env.edge_doors, env.open_space_edges = edges, edge_doors, open_edges
        env.graph = nx.Graph()
        env.graph.add_nodes_from(env.landmarks)
        env.graph.add_edges_from(edges)
        navigation.update_edge_states(env)
        # a doorframe is always passable, a door when open
        kind = {o["objectId"]: o["objectType"] for o in _thor_objects(house)}
        for d in inside:
            passable = kind[d["id"]] == "Doorframe" or d.get("openness", 0) > 0
            assert env.graph[d["room0"]][d["room1"]]["open"] == int(passable)
        # their graph is mansion's: the doors, and the openings (empty walls shared by two rooms)
        # their open-space test finds since the export puts corners at T-junctions
        ours = FloorState(world.house(n), {}).room_graph()
        mansion_edges = {tuple(sorted((a, b))) for a, bs in ours.items() for b in bs if a != b}
        missed = mansion_edges - set(edges)
        assert set(edges) == mansion_edges, f"floor {n}: missed {missed}, extra {set(edges) - mansion_edges}"
        assert nx.is_connected(env.graph), f"floor {n}: {list(nx.connected_components(env.graph))}"
        counts["openings"] += len(mansion_edges - {tuple(sorted((d["room0"], d["room1"]))) for d in inside})
        counts["openings their graph misses"] += len(missed)
        counts["floors their graph joins whole"] += int(nx.is_connected(env.graph))
        hub = next(f.hub for f in world.manifest.floors if f.index == n)
        assert navigation.get_current_room(env) == hub
        # their landmark names carry the floor: GoToLandmark reads it (and refuses a landmark
        # of a floor the agent is not on before it moves the agent)
        env.current_floor = n + 1
        for rid in env.landmarks:
            ok, msg = goto.step(env, landmark_name=rid)
            assert not ok and f"is on floor {n}," in msg, msg
        env.current_floor = n
        counts["floors"] += 1
        counts["rooms"] += len(rooms)
        counts["door edges"] += len(edge_doors)
        counts["open-space edges"] += len(open_edges)
    return counts


def test_mansion_api_reads_the_export(exported: Path, capsys: pytest.CaptureFixture[str]) -> None:
    counts = check_with_mansion_api(exported)
    assert counts["floors"] == 3 and counts["door edges"] > 10


# -- their layout, written by hand, in mansion's environment ------------------------------------

def _rect(x0: float, z0: float, x1: float, z1: float, split: list[tuple[float, float]] = ()) -> list[tuple[float, float]]:
    """A room's outline, clockwise seen from above (x right, z up) as mansion writes them, with
    extra corners where a neighbour's wall ends."""
    ring = [(x0, z0), (x0, z1), (x1, z1), (x1, z0)]
    out = []
    for i, a in enumerate(ring):
        b = ring[(i + 1) % 4]
        out.append(a)
        mids = [p for p in split if p not in ring and (
            (a[0] == b[0] == p[0] and min(a[1], b[1]) < p[1] < max(a[1], b[1]))
            or (a[1] == b[1] == p[1] and min(a[0], b[0]) < p[0] < max(a[0], b[0])))]
        out += sorted(mids, key=lambda p: abs(p[0] - a[0]) + abs(p[1] - a[1]))
    return out


def _handmade(folder: Path) -> None:
    """Two floors in their layout, from their documentation: a hall with a stair and an elevator
    beside it, a kitchen (an apple on the floor) below and a bedroom above."""
    folder.mkdir()
    mat = {"name": "PinkConcrete_Smooth"}
    for n, other in ((1, "kitchen"), (2, "bedroom")):
        p = f"F{n}_"
        rooms = {
            p + "hall": _rect(0, 0, 6, 4, [(6, 2)]),
            p + "stair": _rect(6, 0, 8, 2),
            p + "elevator": _rect(6, 2, 8, 4),
            p + other: _rect(0, 4, 6, 8),
        }
        types_ = {p + "hall": "Hallway", p + "stair": "stair", p + "elevator": "elevator", p + other: other.title()}
        walls, edge_wall = [], {}
        for rid, ring in rooms.items():
            for i, a in enumerate(ring):
                b = ring[(i + 1) % len(ring)]
                wid = f"wall|{rid}|{i}"
                walls.append({"id": wid, "roomId": rid, "material": {"name": "WallDrywallWhite3"},
                              "polygon": [{"x": a[0], "y": 0, "z": a[1]}, {"x": b[0], "y": 0, "z": b[1]},
                                          {"x": b[0], "y": 3, "z": b[1]}, {"x": a[0], "y": 3, "z": a[1]}]})
                edge_wall[(a, b)] = wid
        doors = []

        def door(i: int, r0: str, r1: str, a: tuple[float, float], b: tuple[float, float], t: float,
                 asset: str, openable: bool) -> None:
            w = 1.0 if asset == "Doorframe_1" or asset == "Doorway_1" else 1.9
            doors.append({"id": f"door|{i}|{r0}|{r1}", "assetId": asset, "room0": r0, "room1": r1,
                          "wall0": edge_wall[(a, b)], "wall1": edge_wall[(b, a)],
                          "holePolygon": [{"x": t, "y": 0, "z": 0}, {"x": t + w, "y": 2.1, "z": 0}],
                          "assetPosition": {"x": t + w / 2, "y": 1.05, "z": 0},
                          "openable": openable, "openness": 1 if openable else 0})

        door(0, p + "hall", p + "stair", (6, 2), (6, 0), 0.5, "Doorframe_1", False)
        door(1, p + "hall", p + "elevator", (6, 4), (6, 2), 0.05, "Doorway_Double_8", True)
        door(2, p + "hall", p + other, (0, 4), (6, 4), 2.5, "Doorway_1", True)
        objects = []
        if n == 1:
            objects.append({"id": "Apple|1", "assetId": "Apple_1", "kinematic": False, "roomId": p + other,
                            "position": {"x": 3.0, "y": 0.06, "z": 6.0}, "rotation": {"x": 0, "y": 0, "z": 0}})
        objects.append({"id": f"vertical_core_{'stair' if n == 1 else 'stair_flat'}_1 ({p}stair)",
                        "assetId": "small_stair" if n == 1 else "small_stair_flat", "kinematic": True,
                        "roomId": p + "stair", "position": {"x": 7, "y": 1.75 if n == 1 else 0.0125, "z": 1},
                        "rotation": {"x": 0, "y": 270, "z": 0}})
        objects.append({"id": f"vertical_core_elevator_panel_1 ({p}elevator)", "assetId": "elevator_panel_4",
                        "kinematic": True, "roomId": p + "elevator", "position": {"x": 7, "y": 1.2, "z": 3.99},
                        "rotation": {"x": 90, "y": 180, "z": 0}})
        agent = {"horizon": 30, "position": {"x": 3.0, "y": 0.95, "z": 2.0}, "rotation": {"x": 0, "y": 90, "z": 0},
                 "standing": True}
        house = {
            "id": f"handmade-{n}",
            "proceduralParameters": {"ceilingMaterial": {"name": "WallDrywallWhite3"}, "floorColliderThickness": 1.0,
                                     "lights": [], "receptacleHeight": 0.7, "reflections": [],
                                     "skyboxId": "SkyAlbany"},
            "rooms": [{"id": rid, "roomType": types_[rid], "floorMaterial": mat,
                       "floorPolygon": [{"x": x, "y": 0, "z": z} for x, z in ring]} for rid, ring in rooms.items()],
            "walls": walls, "doors": doors, "windows": [], "objects": objects,
            "metadata": {"agent": agent, "schema": "1.0.0"},
        }
        (folder / f"floor_{n}.json").write_text(json.dumps(house, indent=1))


@pytest.fixture(scope="session")
def theirs(tmp_path_factory: pytest.TempPathFactory) -> Path:
    folder = tmp_path_factory.mktemp("mw_handmade") / "theirs"
    _handmade(folder)
    return folder


def test_handmade_building_runs_in_building_env(theirs: Path, tmp_path: Path) -> None:
    folder = theirs
    env = BuildingEnv(folder)
    b = env.building
    assert b.floors == [1, 2]
    assert [(c.id, c.kind, c.floors) for c in b.manifest.cores] == [("stair", "stair", [1, 2]), ("elevator", "elevator", [1, 2])]
    assert b.manifest.cores[1].room_on(2) == "F2_elevator"
    assert "Apple|1" in b.floor_state(1).objects and not any(
        o.startswith("vertical_core_") for k in (1, 2) for o in b.floor_state(k).objects)
    assert not errors(validate_path(folder))
    task = TaskSpec.model_validate({
        "id": "carry-apple", "building": "theirs", "instruction": "Bring the apple from the kitchen to the bedroom upstairs.",
        "start": {"floor": 1, "room": "F1_hall"},
        "targets": [{"object_id": "Apple|1", "object_type": "Apple", "floor": 1, "room": "F1_kitchen",
                     "room_type": "Kitchen"}],
        "destination": {"floor": 2, "room": "F2_bedroom", "room_type": "Bedroom"},
        "max_steps": 20,
    })
    outcome = run_task(env, task, OracleAgent)
    assert outcome.success and outcome.floor_changes >= 1, outcome
    # the cores answer to their rooms' names too
    env.reset(options={"floor": 1})
    assert env.GoToRoom("F1_elevator").success and env.CallElevator().success
    assert env.UseElevator(2).success and env.floor == 2
    assert env.GoToRoom("F2_stair").success and env.TakeStairs("Down").success and env.floor == 1
    # and mansion writes it back in their layout, with their fixtures in place again
    out = write_mansionworld(folder, tmp_path / "again")
    again = _floors(out)
    assert {o["assetId"] for o in again[1]["objects"]} == {"Apple_1", "small_stair", "elevator_panel_4"}
    assert {o["assetId"] for o in again[2]["objects"]} == {"small_stair_flat", "elevator_panel_4"}


def test_mansion_api_reads_the_handmade_building(theirs: Path) -> None:
    counts = check_with_mansion_api(theirs)
    assert counts["floors their graph joins whole"] == 2 and counts["door edges"] == 6
