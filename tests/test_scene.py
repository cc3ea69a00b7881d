"""Scenes: the house models, instantiation over a sample of buildings, the golden building, every
validation rule against a hand-broken house, and the CLI commands."""

from __future__ import annotations

import copy
import itertools
import json
import math
import sys
from pathlib import Path
from typing import Any

import pytest
from shapely.geometry import Point, Polygon
from typer.testing import CliRunner

from mansion.building import generate_building
from mansion.cli import app
from mansion.exceptions import InvalidInputError
from mansion.scene import (
    House,
    build_scenes,
    house_json_schema,
    validate_house,
    validate_path,
    write_scenes,
)
from mansion.scene.databases import asset_ids, door_assets, material_names, window_assets
from mansion.scene.interfaces import RoomRings, find_interfaces
from mansion.scene.materials import floor_material, wall_material
from mansion.scene.parts import split_room
from scene_cases import GOLDEN, box_house, golden_building, golden_payload

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benches" / "python"))
from bench_generate import TYPES, case, description  # noqa: E402

runner = CliRunner()


@pytest.fixture(scope="module")
def golden_house() -> dict[str, Any]:
    return json.loads((GOLDEN / "floor_0.json").read_text())


def rules(problems: list[Any]) -> set[str]:
    return {p.rule for p in problems}


def named(problems: list[Any], rule: str, element: str) -> bool:
    return any(p.rule == rule and p.element == element for p in problems)


# -- models and databases ----------------------------------------------------------------------


def test_golden_house_round_trips(golden_house: dict[str, Any]) -> None:
    house = House.model_validate(golden_house)
    assert house.to_dict() == golden_house
    assert house.metadata.schema_version == "1.0.0"
    assert golden_house["metadata"]["schema"] == "1.0.0"


def test_bare_string_material_is_rejected(golden_house: dict[str, Any]) -> None:
    broken = copy.deepcopy(golden_house)
    broken["rooms"][0]["floorMaterial"] = "DarkWoodFloors"  # the 0.0.1 form breaks loading
    problems = validate_house(broken)
    assert rules(problems) == {"schema"}
    assert any("rooms.0.floorMaterial" in p.element for p in problems)


def test_json_schema_names_the_format() -> None:
    schema = house_json_schema()
    props = schema["properties"]
    for key in ("proceduralParameters", "rooms", "walls", "doors", "windows", "objects", "metadata"):
        assert key in props
    door = schema["$defs"]["Door"]["properties"]
    assert {"assetId", "room0", "room1", "wall0", "wall1", "holePolygon", "assetPosition"} <= set(door)
    assert "schema" in schema["$defs"]["HouseMetadata"]["properties"]


def test_databases_come_from_procthor() -> None:
    assert len(asset_ids()) > 1000
    assert all(d.asset_id in asset_ids() and 0.9 < d.width < 2.1 for d in door_assets())
    assert window_assets() and all(w.height > 0 for w in window_assets())
    assert "WoodFloorsCross" in material_names()


@pytest.mark.parametrize(
    ("text", "surface", "expect"),
    [
        ("carpet tiles, charcoal", "floor", "carpet"),
        ("polished concrete, light grey", "floor", "concrete"),
        ("oak parquet, matte", "floor", "wood"),
        ("non-slip ceramic tile, grey", "floor", "tiles"),
        ("exposed brick, red", "wall", "brick"),
        ("painted plaster, white", "wall", "drywall"),
    ],
)
def test_materials_match_the_description(text: str, surface: str, expect: str) -> None:
    match = floor_material(text) if surface == "floor" else wall_material(text)
    assert match.name in material_names()
    assert expect in match.name.lower()


# -- geometry ----------------------------------------------------------------------------------


def test_interfaces_pair_shared_walls_and_split_at_neighbours() -> None:
    # a 4×2 room above two 2×2 rooms: its bottom edge meets two neighbours
    top = RoomRings("top", [(0, 2), (4, 2), (4, 4), (0, 4)])
    left = RoomRings("left", [(0, 0), (2, 0), (2, 2), (0, 2)])
    right = RoomRings("right", [(2, 0), (4, 0), (4, 2), (2, 2)])
    faces = find_interfaces([top, left, right])
    shared = [f for f in faces if f.other is not None]
    assert sorted((f.room, f.other) for f in shared) == [("left", "right"), ("left", "top"), ("right", "top")]
    assert all(abs(f.length - 2.0) < 1e-9 for f in shared)
    outside = sum(f.length for f in faces if f.other is None)
    assert abs(outside - 16.0) < 1e-9  # the 4 × 4 outline


def test_room_with_a_hole_is_cut_into_simple_parts() -> None:
    ring = [(0, 0), (6, 0), (6, 6), (0, 6)]
    hole = [(2, 2), (4, 2), (4, 4), (2, 4)]
    parts = split_room("corridor", ring, [hole])
    assert len(parts) >= 2 and all(p.room == "corridor" for p in parts)
    polys = [Polygon(p.ring) for p in parts]
    assert all(p.is_valid and not p.interiors for p in polys)
    assert abs(sum(p.area for p in polys) - 32.0) < 1e-9


