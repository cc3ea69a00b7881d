"""Seed planners and the callback wrapper the Rust solver calls (no solver needed)."""

from __future__ import annotations

import json
from typing import Any

import pytest

from mansion import FixedSeedPlanner, PlannerError, SeedPlan, SeedPlanner, SeedRequest
from mansion.floorplan import ChildSeed, SeedBox, planner_callback

REQUEST: dict[str, Any] = {
    "round": 2,
    "parent": "hall",
    "cell_size": 0.5,
    "region": {
        "polygon": [[0.0, 0.0], [6.0, 0.0], [6.0, 4.0], [0.0, 4.0]],
        "holes": [],
        "area": 24.0,
        "cells": 96,
    },
    "layout": {"rooms": [{"id": "living", "polygon": [[6, 0], [9, 0], [9, 4], [6, 4]], "holes": []}]},
    "children": [
        {"id": "bath", "room_type": "bathroom", "target_area": 6.0, "own_area": 6.0, "neighbours": ["hall"]},
        {"id": "store", "room_type": "storage", "target_area": 4.0, "own_area": 4.0, "neighbours": ["hall"]},
    ],
    "parent_neighbours": ["living", "bath", "store"],
}
REQUEST_JSON = json.dumps(REQUEST)


def test_fixed_planner_through_the_callback() -> None:
    planner = FixedSeedPlanner({"bath": (1.0, 1.0), "store": (5, 3), "hall": (3.0, 2.0)})
    assert isinstance(planner, SeedPlanner)
    out = json.loads(planner_callback(planner)(REQUEST_JSON))
    assert out == {
        "seeds": {
            "bath": {"point": [1.0, 1.0], "fraction": None},
            "store": {"point": [5.0, 3.0], "fraction": None},
        },
        "parent_seed": [3.0, 2.0],
        "descendant_seeds": {},
    }


def test_fixed_planner_passes_descendants_points() -> None:
    request = json.loads(REQUEST_JSON)
    request["children"][0]["descendants"] = [{"id": "shower", "area": 2.0}, {"id": "wc", "area": 1.0}]
    points = {"bath": (1.0, 1.0), "store": (5, 3), "shower": (0.5, 0.5)}
    out = json.loads(planner_callback(FixedSeedPlanner(points))(json.dumps(request)))
    # descendants with a point are passed on; "wc" has none and grows with its ancestor's seed
    assert out["descendant_seeds"] == {"shower": [0.5, 0.5]}
    alone = json.loads(planner_callback(FixedSeedPlanner(points, descendants=False))(json.dumps(request)))
    assert alone["descendant_seeds"] == {}


def test_fixed_planner_without_parent_point() -> None:
    planner = FixedSeedPlanner({"bath": (1.0, 1.0), "store": (5.0, 3.0)})
    out = json.loads(planner_callback(planner)(REQUEST_JSON))
    assert out["parent_seed"] is None


def test_fixed_planner_missing_child_is_a_planner_error() -> None:
    callback = planner_callback(FixedSeedPlanner({"bath": (1.0, 1.0)}))
    with pytest.raises(PlannerError, match="'store'"):
        callback(REQUEST_JSON)


def test_box_seeds_and_fractions_use_the_contract_shape() -> None:
    def plan(request: SeedRequest) -> SeedPlan:
        assert request.parent == "hall" and request.region.cells == 96
        return SeedPlan(
            seeds={
                "bath": ChildSeed(box=SeedBox(x=(0.0, 2.0), y=(0.0, 3.0)), fraction=0.25),
                "store": ChildSeed(point=(5.0, 3.0), fraction=0.2),
            }
        )

    out = json.loads(planner_callback(plan)(REQUEST_JSON))
    assert out == {
        "seeds": {
            "bath": {"box": {"x": [0.0, 2.0], "y": [0.0, 3.0]}, "fraction": 0.25},
            "store": {"point": [5.0, 3.0], "fraction": 0.2},
        },
        "parent_seed": None,
        "descendant_seeds": {},
    }


