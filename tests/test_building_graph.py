"""The LangGraph pipeline gives the same building as the direct offline loop.

The offline planner is deterministic, so running it through the graph (floors fanned out, waves
of solves, copies filled in at the join) must reproduce ``generate_building`` exactly, apart from
the solver's timings.
"""

from __future__ import annotations

import json

import pytest

from mansion import generate_building
from mansion.building.graph import run_building_graph
from mansion.building.generate import solver_options
from mansion.planning.planner import Constraints, OfflinePlanner

# what generate_building hands the solver by default
SOLVER = solver_options()


def _plain(building) -> dict:
    data = json.loads(building.model_dump_json())
    for floor in data["floors"]:
        floor["layout"].pop("diagnostics")
    return data


@pytest.mark.parametrize(
    ("description", "floors"),
    [
        ("a five-storey office", 5),  # load-bearing walls: one floor per wave, copies
        ("a two-storey hospital", 2),  # no carried walls: every floor in the first wave
    ],
)
def test_graph_matches_the_direct_loop(description: str, floors: int) -> None:
    direct = generate_building(description, floors=floors, seed=3)
    seen: list[tuple[str, int, int]] = []
    graphed = run_building_graph(
        OfflinePlanner(), description, Constraints(floors=floors), seed=3, solver=SOLVER,
        progress=lambda m, d, t: seen.append((m, d, t)),
    )
    assert _plain(graphed) == _plain(direct)
    assert seen[-1] == ("checks", floors, floors)
    if direct.program.load_bearing_walls:
        assert any(f.copy_of is not None for f in direct.floors) or any(
            f.footprint.fixed_walls for f in direct.floors
        )