def test_cuts_leave_parts_an_agent_can_walk() -> None:
    # a supermarket's corridor (benchmark seed 79, floor 1) around two rooms; its shortest cut
    # left a part whose two lobes met through a 0.5 m gap beside a stair core
    ring = [(2.5, 9.0), (19.0, 9.0), (19.0, 15.0), (16.0, 15.0), (16.0, 21.0), (9.0, 21.0), (9.0, 16.5),
            (4.5, 16.5), (4.5, 21.0), (3.0, 21.0), (3.0, 18.0), (0.0, 18.0), (0.0, 12.0), (2.5, 12.0)]
    holes = [[(4.0, 10.5), (4.0, 14.0), (8.0, 14.0), (8.0, 10.5)],
             [(12.0, 10.5), (12.0, 14.5), (16.0, 14.5), (16.0, 10.5)]]
    parts = split_room("corridor", ring, holes)
    polys = [Polygon(p.ring) for p in parts]
    assert abs(sum(p.area for p in polys) - Polygon(ring, holes).area) < 1e-9
    for poly in polys:
        # an agent 0.7 m across reaches every bit of every part, in one piece
        core = poly.buffer(-0.35, join_style="mitre")
        assert core.geom_type == "Polygon", poly
        assert abs(core.buffer(0.35, join_style="mitre").intersection(poly).area - poly.area) < 1e-6


# -- instantiation -----------------------------------------------------------------------------


def test_golden_building_is_pinned() -> None:
    expected = {p.name: json.loads(p.read_text()) for p in GOLDEN.glob("*.json")}
    assert golden_payload() == expected, "scenes changed: if on purpose, run python tests/scene_cases.py"


@pytest.mark.parametrize("seed", range(len(TYPES)))
def test_every_building_type_gives_valid_scenes(seed: int, tmp_path: Path) -> None:
    """One building of each type (seeds 0–13 of the benchmark's hundred; the whole hundred is
    benches/python/bench_scenes.py)."""
    kind, floors = case(seed)
    building = generate_building(description(kind, floors), building_type=kind, floors=floors, seed=seed)
    manifest = write_scenes(building, tmp_path)
    # nothing the loader refuses, no warning, every room reachable and whole for the agent
    assert validate_path(manifest) == []
    scenes = build_scenes(building, objects=False)
    for house, floor in zip(scenes.houses, building.floors, strict=True):
        # every access edge of the graph is a door or an opening, and doors carry real assets
        assert house.objects == []
        assert house.metadata.mansion is not None and house.metadata.mansion.furnishing is None
        for door in house.doors:
            assert door.asset_id.startswith("Doorway")
        parts = {r.id: (r.metadata.part_of if r.metadata and r.metadata.part_of else r.id) for r in house.rooms}
        assert set(parts.values()) == {r.id for r in floor.layout.rooms}
    assert len(scenes.manifest.cores) == len(building.program.cores)
    for core in scenes.manifest.cores:
        assert [landing.floor for landing in core.landings] == core.floors


def test_cores_are_rooms_with_their_record() -> None:
    building = golden_building()
    scenes = build_scenes(building)
    core = building.program.cores[0]
    for k in core.floors:
        room = next(r for r in scenes.houses[k].rooms if r.id == core.id)
        assert room.metadata is not None and room.metadata.core is not None
        rec = room.metadata.core
        assert rec.kind == core.type and rec.floors == sorted(core.floors)
        assert rec.door in {d.id for d in scenes.houses[k].doors}
        assert rec.landing is not None and rec.landing.position.y == pytest.approx(0.95)
    elevations = [f.elevation for f in scenes.manifest.floors]
    assert elevations == sorted(elevations) and elevations[0] == 0.0


@pytest.mark.parametrize(("seed", "entry"), [(30, "entrance_hall"), (37, "entrance_vestibule")])
def test_the_front_door_opens_into_the_entrance_room(seed: int, entry: str) -> None:
    """A townhouse's front door opened into its living room (the hub) beside its entrance hall,
    where the living room's doorstep reached more of the floor; a lobby, foyer, entrance hall or
    vestibule with an exterior wall now takes the front door before the hub."""
    kind, floors = case(seed)
    building = generate_building(description(kind, floors), building_type=kind, floors=floors, seed=seed)
    ground = build_scenes(building, objects=False).houses[0]
    door = next(d for d in ground.doors if d.id == "door|0|entrance")
    types = {n.id: n.room_type for n in building.floors[0].graph.nodes}
    assert door.room0 == door.room1 and types[door.room0] == entry


# -- every rule, hand-broken ---------------------------------------------------------------------


def _first(items: list[dict[str, Any]], **match: Any) -> dict[str, Any]:
    return next(i for i in items if all(i.get(k) == v for k, v in match.items()))


def _wall(house: dict[str, Any], wid: str) -> dict[str, Any]:
    return _first(house["walls"], id=wid)


def test_golden_house_is_valid_and_navigable(golden_house: dict[str, Any]) -> None:
    assert validate_house(golden_house) == []


def _loop() -> dict[str, Any]:
    """A corridor d over three rooms a | b | c, doors d–a, d–c, a–b, b–c (a loop), a dresser
    in a, the spawn in the corridor."""
    return box_house(
        {"d": (0, 3, 9, 5), "a": (0, 0, 3, 3), "b": (3, 0, 6, 3), "c": (6, 0, 9, 3)},
        [("d", "a", 1.0), ("d", "c", 1.0), ("a", "b", 1.0), ("b", "c", 1.0)], (4.5, 4.0),
        [{"id": "a|dresser", "assetId": "Dresser_205_1", "room": "a", "kinematic": True,
          "position": {"x": 0.3, "y": 0.35, "z": 1.5}, "rotation": {"x": 0, "y": 90, "z": 0}}],
    )


def test_valid_house_has_no_problem() -> None:
    assert validate_house(_loop()) == []


