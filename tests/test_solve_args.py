"""solve_floor's argument checking and the options object it sends to the core (no solver needed:
every check runs before the Rust core is called)."""

from __future__ import annotations

import math
from typing import Any

import pytest

import mansion
from mansion import EnergyWeights, Footprint, InvalidInputError, SolverSettings
from mansion.examples import example_apartment
from mansion.floorplan import build_options


def test_default_options_match_the_binding_contract() -> None:
    assert build_options() == {
        "cell_size": 0.5,
        "retries": 10,
        "batch": 100,
        "min_contact": 1.0,
        "hierarchical": True,
        "rng_seed": 0,
        "weights": {
            "ratio": 1.28, "seed": 0.21, "drift": 17.65, "wall": 0.57, "corner": 0.29, "rect": 0.0,
            "aspect": 0.0,
        },
        "k": 8.0,
        "gammas": [0.25, 1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0],
        "seed_separation": 2.0,
        "fallback_samples": 400,
        "min_width": None,
        "relax_widths": True,
        "max_backtracks": 8,
        "strict_backtracks": None,
        "refine_walls": True,
        "growth": "balanced",
        "reseeds": 0,
        "slabs": False,
        "wide_retries": 0,
        "repair": False,
        "rebalance": False,
        "rebalance_later_only": False,
        "keep_first_round": False,
        "hold_regions": False,
    }


def test_options_take_models_and_dicts() -> None:
    opts = build_options(
        weights={"wall": 0.0},
        settings=SolverSettings(k=2.0, gammas=[1.0, 2.0], min_width=2),
        rng_seed=2**64 - 1,
        hierarchical=False,
    )
    assert opts["weights"] == {
        "ratio": 1.28, "seed": 0.21, "drift": 17.65, "wall": 0.0, "corner": 0.29, "rect": 0.0, "aspect": 0.0,
    }
    assert opts["k"] == 2.0 and opts["gammas"] == [1.0, 2.0] and opts["min_width"] == 2
    assert opts["hierarchical"] is False
    assert build_options(weights=EnergyWeights(ratio=1.0))["weights"]["ratio"] == 1.0


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"cell_size": 0}, "cell_size"),
        ({"cell_size": -0.5}, "cell_size"),
        ({"cell_size": math.nan}, "cell_size"),
        ({"cell_size": "0.5"}, "cell_size"),
        ({"retries": 0}, "retries"),
        ({"retries": 2.5}, "retries"),
        ({"retries": True}, "retries"),
        ({"batch": 0}, "batch"),
        ({"min_contact": -1.0}, "min_contact"),
        ({"min_contact": math.inf}, "min_contact"),
        ({"rng_seed": -1}, "rng_seed"),
        ({"rng_seed": 2**64}, "rng_seed"),
        ({"hierarchical": 1}, "hierarchical"),
        ({"weights": {"ratio": -1.0}}, "ratio"),
        ({"weights": {"colour": 1.0}}, "colour"),
        ({"settings": {"gammas": []}}, "gammas"),
        ({"settings": {"gammas": [2.0, 1.0]}}, "gammas"),
        ({"settings": {"min_width": 0}}, "min_width"),
    ],
)
def test_bad_arguments_are_invalid_input(kwargs: dict[str, Any], match: str) -> None:
    graph, footprint = example_apartment()
    with pytest.raises(InvalidInputError, match=match):
        mansion.solve_floor(graph, footprint, **kwargs)


def test_pydantic_errors_become_readable_invalid_input() -> None:
    graph, _ = example_apartment()
    with pytest.raises(InvalidInputError) as info:
        mansion.solve_floor(graph, {"polygon": [[0, 0], [12, 0], [12, "north"]]})
    message = str(info.value)
    assert message.startswith("invalid footprint: polygon.2.1")
    with pytest.raises(InvalidInputError, match="room graph must be a RoomGraph or a dict"):
        mansion.solve_floor("graph.json", Footprint.rectangle(12, 8))  # type: ignore[arg-type]
    with pytest.raises(InvalidInputError, match="nodes.0.type"):
        mansion.solve_floor({"nodes": [{"id": "a", "type": "hall", "area": 3}]}, Footprint.rectangle(3, 3))


def test_a_bad_seed_planner_is_rejected_early() -> None:
    graph, footprint = example_apartment()
    with pytest.raises(InvalidInputError, match="seed_planner"):
        mansion.solve_floor(graph, footprint, seed_planner=42)  # type: ignore[arg-type]