def test_a_plain_dict_plan_is_accepted() -> None:
    def plan(request: SeedRequest) -> dict[str, Any]:
        return {"seeds": {c.id: {"point": [1, 1]} for c in request.children}}

    out = json.loads(planner_callback(plan)(REQUEST_JSON))
    assert set(out["seeds"]) == {"bath", "store"}


def test_planner_exception_becomes_planner_error() -> None:
    class Broken:
        def plan(self, request: SeedRequest) -> SeedPlan:
            raise RuntimeError("the model returned no JSON")

    with pytest.raises(PlannerError, match="the model returned no JSON") as info:
        planner_callback(Broken())(REQUEST_JSON)
    assert "round 2" in str(info.value) and "'hall'" in str(info.value)
    assert isinstance(info.value.__cause__, RuntimeError)


@pytest.mark.parametrize(
    ("plan", "match"),
    [
        ({"seeds": {"bath": {"point": [1, 1]}, "store": {"point": [2, 2]}, "attic": {"point": [0, 0]}}}, "'attic'"),
        ({"seeds": {"bath": {"point": [1, 1]}}}, "'store'"),
        ({"seeds": {"bath": {"point": [1, 1], "box": {"x": [0, 1], "y": [0, 1]}}, "store": {"point": [2, 2]}}}, "exactly one"),
        ({"seeds": {"bath": {"point": [1, 1], "fraction": 3.0}, "store": {"point": [2, 2]}}}, "fraction"),
        ({"seeds": {"bath": {"box": {"x": [2, 1], "y": [0, 1]}}, "store": {"point": [2, 2]}}}, "inverted"),
        ({"nothing": True}, "seeds"),
    ],
)
def test_bad_plans_are_planner_errors(plan: dict[str, Any], match: str) -> None:
    with pytest.raises(PlannerError, match=match):
        planner_callback(lambda request: plan)(REQUEST_JSON)


def test_malformed_request_is_a_planner_error() -> None:
    callback = planner_callback(FixedSeedPlanner({}))
    with pytest.raises(PlannerError, match="malformed seed request"):
        callback('{"round": 1}')


def _pantry_floor() -> tuple[dict[str, Any], dict[str, Any], dict[str, tuple[float, float]]]:
    graph = {
        "nodes": [
            {"id": "hall", "type": "main", "area": 30.0},
            {"id": "kitchen", "type": "Entities", "area": 30.0},
            {"id": "pantry", "type": "Entities", "area": 10.0},
            {"id": "study", "type": "Entities", "area": 10.0},
        ],
        "edges": [
            {"source": "hall", "target": "kitchen"},
            {"source": "kitchen", "target": "pantry"},
            {"source": "hall", "target": "study"},
        ],
    }
    footprint = {"polygon": [[0, 0], [10, 0], [10, 8], [0, 8]]}
    points = {"hall": (3.0, 6.0), "kitchen": (7.5, 5.0), "pantry": (8.5, 1.0), "study": (2.0, 2.0)}
    return graph, footprint, points


def test_descendant_seeds_grow_a_child_region_from_every_room_it_will_hold() -> None:
    from mansion import solve_floor

    graph, footprint, points = _pantry_floor()
    layout = solve_floor(graph, footprint, seed_planner=FixedSeedPlanner(points), rng_seed=3)
    assert [r.parent for r in layout.diagnostics.rounds] == ["hall", "kitchen"]
    # the pantry, placed through the kitchen's round, ends up near its own point
    pantry = layout.room("pantry")
    assert abs(pantry.centroid[0] - 8.5) < 2.0 and abs(pantry.centroid[1] - 1.0) < 2.0
    assert layout.adjacency("kitchen", "pantry") is not None
    assert sum(r.area for r in layout.rooms) == pytest.approx(80.0)


def test_a_descendant_seed_for_a_room_no_child_holds_is_a_planner_error() -> None:
    from mansion import solve_floor

    graph, footprint, points = _pantry_floor()

    def plan(request: SeedRequest) -> SeedPlan:
        base = FixedSeedPlanner(points).plan(request)
        return base.model_copy(update={"descendant_seeds": {"study": (1.0, 1.0)}})

    with pytest.raises(PlannerError, match="descendant seed for 'study'"):
        solve_floor(graph, footprint, seed_planner=plan)