def _blockers(room: tuple[float, float, float], z0: float, z1: float) -> list[dict[str, Any]]:
    """Dressers standing side by side across a room from z0 to z1 at x (a wall of furniture)."""
    x, _, _ = room
    out, z = [], z0
    while z < z1 - 1e-6:
        out.append({"id": f"block|{len(out)}", "assetId": "Dresser_209_1", "room": "b",
                    "kinematic": True, "position": {"x": x, "y": 0.35, "z": z + 1.14},
                    "rotation": {"x": 0, "y": 90, "z": 0}})
        z += 2.28
    return out


def _set(path: str, value: Any) -> Any:
    def change(h: dict[str, Any]) -> None:
        *head, last = path.split(".")
        node: Any = h
        for k in head:
            node = node[int(k)] if isinstance(node, list) else node[k]
        if value is _DELETE:
            del node[last]
        else:
            node[last] = value
    return change


_DELETE = object()


def _dup_door(h: dict[str, Any]) -> None:
    h["doors"][1]["id"] = h["doors"][0]["id"]


def _two_holes(h: dict[str, Any]) -> None:
    extra = copy.deepcopy(h["doors"][0])
    extra["id"] = "door|extra"
    h["doors"].append(extra)


def _narrow_door(h: dict[str, Any]) -> None:
    # c is reached through doors of 0.5 m only: an agent needing 0.6 m stays out
    for d in h["doors"]:
        if "c" in (d["room0"], d["room1"]):
            d["holePolygon"][0]["x"] += 0.25
            d["holePolygon"][1]["x"] -= 0.25
            d["assetPosition"]["x"] += 0.25


def _furniture_wall(h: dict[str, Any]) -> None:
    # b is cut in two between its doors (a and c are still reached round through the corridor)
    h["objects"] += _blockers((4.5, 0, 0), 0.0, 3.0)


ERROR_CASES = {
    "schema": _set("metadata.schema", "0.0.1"),
    "duplicate-id": _dup_door,
    "one-hole-per-wall": _two_holes,
    "hole-wall": _set("doors.0.wall0", "wall|nowhere"),
    "hole-polygon": _set("doors.0.holePolygon", [{"x": 1.0, "y": 0.0, "z": 0.0}]),
    "hole-asset": _set("doors.0.assetId", "Doorway_999"),
    "material": _set("walls.0.material", None),
    "skybox": _set("proceduralParameters.skyboxId", "SkyNowhere"),
    "object-rotation": _set("objects.0.rotation", _DELETE),
    "spawn": _set("metadata.agentPoses.default.position", {"x": -5.0, "y": 0.95, "z": -5.0}),
    "navigable": _narrow_door,
    "room-doors": _furniture_wall,
}


@pytest.mark.parametrize("rule", sorted(ERROR_CASES))
def test_each_error_rule_has_a_broken_house(rule: str) -> None:
    from mansion.scene.validate import ERRORS, errors

    h = _loop()
    ERROR_CASES[rule](h)
    found = errors(validate_house(h))
    assert {p.rule for p in found} == {rule}, found
    assert all(p.severity == "error" for p in found)
    assert rule in ERRORS


def test_null_floor_material_and_the_outside_door_convention() -> None:
    h = _loop()
    h["rooms"][1]["floorMaterial"]["name"] = None
    assert named(validate_house(h), "material", "a")
    # ProcTHOR's outside door: room0 == room1, wall1 the exterior twin (roomId "exterior")
    h = _loop()
    ext = next(w for w in h["walls"] if w["id"].startswith("wall|exterior|wall|a|"))
    inner = next(w for w in h["walls"] if "wall|exterior|" + w["id"] == ext["id"])
    ext["roomId"] = "exterior"
    lo, hi = 0.5, 1.5
    h["doors"].append({"id": "door|out", "assetId": "Doorway_1", "room0": "a", "room1": "a",
                       "wall0": inner["id"], "wall1": ext["id"],
                       "holePolygon": [{"x": lo, "y": 0, "z": 0}, {"x": hi, "y": 2.1, "z": 0}],
                       "assetPosition": {"x": 1.0, "y": 1.05, "z": 0}})
    assert {p.rule for p in validate_house(h)} <= {"asset-position"}


@pytest.mark.slow
def test_real_houses_give_no_error() -> None:
    """Every real house AI2-THOR loads (ProcTHOR's and Holodeck's, ../shared/data/real-houses)
    passes without an error: no top-level id, ProcTHOR's conventions, furniture in their way."""
    import gzip

    from mansion.scene.validate import errors

    import os

    folder = os.environ.get("MANSION_REAL_HOUSES") or Path(__file__).resolve().parents[1].parent / "shared" / "data" / "real-houses"
    data = Path(folder) / "houses.jsonl.gz"
    if not data.is_file():
        pytest.skip(f"{data} is absent")
    count = 0
    with gzip.open(data, "rt", encoding="utf-8") as lines:
        for line in lines:
            record = json.loads(line)
            assert errors(validate_house(record["house"], source=record["name"])) == [], record["name"]
            count += 1
    assert count == 127


def test_overlapping_rooms(golden_house: dict[str, Any]) -> None:
    h = copy.deepcopy(golden_house)
    study = _first(h["rooms"], id="study")
    study["floorPolygon"] = copy.deepcopy(_first(h["rooms"], id="storage")["floorPolygon"])
    problems = validate_house(h)
    assert named(problems, "room-overlap", "study") or named(problems, "room-overlap", "storage")


def test_missing_wall_leaves_room_open(golden_house: dict[str, Any]) -> None:
    h = copy.deepcopy(golden_house)
    gone = next(w for w in h["walls"] if w["roomId"] == "study" and "exterior" not in w["id"])
    h["walls"].remove(gone)
    problems = validate_house(h)
    assert named(problems, "wall-closure", "study")
    assert any(p.rule == "wall-pair" for p in problems)


