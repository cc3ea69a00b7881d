"""The pydantic models: JSON round trips, the contract's JSON shapes, and input validation."""

from __future__ import annotations

import copy
import json
from typing import Any

import numpy as np
import pytest
from pydantic import BaseModel, ValidationError
from shapely.geometry import Point as ShapelyPoint
from shapely.geometry import Polygon

import mansion
from mansion import (
    Adjacency,
    Core,
    Diagnostics,
    EnergyWeights,
    FloorLayout,
    Footprint,
    InvalidInputError,
    LabelGrid,
    LayoutRoom,
    RoomEdge,
    RoomGraph,
    RoomNode,
    RoundDiagnostics,
    SolverSettings,
)
from mansion.examples import EXAMPLES, example_apartment, example_office
from mansion.floorplan import ChildSeed, SeedBox, SeedPlan, SeedRequest

# A layout exactly as the Rust solver returns it (the binding contract): a 4 × 2 m floor with a
# 1 × 1 m stair core in the corner, a hall and a room with a 1 m² courtyard-free notch.
LAYOUT_JSON: dict[str, Any] = {
    "rooms": [
        {
            "id": "hall",
            "room_type": "entrance_hall",
            "type": "main",
            "polygon": [[1.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [0.0, 1.0], [1.0, 1.0]],
            "holes": [],
            "area": 3.0,
            "target_area": 3.5,
            "centroid": [1.1666666666666667, 1.1666666666666667],
        },
        {
            "id": "office",
            "room_type": "office",
            "type": "Entities",
            "polygon": [[2.0, 0.0], [4.0, 0.0], [4.0, 2.0], [2.0, 2.0]],
            "holes": [],
            "area": 4.0,
            "target_area": 3.5,
            "centroid": [3.0, 1.0],
        },
        {
            "id": "stair_1",
            "room_type": "stair",
            "type": "stair",
            "polygon": [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
            "holes": [],
            "area": 1.0,
            "target_area": 0.0,
            "centroid": [0.5, 0.5],
        },
    ],
    "grid": {
        "origin": [0.0, 0.0],
        "cell_size": 1.0,
        "cols": 4,
        "rows": 2,
        "ids": ["hall", "office", "stair_1"],
        "labels": [[2, 0, 1, 1], [0, 0, 1, 1]],
    },
    "adjacencies": [
        {"a": "hall", "b": "office", "contact": 2.0, "longest": 2.0},
        {"a": "hall", "b": "stair_1", "contact": 2.0, "longest": 1.0},
    ],
    "diagnostics": {
        "rounds": [
            {
                "parent": "hall",
                "children": ["office"],
                "retry": 0,
                "fallback": False,
                "widths_relaxed": False,
                "relaxed_width": None,
                "candidates": 100,
                "rejected": {"topology": 12, "disconnected": 3},
                "energy": {
                    "total": 0.125,
                    "rooms": {
                        "office": {
                            "ratio": 0.857,
                            "seed": 0.0,
                            "drift": 0.0,
                            "wall": 0.8,
                            "corner": 0.0,
                            "energy": 0.057,
                        }
                    },
                },
                "seconds": 0.002,
            }
        ],
        "fallback_used": False,
        "backtracks": 0,
        "seconds": 0.003,
    },
}

SEED_REQUEST_JSON: dict[str, Any] = {
    "round": 1,
    "parent": "hall",
    "cell_size": 0.5,
    "region": {
        "polygon": [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]],
        "holes": [],
        "area": 8.0,
        "cells": 32,
    },
    "layout": {"rooms": [{"id": "stair_1", "polygon": [[4, 0], [5, 0], [5, 1], [4, 1]], "holes": []}]},
    "children": [
        {
            "id": "office",
            "room_type": "office",
            "target_area": 4.5,
            "own_area": 3.5,
            "neighbours": ["hall", "store"],
            "descendants": [{"id": "store", "area": 1.5}],
        }
    ],
    "parent_neighbours": ["office", "stair_1"],
}


def roundtrip(model: BaseModel) -> BaseModel:
    again = type(model).model_validate_json(model.model_dump_json())
    assert again == model
    assert again.model_dump_json() == model.model_dump_json()
    return again


def graph_dict() -> dict[str, Any]:
    return {
        "nodes": [
            {"id": "hub", "type": "main", "area": 20.0},
            {"id": "kitchen", "type": "Entities", "area": 10.0},
            {"id": "bedroom", "type": "Entities", "area": 12.0},
            {"id": "stair_1", "type": "stair", "area": 0.0},
        ],
        "edges": [
            {"source": "hub", "target": "kitchen"},
            {"source": "hub", "target": "bedroom"},
            {"source": "hub", "target": "stair_1"},
        ],
    }


# -- round trips --------------------------------------------------------------------------------


@pytest.mark.parametrize("name", sorted(EXAMPLES))
def test_examples_round_trip(name: str) -> None:
    graph, footprint = EXAMPLES[name]()
    roundtrip(graph)
    roundtrip(footprint)
    for node in graph.nodes:
        roundtrip(node)
    for edge in graph.edges:
        roundtrip(edge)
    for core in footprint.cores:
        roundtrip(core)


def test_examples_areas_fill_the_free_area() -> None:
    for make in (example_apartment, example_office):
        graph, footprint = make()
        rooms = sum(n.area for n in graph.nodes if not n.is_core)
        assert rooms == pytest.approx(footprint.free_area, rel=0.02)
        core_ids = {c.id for c in footprint.cores}
        assert core_ids == {n.id for n in graph.nodes if n.is_core}
    graph, _ = example_office()
    assert 18 <= len([n for n in graph.nodes if not n.is_core]) <= 22


def test_node_defaults_and_round_trip() -> None:
    node = RoomNode(id="kitchen", type="Entities", area=9)
    assert node.room_type == "kitchen"
    assert node.open_relation == "door"
    assert node.floor_material is None
    again = roundtrip(node)
    assert isinstance(again, RoomNode) and again.area == 9.0
    roundtrip(RoomEdge(source="a", target="b", kind="adjacent"))


def test_footprint_round_trip_with_everything() -> None:
    fp = Footprint(
        polygon=[(0, 0), (10, 0), (10, 8), (0, 8)],
        holes=[[(4, 3), (6, 3), (6, 5), (4, 5)]],
        cores=[Core(id="lift", type="elevator", x=(0, 2), y=(0, 2.5))],
        fixed_walls=[((5.0, 0.0), (5.0, 3.0))],
    )
    roundtrip(fp)
    assert fp.area == pytest.approx(76.0)
    assert fp.free_area == pytest.approx(71.0)
    assert Footprint.rectangle(12, 8).area == pytest.approx(96.0)


def test_layout_contract_json_round_trips_exactly() -> None:
    text = json.dumps(LAYOUT_JSON)
    layout = FloorLayout.model_validate_json(text)
    # timings are read but never written: the same inputs and seed give the same bytes
    assert layout.diagnostics.seconds == 0.003 and layout.diagnostics.rounds[0].seconds == 0.002
    timeless = copy.deepcopy(LAYOUT_JSON)
    del timeless["diagnostics"]["seconds"], timeless["diagnostics"]["rounds"][0]["seconds"]
    assert json.loads(layout.model_dump_json()) == timeless
    layout = FloorLayout.model_validate(timeless)
    roundtrip(layout)
    for part in (
        *layout.rooms,
        layout.grid,
        *layout.adjacencies,
        layout.diagnostics,
        *layout.diagnostics.rounds,
    ):
        roundtrip(part)
    assert isinstance(layout.rooms[0], LayoutRoom)
    assert isinstance(layout.adjacencies[0], Adjacency)
    assert isinstance(layout.diagnostics, Diagnostics)
    assert isinstance(layout.diagnostics.rounds[0], RoundDiagnostics)


def test_layout_helpers(tmp_path: Any) -> None:
    layout = FloorLayout.model_validate(LAYOUT_JSON)
    assert layout.room("office").area == 4.0
    assert layout.room("stair_1").is_core
    with pytest.raises(KeyError, match="nowhere"):
        layout.room("nowhere")
    assert layout.adjacency("office", "hall") is not None
    assert layout.adjacency("office", "stair_1") is None
    assert layout.room("office").area_error == pytest.approx(0.5 / 3.5)
    assert layout.room("stair_1").area_error is None

    grid = layout.grid
    arr = grid.array()
    assert arr.dtype == np.int32 and arr.shape == (2, 4)
    assert arr[0, 0] == 2  # row 0 is the bottom row
    assert grid.room_at(0.5, 0.5) == "stair_1"
    assert grid.room_at(0.5, 1.5) == "hall"
    assert grid.room_at(3.9, 1.9) == "office"
    assert grid.room_at(-0.1, 0.5) is None
    assert grid.room_at(4.0, 0.5) is None
    # the array is kept for the grid's labels, each caller given a copy of its own
    arr[0, 0] = 7
    assert grid.array()[0, 0] == 2
    # a grid with other labels has its own array, the one it was given, and equals a grid read
    # from the same lists
    other = grid.relabelled(np.zeros((2, 4), dtype=np.int64), ids=grid.ids)
    assert other.labels == [[0] * 4] * 2 and not other.array().any() and grid.array()[0, 0] == 2
    assert other == grid.model_copy(update={"labels": [[0] * 4 for _ in range(2)]})

    path = layout.to_json(tmp_path / "sub" / "layout.json")
    assert FloorLayout.load(path) == layout.model_copy(update={"diagnostics": layout.diagnostics.model_copy(update={
        "seconds": 0.0, "rounds": [r.model_copy(update={"seconds": 0.0}) for r in layout.diagnostics.rounds]})})
    assert [p.name for p in path.parent.iterdir()] == ["layout.json"]  # no temp file left


def test_label_grid_shape_is_checked() -> None:
    bad = copy.deepcopy(LAYOUT_JSON["grid"])
    bad["labels"][1].append(0)
    with pytest.raises(ValidationError, match="row 1"):
        LabelGrid.model_validate(bad)
    bad = copy.deepcopy(LAYOUT_JSON["grid"])
    bad["labels"][0][0] = 7
    with pytest.raises(ValidationError, match="label 7"):
        LabelGrid.model_validate(bad)


def test_settings_and_weights_round_trip(tmp_path: Any) -> None:
    w = EnergyWeights()
    assert (w.ratio, w.seed, w.drift, w.wall, w.corner) == (1.28, 0.21, 17.65, 0.57, 0.29)
    roundtrip(w)
    roundtrip(EnergyWeights(ratio=1.5, seed=0.0, wall=2.0, corner=0.25))
    s = SolverSettings()
    assert s.gammas[0] == 0.25 and len(s.gammas) == 10 and s.growth == "balanced"
    roundtrip(s)
    roundtrip(SolverSettings(k=4.0, gammas=[1.0, 2.0], min_width=3, fallback_samples=50))

    w.model_copy(update={"wall": 1.25}).save(tmp_path / "w.json")
    assert EnergyWeights.load(tmp_path / "w.json").wall == 1.25
    (tmp_path / "partial.json").write_text('{"ratio": 2.0}')
    assert EnergyWeights.load(tmp_path / "partial.json") == EnergyWeights(ratio=2.0)
    (tmp_path / "typo.json").write_text('{"ratoi": 2.0}')
    with pytest.raises(InvalidInputError, match="ratoi"):
        EnergyWeights.load(tmp_path / "typo.json")
    (tmp_path / "neg.json").write_text('{"corner": -1}')
    with pytest.raises(InvalidInputError, match="corner"):
        EnergyWeights.load(tmp_path / "neg.json")
    with pytest.raises(ValidationError, match="must not decrease"):
        SolverSettings(gammas=[1.0, 3.0, 2.0])


def test_seed_models_round_trip() -> None:
    request = SeedRequest.model_validate_json(json.dumps(SEED_REQUEST_JSON))
    assert json.loads(request.model_dump_json()) == SEED_REQUEST_JSON
    roundtrip(request)
    plan = SeedPlan(
        seeds={
            "office": ChildSeed(point=(3.0, 1.0), fraction=0.5),
            "store": ChildSeed(box=SeedBox(x=(0.0, 1.0), y=(0.0, 2.0))),
        },
        parent_seed=(1.0, 1.0),
    )
    roundtrip(plan)
    roundtrip(SeedPlan(seeds={}))
    with pytest.raises(ValidationError, match="exactly one"):
        ChildSeed(point=(0, 0), box=SeedBox(x=(0, 1), y=(0, 1)))
    with pytest.raises(ValidationError, match="exactly one"):
        ChildSeed()
    with pytest.raises(ValidationError, match="outside"):
        ChildSeed(point=(0, 0), fraction=1.5)


# -- room graph validation ----------------------------------------------------------------------


def _with(change: str) -> dict[str, Any]:
    g = graph_dict()
    if change == "unknown edge node":
        g["edges"].append({"source": "kitchen", "target": "ghost_room"})
    elif change == "duplicate id":
        g["nodes"].append({"id": "kitchen", "type": "Entities", "area": 4.0})
    elif change == "zero main":
        g["nodes"][0]["type"] = "area"
    elif change == "two mains":
        g["nodes"][2]["type"] = "main"
    elif change == "self-loop":
        g["edges"].append({"source": "bedroom", "target": "bedroom"})
    elif change == "duplicate edge":
        g["edges"].append({"source": "kitchen", "target": "hub", "kind": "adjacent"})
    elif change == "zero area":
        g["nodes"][1]["area"] = 0.0
    else:
        raise AssertionError(change)
    return g


GRAPH_ERRORS = [
    ("unknown edge node", ["ghost_room", "kitchen"]),
    ("duplicate id", ["kitchen"]),
    ("zero main", ["main"]),
    ("two mains", ["hub", "bedroom"]),
    ("self-loop", ["bedroom", "self-loop"]),
    ("duplicate edge", ["kitchen", "hub"]),
    ("zero area", ["kitchen"]),
]


@pytest.mark.parametrize(("change", "names"), GRAPH_ERRORS)
def test_graph_errors_are_invalid_input(change: str, names: list[str]) -> None:
    data = _with(change)
    with pytest.raises(InvalidInputError) as info:
        RoomGraph.parse(data)
    for name in names:
        assert name in str(info.value)
    assert "Value error" not in str(info.value)  # pydantic's wrapping is unwrapped

    # Built directly, pydantic wraps the same message in a ValidationError (a ValueError).
    with pytest.raises(ValidationError) as direct:
        RoomGraph.model_validate(data)
    for name in names:
        assert name in str(direct.value)


@pytest.mark.parametrize(("change", "names"), GRAPH_ERRORS)
def test_solve_floor_reports_graph_errors_as_invalid_input(change: str, names: list[str]) -> None:
    # Validation happens before the Rust core is called.
    with pytest.raises(InvalidInputError) as info:
        mansion.solve_floor(_with(change), Footprint.rectangle(6, 6))
    for name in names:
        assert name in str(info.value)


def test_valid_graph_helpers() -> None:
    graph = RoomGraph.parse(graph_dict())
    assert graph.hub.id == "hub"
    assert graph.node("kitchen").area == 10.0
    assert graph.neighbours("hub") == ["kitchen", "bedroom", "stair_1"]
    assert graph.neighbours("kitchen") == ["hub"]
    with pytest.raises(KeyError):
        graph.node("ghost")
    # A model instance is validated again: a later mutation cannot slip through.
    graph.nodes[1].area = -3.0
    with pytest.raises(InvalidInputError, match="area"):
        RoomGraph.parse(graph)


def test_footprint_errors_are_invalid_input() -> None:
    with pytest.raises(InvalidInputError, match="lift"):
        Footprint.parse(
            {"polygon": [[0, 0], [4, 0], [4, 4]], "cores": [{"id": "lift", "type": "elevator", "x": [2, 1], "y": [0, 1]}]}
        )
    with pytest.raises(InvalidInputError, match="polygon"):
        Footprint.parse({"polygon": [[0, 0], [4, 0]]})
    with pytest.raises(InvalidInputError, match="polygon"):
        Footprint.parse({"polygon": [[0, 0], [4, "east"], [4, 4]]})
    with pytest.raises(InvalidInputError, match="duplicate core id 'c'"):
        Footprint.parse(
            {
                "polygon": [[0, 0], [4, 0], [4, 4], [0, 4]],
                "cores": [
                    {"id": "c", "type": "stair", "x": [0, 1], "y": [0, 1]},
                    {"id": "c", "type": "stair", "x": [3, 4], "y": [3, 4]},
                ],
            }
        )
    with pytest.raises(InvalidInputError):
        Footprint.rectangle(0, 3)


# -- Footprint.from_mask (needs mansion._core.mask_outline) -------------------------------------


L_MASK = [
    [1, 0, 0],
    [1, 0, 0],
    [1, 1, 1],
]

# Not symmetric top to bottom, so a missing flip shows: the hole is in the second row from the
# top and the notch at the bottom right.
HOLE_MASK = [
    [1, 1, 1],
    [1, 0, 1],
    [1, 1, 1],
    [1, 1, 0],
]


def _shape(fp: Footprint) -> Polygon:
    return Polygon(fp.polygon, fp.holes)


def _assert_cells_match(fp: Footprint, mask: list[list[int]], s: float) -> None:
    poly = _shape(fp)
    h = len(mask)
    for r, row in enumerate(mask):
        for c, v in enumerate(row):
            centre = ShapelyPoint((c + 0.5) * s, (h - r - 0.5) * s)
            assert poly.contains(centre) == bool(v), (r, c)


def test_from_mask_l_shape() -> None:
    fp = Footprint.from_mask(np.array(L_MASK, dtype=bool), 0.5)
    expected = Polygon([(0, 0), (1.5, 0), (1.5, 0.5), (0.5, 0.5), (0.5, 1.5), (0, 1.5)])
    assert _shape(fp).equals(expected)
    assert fp.holes == []
    assert fp.area == pytest.approx(5 * 0.25)
    _assert_cells_match(fp, L_MASK, 0.5)


def test_from_mask_with_hole() -> None:
    fp = Footprint.from_mask(HOLE_MASK, 1.0)  # nested lists of 0/1 work too
    expected = Polygon(
        [(0, 0), (2, 0), (2, 1), (3, 1), (3, 4), (0, 4)],
        [[(1, 2), (2, 2), (2, 3), (1, 3)]],
    )
    assert len(fp.holes) == 1
    assert _shape(fp).equals(expected)
    assert fp.area == pytest.approx(10.0)
    _assert_cells_match(fp, HOLE_MASK, 1.0)


@pytest.mark.parametrize(("mask", "s"), [(L_MASK, 0.5), (HOLE_MASK, 1.0), (HOLE_MASK, 0.25)])
def test_from_mask_rasterises_back_to_the_mask(mask: list[list[int]], s: float) -> None:
    from mansion import _core

    fp = Footprint.from_mask(mask, s)
    grid, origin = _core.rasterise(fp.model_dump_json(), s)
    assert grid.dtype == np.int32
    image = np.array(mask, dtype=bool)
    h, w = image.shape
    # Compare cell by cell through plan coordinates, whatever border the grid carries.
    for r in range(grid.shape[0]):
        for c in range(grid.shape[1]):
            x = origin[0] + (c + 0.5) * s
            y = origin[1] + (r + 0.5) * s
            col, row_from_bottom = int(np.floor(x / s)), int(np.floor(y / s))
            inside = 0 <= col < w and 0 <= row_from_bottom < h and image[h - 1 - row_from_bottom, col]
            assert (grid[r, c] != -1) == inside, (r, c)
    free_cells = int((grid != -1).sum())
    assert free_cells == int(image.sum())


def test_from_mask_rejects_bad_masks() -> None:
    with pytest.raises(InvalidInputError, match="2-D"):
        Footprint.from_mask([1, 1, 0], 1.0)
    with pytest.raises(InvalidInputError, match="no true cell"):
        Footprint.from_mask([[0, 0], [0, 0]], 1.0)
    with pytest.raises(InvalidInputError, match="cell_size"):
        Footprint.from_mask([[1]], 0.0)
    with pytest.raises(InvalidInputError, match="booleans"):
        Footprint.from_mask([[1, 2]], 1.0)


def test_public_api_names_exist() -> None:
    for name in mansion.__all__:
        assert hasattr(mansion, name), name
    assert isinstance(mansion.__version__, str) and mansion.__version__
