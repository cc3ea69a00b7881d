"""Scenes: the house models, instantiation over a sample of buildings, the golden building, every
validation rule against a hand-broken house, and the CLI commands."""

from __future__ import annotations

import copy
import json
import sys
from pathlib import Path
from typing import Any

import pytest
from shapely.geometry import Polygon
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
from scene_cases import GOLDEN, golden_building, golden_payload

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
    assert validate_path(manifest) == []
    scenes = build_scenes(building)
    for house, floor in zip(scenes.houses, building.floors, strict=True):
        # every access edge of the graph is a door or an opening, and doors carry real assets
        assert house.objects == []
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


# -- every rule, hand-broken ---------------------------------------------------------------------


def _first(items: list[dict[str, Any]], **match: Any) -> dict[str, Any]:
    return next(i for i in items if all(i.get(k) == v for k, v in match.items()))


def _wall(house: dict[str, Any], wid: str) -> dict[str, Any]:
    return _first(house["walls"], id=wid)


def test_valid_house_has_no_problem(golden_house: dict[str, Any]) -> None:
    assert validate_house(golden_house) == []


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
    assert named(validate_house(h), "hole-wall", door["id"])


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
    assert named(problems, "asset-id", h["doors"][0]["id"])
    assert named(problems, "asset-id", h["windows"][0]["id"])
    assert named(problems, "asset-id", h["rooms"][0]["id"])


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
    assert named(validate_house(h), "reachable", "guest_bedroom")


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


def test_bad_house_file_is_a_clear_error(tmp_path: Path) -> None:
    bad = tmp_path / "house.json"
    bad.write_text("{not json")
    with pytest.raises(InvalidInputError, match="cannot read"):
        validate_path(bad)


# -- command line ------------------------------------------------------------------------------


def test_cli_validate_reports_the_element(tmp_path: Path, golden_house: dict[str, Any]) -> None:
    good = tmp_path / "good.json"
    good.write_text(json.dumps(golden_house))
    result = runner.invoke(app, ["validate", str(good)])
    assert result.exit_code == 0, result.output
    h = copy.deepcopy(golden_house)
    h["doors"][0]["holePolygon"][0]["y"] = 0.3
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(h))
    result = runner.invoke(app, ["validate", str(bad)])
    assert result.exit_code == 1
    assert "door-floor" in result.output and h["doors"][0]["id"] in result.output


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