def test_wall_without_twin(golden_house: dict[str, Any]) -> None:
    h = copy.deepcopy(golden_house)
    ext = next(w for w in h["walls"] if "exterior" in w["id"])
    h["walls"].remove(ext)
    twin_of = [p for p in validate_house(h) if p.rule == "wall-pair"]
    assert twin_of and "twin" in twin_of[0].message


def test_wall_facing_away_from_its_room(golden_house: dict[str, Any]) -> None:
    h = copy.deepcopy(golden_house)
    w = next(w for w in h["walls"] if w["roomId"] == "study" and "exterior" not in w["id"])
    w["roomId"] = "garage"
    assert named(validate_house(h), "wall-room", w["id"])


def test_hole_outside_its_wall(golden_house: dict[str, Any]) -> None:
    h = copy.deepcopy(golden_house)
    door = h["doors"][0]
    door["holePolygon"][1]["x"] += 50.0
    assert named(validate_house(h), "hole-extent", door["id"])


def test_two_holes_on_one_wall(golden_house: dict[str, Any]) -> None:
    h = copy.deepcopy(golden_house)
    extra = copy.deepcopy(h["windows"][0])
    extra["id"] = "window|extra"
    h["windows"].append(extra)
    assert named(validate_house(h), "one-hole-per-wall", extra["wall0"])


def test_door_above_the_floor(golden_house: dict[str, Any]) -> None:
    h = copy.deepcopy(golden_house)
    door = h["doors"][0]
    door["holePolygon"][0]["y"] = 0.2
    assert named(validate_house(h), "door-floor", door["id"])


def test_door_naming_the_wrong_room(golden_house: dict[str, Any]) -> None:
    h = copy.deepcopy(golden_house)
    door = h["doors"][0]
    door["room1"] = "kitchen" if door["room1"] != "kitchen" else "garage"
    assert named(validate_house(h), "door-rooms", door["id"])


def test_door_walls_that_are_not_twins(golden_house: dict[str, Any]) -> None:
    h = copy.deepcopy(golden_house)
    door = h["doors"][0]
    other = next(
        w for w in h["walls"]
        if w["roomId"] == door["room1"] and w["id"] != door["wall1"]
        and w["id"] not in {d["wall1"] for d in h["doors"]} | {d["wall0"] for d in h["doors"]}
        and w["id"] not in {x["wall0"] for x in h["windows"]} | {x["wall1"] for x in h["windows"]}
    )
    door["wall1"] = other["id"]
    assert named(validate_house(h), "hole-twins", door["id"])


def test_asset_position_off_the_hole(golden_house: dict[str, Any]) -> None:
    h = copy.deepcopy(golden_house)
    door = h["doors"][0]
    door["assetPosition"]["x"] += 0.4
    assert named(validate_house(h), "asset-position", door["id"])


def test_unknown_assets_and_materials(golden_house: dict[str, Any]) -> None:
    h = copy.deepcopy(golden_house)
    h["doors"][0]["assetId"] = "Doorway_999"
    h["windows"][0]["assetId"] = "Doorway_1"
    h["rooms"][0]["floorMaterial"]["name"] = "NoSuchMaterial"
    problems = validate_house(h)
    assert named(problems, "hole-asset", h["doors"][0]["id"])
    assert named(problems, "hole-asset-type", h["windows"][0]["id"])
    assert named(problems, "material", h["rooms"][0]["id"])


def test_object_outside_every_room(golden_house: dict[str, Any]) -> None:
    h = copy.deepcopy(golden_house)
    h["objects"] = [
        {"id": "Sofa|1", "assetId": "Sofa_1", "position": {"x": -20.0, "y": 0.4, "z": -20.0},
         "rotation": {"x": 0, "y": 0, "z": 0}, "kinematic": True},
    ]
    problems = validate_house(h)
    assert named(problems, "object-in-room", "Sofa|1")


def test_room_cut_off_from_the_hub(golden_house: dict[str, Any]) -> None:
    h = copy.deepcopy(golden_house)
    door = _first(h["doors"], room1="guest_bedroom") if any(
        d["room1"] == "guest_bedroom" for d in h["doors"]) else _first(h["doors"], room0="guest_bedroom")
    h["doors"].remove(door)
    assert named(validate_house(h), "navigable", "guest_bedroom")


def test_core_moved_on_one_floor(tmp_path: Path) -> None:
    manifest = write_scenes(golden_building(), tmp_path)
    floor1 = tmp_path / "floor_1.json"
    h = json.loads(floor1.read_text())
    core = next(r for r in h["rooms"] if r.get("metadata", {}).get("core"))
    for p in core["floorPolygon"]:
        p["x"] += 0.5
    floor1.write_text(json.dumps(h))
    problems = validate_path(manifest)
    assert named(problems, "core-align", core["id"])


def test_a_buildings_floor_files_get_the_problems_of_their_dicts(tmp_path: Path) -> None:
    """validate_building parses floor files with pydantic's JSON parser and reads a file the
    model rejects again as a dict: either way a floor's problems are validate_house's."""
    manifest = write_scenes(golden_building(), tmp_path)
    h = json.loads((tmp_path / "floor_0.json").read_text())
    changes = {
        # parses (the model's default rotation) but the loader fails
        "rotations left out": lambda h: (
            h["objects"][0].pop("rotation"),
            next(o for o in h["objects"] if o.get("children"))["children"][0].pop("rotation"),
        ),
        "a hole of one point": lambda h: h["doors"][0].update(holePolygon=h["doors"][0]["holePolygon"][:1]),
        "schema errors": lambda h: (h["objects"][0].update(rotation=None), h["walls"][0].update(polygon="no"),
                                    h["metadata"].update(schema="0.0.1")),
        "a wall moved": lambda h: h["walls"][3]["polygon"][0].update(x=h["walls"][3]["polygon"][0]["x"] + 0.3),
    }
    for name, change in changes.items():
        broken = copy.deepcopy(h)
        change(broken)
        (tmp_path / "floor_0.json").write_text(json.dumps(broken, indent=1))
        got = [p for p in validate_path(manifest) if p.source.endswith("floor_0.json")]
        want = validate_house(broken, source=str(tmp_path / "floor_0.json"))
        assert got and got == want, name


def test_a_building_validated_from_the_houses_it_wrote_gets_the_problems_of_its_files(tmp_path: Path) -> None:
    """The dataset job checks the houses it has just written rather than reading them back: they
    read back equal, and the problems (the sources naming the files) are those of the files."""
    from mansion.scene import validate_building
    from mansion.scene.write import save_scenes
    from mansion.scene.house import Vec3

    scenes = build_scenes(golden_building(), objects=True)
    houses = scenes.houses
    # problems to find: an object moved out of its room, a wall moved off its room's outline
    obj = houses[0].objects[0]
    obj.position = Vec3(x=obj.position.x + 40.0, y=obj.position.y, z=obj.position.z)
    wall = houses[-1].walls[3]
    wall.polygon[0] = Vec3(x=wall.polygon[0].x + 0.3, y=wall.polygon[0].y, z=wall.polygon[0].z)
    manifest = save_scenes(scenes, tmp_path)
    for house, floor in zip(houses, scenes.manifest.floors, strict=True):
        assert House.model_validate_json((tmp_path / floor.house).read_text()) == house
    read = validate_building(manifest)
    assert named(read, "object-in-room", obj.id) and any(p.rule == "wall-room" or wall.id in p.element for p in read)
    assert validate_building(manifest, written=houses) == read
    with pytest.raises(InvalidInputError, match="houses given"):
        validate_building(manifest, written=houses[:1])


def test_bad_house_file_is_a_clear_error(tmp_path: Path) -> None:
    bad = tmp_path / "house.json"
    bad.write_text("{not json")
    with pytest.raises(InvalidInputError, match="cannot read"):
        validate_path(bad)


# -- command line ------------------------------------------------------------------------------


def test_cli_validate_errors_warnings_strict_and_json(tmp_path: Path) -> None:
    good = tmp_path / "good.json"
    good.write_text(json.dumps(_loop()))
    result = runner.invoke(app, ["validate", str(good)])
    assert result.exit_code == 0, result.output
    # a warning (a door hole above the floor) passes, unless --strict
    h = _loop()
    h["doors"][0]["holePolygon"][0]["y"] = 0.3
    h["doors"][0]["assetPosition"]["y"] += 0.3
    warned = tmp_path / "warned.json"
    warned.write_text(json.dumps(h))
    result = runner.invoke(app, ["validate", str(good), str(warned)])
    assert result.exit_code == 0, result.output
    assert "warning [door-floor] door|0" in result.output
    result = runner.invoke(app, ["validate", "--strict", str(warned)])
    assert result.exit_code == 1
    # an error fails; --json lists every problem with its severity
    h = _loop()
    h["proceduralParameters"]["skyboxId"] = "SkyNowhere"
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(h))
    out = tmp_path / "problems.json"
    result = runner.invoke(app, ["validate", str(warned), str(bad), "--json", str(out)])
    assert result.exit_code == 1
    assert "error [skybox] proceduralParameters" in result.output
    listed = json.loads(out.read_text())
    assert {(p["severity"], p["rule"]) for p in listed} == {("warning", "door-floor"), ("error", "skybox")}


def test_cli_render_and_schema(tmp_path: Path) -> None:
    write_scenes(golden_building(), tmp_path / "scenes")
    result = runner.invoke(app, ["render", str(tmp_path)])
    assert result.exit_code == 0, result.output
    assert (tmp_path / "scenes" / "floor_0.png").stat().st_size > 1000
    assert (tmp_path / "scenes" / "floor_1.png").is_file()
    result = runner.invoke(app, ["schema", "--out", str(tmp_path / "schema.json")])
    assert result.exit_code == 0, result.output
    assert json.loads((tmp_path / "schema.json").read_text())["properties"]["rooms"]


def test_committed_json_schema_is_current() -> None:
    committed = Path(__file__).resolve().parents[1] / "docs" / "house.schema.json"
    assert json.loads(committed.read_text()) == house_json_schema(), "run: mansion schema --out docs/house.schema.json"


# -- objects --------------------------------------------------------------------------------------


def _objects(house: dict[str, Any], room: str) -> list[dict[str, Any]]:
    return [o for o in house["objects"] if o["room"] == room]


def test_golden_floors_are_furnished_around_their_doors(golden_house: dict[str, Any]) -> None:
    house = House.model_validate(golden_house)
    record = house.metadata.mansion
    assert record is not None and record.furnishing is not None
    rooms = record.furnishing.rooms
    assert set(rooms) == {r.id for r in house.rooms}
    # cores and circulation stay clear; the others hold what the record says
    assert rooms["stair_1"].status == "skipped"
    for rid, r in rooms.items():
        assert len(_objects(golden_house, rid)) == r.objects
        assert r.status != "failed" or r.objects == 0
    ids = [o["id"] for o in golden_house["objects"]]
    ids += [c["id"] for o in golden_house["objects"] for c in o.get("children", [])]
    assert len(ids) == len(set(ids)) and len(ids) > 50
    known = asset_ids()
    assert all(o["assetId"] in known for o in golden_house["objects"])
    assert any(o.get("children") for o in golden_house["objects"])
    # every door records the room its leaf swings into
    assert all(d["swingRoom"] in (d["room0"], d["room1"]) for d in golden_house["doors"])


def test_no_object_in_a_door_swing_or_on_a_pose(golden_house: dict[str, Any]) -> None:
    from shapely.geometry import box as square

    from mansion.placement.check import footprint
    from mansion.scene.entrances import room_entrances

    house = House.model_validate(golden_house)
    db = asset_ids()
    fps = {
        o.id: (o.room, footprint((o.position.x, o.position.z), db[o.asset_id]["boundingBox"]["x"],
                                 db[o.asset_id]["boundingBox"]["z"], o.rotation.y))
        for o in house.objects
    }
    for rid, ways in room_entrances(house).items():
        poly = Polygon([(p.x, p.z) for p in next(r for r in house.rooms if r.id == rid).floor_polygon])
        for e in ways:
            if e.kind != "door" or not e.swings_here:
                continue
            # the square the leaf sweeps inside the room
            (ax, az), (bx, bz) = e.a, e.b
            zone = Polygon([e.a, e.b, (bx - (bz - az), bz + (bx - ax)), (ax - (bz - az), az + (bx - ax))])
            if not poly.buffer(1e-6).covers(zone):
                zone = Polygon([e.a, e.b, (bx + (bz - az), bz - (bx - ax)), (ax + (bz - az), az - (bx - ax))])
            for oid, (room, fp) in fps.items():
                if room == rid:
                    assert fp.intersection(zone).area < 1e-6, (oid, e.id)
    spawn = house.metadata.agent_poses["default"].position
    spot = square(spawn.x - 0.25, spawn.z - 0.25, spawn.x + 0.25, spawn.z + 0.25)
    assert all(not fp.intersects(spot) for _, fp in fps.values())


def test_generation_without_objects_and_deterministic_objects() -> None:
    building = golden_building()
    bare = build_scenes(building, objects=False)
    assert all(h.objects == [] for h in bare.houses)
    again = build_scenes(building)
    assert [h.to_dict() for h in again.houses] == [h.to_dict() for h in build_scenes(building).houses]


def test_object_footprint_leaving_its_room(golden_house: dict[str, Any]) -> None:
    h = copy.deepcopy(golden_house)
    obj = max(h["objects"], key=lambda o: o["position"]["y"])
    room = Polygon([(p["x"], p["z"]) for p in _first(h["rooms"], id=obj["room"])["floorPolygon"]])
    # the centre stays inside, 5 cm from the wall; the footprint pokes through it
    x0, _, _, _ = room.bounds
    z = room.representative_point().y
    obj["position"]["x"], obj["position"]["z"] = x0 + 0.05, z
    assert room.covers(__import__("shapely").Point(x0 + 0.05, z))
    assert named(validate_house(h), "object-in-room", obj["id"])


def test_overlapping_objects_and_the_tucked_exception(golden_house: dict[str, Any]) -> None:
    h = copy.deepcopy(golden_house)
    tucked = next(o for o in h["objects"] if "tuckedUnder" in o)
    table = _first(h["objects"], id=tucked["tuckedUnder"])
    # the tucked chair overlaps its table, and may (it is kinematic: the physics leaves it)
    assert tucked["kinematic"] is True
    assert not [p for p in validate_house(h) if p.rule in ("object-overlap", "seat-physics")]
    from mansion.placement.check import footprint

    def fp(o: dict[str, Any]) -> Polygon:
        bb = asset_ids()[o["assetId"]]["boundingBox"]
        return footprint((o["position"]["x"], o["position"]["z"]), bb["x"], bb["z"], o["rotation"]["y"])

    share = fp(tucked).intersection(fp(table)).area / fp(tucked).area
    tucked["kinematic"] = False  # a dynamic seat is fine only if it overlaps as real ones do
    assert named(validate_house(h), "seat-physics", tucked["id"]) == (share > 0.38)
    tucked["kinematic"] = True
    tucked["tuckedUnder"] = "another-table"  # pushed under some other table: a collision
    problems = validate_house(h)
    assert any(p.rule == "object-overlap" and {p.element, table["id"]} >= {tucked["id"]} or
               (p.rule == "object-overlap" and p.element == table["id"]) for p in problems)
    h = copy.deepcopy(golden_house)
    a, b = [o for o in h["objects"] if "tuckedUnder" not in o][:2]
    b["position"]["x"], b["position"]["z"], b["room"] = a["position"]["x"], a["position"]["z"], a["room"]
    assert any(p.rule == "object-overlap" and p.element in (a["id"], b["id"]) for p in validate_house(h))


def test_child_off_its_receptacle(golden_house: dict[str, Any]) -> None:
    h = copy.deepcopy(golden_house)
    parent = next(o for o in h["objects"] if o.get("children"))
    child = parent["children"][0]
    child["position"]["y"] += 0.2
    assert named(validate_house(h), "object-child", child["id"])
    h = copy.deepcopy(golden_house)
    parent = next(o for o in h["objects"] if o.get("children"))
    child = parent["children"][0]
    child["position"]["x"] += 3.0
    assert named(validate_house(h), "object-child", child["id"])
    # at the receptacle's edge: a child sticking out by less than the tolerance (1 cm) is on it,
    # one sticking out by 3 cm is not, whichever way the receptacle is turned
    from mansion.scene.validate import OBJECT_TOLERANCE

    db = asset_ids()
    for yaw, axis in itertools.product((0.0, 90.0, 30.0), "xz"):
        for out, bad in ((0.5 * OBJECT_TOLERANCE, False), (3 * OBJECT_TOLERANCE, True)):
            h = copy.deepcopy(golden_house)
            parent = next(o for o in h["objects"] if o.get("children"))
            child = parent["children"][0]
            del parent["children"][1:]
            parent["rotation"]["y"] = child["rotation"]["y"] = yaw
            pb, cb = db[parent["assetId"]]["boundingBox"], db[child["assetId"]]["boundingBox"]
            # outwards along the receptacle's width (x) or depth (z), turned as footprints are
            shift = (pb[axis] - cb[axis]) / 2 + out
            a = math.radians(-yaw)
            ux, uz = (math.cos(a), math.sin(a)) if axis == "x" else (-math.sin(a), math.cos(a))
            child["position"]["x"] = parent["position"]["x"] + ux * shift
            child["position"]["z"] = parent["position"]["z"] + uz * shift
            assert named(validate_house(h), "object-child", child["id"]) == bad, (yaw, axis, out)


def test_object_blocking_a_doorway_makes_the_room_unreachable(golden_house: dict[str, Any]) -> None:
    from mansion.scene.entrances import room_entrances

    h = copy.deepcopy(golden_house)
    house = House.model_validate(h)
    ways = room_entrances(house)
    # a furnished room with a single door: a dresser wider than the doorway, pushed against it,
    # shuts it (the widest shallow dresser, and a room whose door it covers)
    bed = max(
        (a for a, rec in asset_ids().items()
         if rec["objectType"] == "Dresser" and rec["boundingBox"]["z"] <= 0.6),
        key=lambda a: asset_ids()[a]["boundingBox"]["x"],
    )
    reach = asset_ids()[bed]["boundingBox"]["x"] - 0.2
    rid = next(
        r for r, w in ways.items()
        if len(w) == 1 and len(_objects(h, r)) >= 3 and w[0].width <= reach
    )
    door = ways[rid][0]
    room = Polygon([(p.x, p.z) for p in next(r for r in house.rooms if r.id == rid).floor_polygon])
    (ax, az), (bx, bz) = door.a, door.b
    mx, mz = (ax + bx) / 2, (az + bz) / 2
    nx, nz = -(bz - az) / door.width, (bx - ax) / door.width
    if not room.contains(__import__("shapely").Point(mx + nx * 0.3, mz + nz * 0.3)):
        nx, nz = -nx, -nz
    # turned along the wall, the dresser covers the whole doorway
    depth = asset_ids()[bed]["boundingBox"]["z"]
    yaw = math.degrees(math.atan2(nx, nz))
    h["objects"].append({
        "id": "blocker", "assetId": bed, "room": rid, "kinematic": True,
        "position": {"x": mx + nx * (depth / 2 + 0.02), "y": 0.5, "z": mz + nz * (depth / 2 + 0.02)},
        "rotation": {"x": 0, "y": yaw, "z": 0},
    })
    problems = validate_house(h)
    unreached = {p.element for p in problems if p.rule == "object-reach"}
    assert {o["id"] for o in _objects(h, rid)} - {"blocker"} <= unreached, problems


def test_object_on_the_spawn(golden_house: dict[str, Any]) -> None:
    h = copy.deepcopy(golden_house)
    spawn = h["metadata"]["agentPoses"]["default"]["position"]
    # an object of the spawn's room (moved into another room it would be reported as misplaced)
    room = next(r["id"] for r in h["rooms"] if Polygon(
        [(p["x"], p["z"]) for p in r["floorPolygon"]]).covers(Point(spawn["x"], spawn["z"])))
    obj = next(o for o in h["objects"] if o["room"] == room)
    obj["position"]["x"], obj["position"]["z"] = spawn["x"], spawn["z"]
    assert named(validate_house(h), "object-reach", "agentPoses.default")


def test_a_room_that_cannot_be_furnished_is_recorded_not_fatal() -> None:
    from mansion.scene import floor_house
    from mansion.scene.furnish import FurnishJob, furnish_houses

    house = floor_house(golden_building(), 0, objects=False)
    # shut every door of one room (an agent no longer fits through any): it gets nothing
    rid = next(r.id for r in house.rooms if r.id == "study")
    for d in house.doors:
        if rid in (d.room0, d.room1):
            lo, hi = d.hole_polygon
            hi.x = lo.x + 0.3
    furnish_houses([FurnishJob(house, {}, 3)], "villa")
    record = house.metadata.mansion.furnishing
    assert record.rooms[rid].status == "failed" and "wide" in (record.rooms[rid].reason or "")
    assert rid in record.failed
    assert not [o for o in house.objects if o.room == rid]
    assert any(r.status == "furnished" for r in record.rooms.values())


def test_a_strip_narrower_than_the_agent_is_not_walkable() -> None:
    from mansion.scene import navigation

    # b is a 0.5 m strip (one solver cell) between a and c, its two doors offset: the agent
    # needing 0.6 m cannot walk from one to the other inside it (it goes round through d, e)
    rooms = {"d": (0, 3, 6.5, 5), "a": (0, 0, 3, 3), "b": (3, 0, 3.5, 3), "c": (3.5, 0, 6.5, 1.5),
             "e": (3.5, 1.5, 6.5, 3)}
    doors = [("d", "a", 1.0), ("d", "e", 1.0), ("e", "c", 1.0), ("a", "b", 1.0), ("b", "c", 1.0)]
    h = box_house(rooms, doors, (3.0, 4.0))
    problems = validate_house(h)
    assert [(p.rule, p.element) for p in problems if p.severity == "error"] == [("room-doors", "b")]
    assert "strip narrower than 0.60 m" in problems[0].message
    house = House.model_validate(h)
    cut = navigation.disconnected_entrances(house)
    assert [c.room for c in cut] == ["b"] and not cut[0].furniture
    # a smaller agent (radius 0.2 m, no margin: 0.4 m passages) walks along it
    assert navigation.disconnected_entrances(house, radius=0.2, margin=0.0) == []
    # without the ways round, c and e are cut off from the spawn in a
    h = box_house(rooms, [("a", "b", 1.0), ("b", "c", 1.0), ("e", "c", 1.0), ("d", "a", 1.0)], (1.5, 1.5))
    house = House.model_validate(h)
    assert navigation.unreachable_rooms(house) == ["c", "e"]
    assert navigation.unreachable_rooms(house, radius=0.2, margin=0.0) == []
    assert {p.element for p in validate_house(h) if p.rule == "navigable"} == {"c", "e"}


def test_furniture_checks_share_the_grown_obstacles() -> None:
    """The validator grows a floor's objects once (navigation.Obstacles) for the two furniture
    checks; they answer as when each grows its own, and refuse obstacles grown for another agent."""
    import shapely

    from mansion.scene import navigation

    h = _loop()
    # a dresser in b across the doorstep of its door from a
    h["objects"].append({"id": "b|dresser", "assetId": "Dresser_209_1", "room": "b", "kinematic": True,
                         "position": {"x": 3.3, "y": 0.35, "z": 1.5}, "rotation": {"x": 0, "y": 90, "z": 0}})
    house = House.model_validate(h)
    c = navigation.AGENT_RADIUS + navigation.MARGIN
    shared = navigation.Obstacles.of(house, c)
    assert shared.footprints == navigation.floor_objects(house) and len(shared.footprints) == 2
    # grown as one geometry: each footprint grown and the union of the two
    grown = shared.grown(shared.footprints)
    each = shapely.union_all([fp.buffer(c - navigation._TOL) for fp in shared.footprints])
    assert grown.symmetric_difference(each).area < 1e-9 and grown.area > sum(fp.area for fp in shared.footprints)
    assert shared.grown([]) is None
    cut = navigation.disconnected_entrances(house)
    blocked = navigation.blocked_entrances(house)
    assert [c.room for c in cut] == ["b"] and cut[0].furniture
    assert [room for room, _ in blocked] == ["b"]
    assert navigation.disconnected_entrances(house, obstacles=shared) == cut
    assert navigation.blocked_entrances(house, obstacles=shared) == blocked
    with pytest.raises(ValueError, match="clearance"):
        navigation.blocked_entrances(house, obstacles=navigation.Obstacles.of(house, 0.2))


def test_a_gap_narrower_than_the_agent_has_no_doorstep_to_shut_off() -> None:
    """A way narrower than the agent's passage (a 0.5 m gap where two rooms' walls leave an
    opening) is no way in, as for the furnishing and the doors a room must connect: furniture
    before it shuts nothing off (supermarket 93 of the hundred: shelves beside a 0.5 m gap)."""
    from mansion.scene import navigation

    def house(width: float) -> House:
        h = box_house(
            {"d": (0, 3, 9, 5), "a": (0, 0, 3, 3), "b": (3, 0, 6, 3), "c": (6, 0, 9, 3)},
            [("d", "a", 1.0), ("d", "c", 1.0), ("a", "b", width), ("b", "c", 1.0)], (4.5, 4.0),
            [{"id": "b|dresser", "assetId": "Dresser_209_1", "room": "b", "kinematic": True,
              "position": {"x": 3.3, "y": 0.35, "z": 1.5}, "rotation": {"x": 0, "y": 90, "z": 0}}],
        )
        return House.model_validate(h)

    assert [room for room, _ in navigation.blocked_entrances(house(1.0))] == ["b"]
    assert navigation.blocked_entrances(house(0.5)) == []


def test_house_text_is_json_dumps_but_for_small_numbers_written_in_full() -> None:
    """Every house file goes through house_text: pydantic's serializer, with json.dumps's
    layout and ASCII escapes, which reads back to the same values."""
    import random

    from mansion.scene.house import house_text

    rng = random.Random(3)
    words = ["door|1|2", "1×1", "café", "😀 emoji", 'quote " and \\ backslash', "tab\tnew\nline", ""]

    def value(depth: int) -> Any:
        kind = rng.randrange(7 if depth < 3 else 4)
        if kind == 0:
            return round(rng.uniform(-50, 50), rng.randrange(0, 16))
        if kind == 1:
            return rng.choice([0, -3, 10**12, True, False, None, -0.0, 1e300, 0.5e-3])
        if kind == 2:
            return rng.choice(words)
        if kind == 3:
            return rng.uniform(-1e-4, 1e-4) * 10 ** -rng.randrange(0, 4)
        if kind in (4, 5):
            return {rng.choice(words) + str(k): value(depth + 1) for k in range(rng.randrange(0, 4))}
        return [value(depth + 1) for _ in range(rng.randrange(0, 4))]

    differ = 0
    for _ in range(300):
        data = {"rooms": value(0), "objects": [value(1) for _ in range(3)]}
        text = house_text(data)
        assert text.isascii() and text.endswith("\n")
        assert json.loads(text) == data
        differ += text != json.dumps(data, indent=1) + "\n"
        assert house_text(data, indent=None) == json.dumps(data) + "\n"
    assert 0 < differ < 300  # only where a number lies between 1e-7 and 1e-4
    assert house_text({"x": 3e-05, "y": 2.5}) == '{\n "x": 0.00003,\n "y": 2.5\n}\n'
