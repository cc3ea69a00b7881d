"""The paper's global multi-floor generation as a LangGraph graph.

Nodes, in the paper's order::

    program ──Send per original floor──▶ topology ──▶ floors ◀──────────────┐
                                                        │  Send per ready   │
                                                        ├──────floor──▶ solve
                                                        ▼
                                                      finish (checks)

``program`` asks the planner for the building program (PlanBuildingProgram); ``topology`` runs
once per original floor, all floors at once (GenerateFloorTopology: with an LLM these calls are
independent and slow, so they go out together). ``floors`` is the join: it writes the copies whose
original is solved and sends every floor that can be solved now to ``solve`` (SolveFloorLayout,
with the planner's seed planner in the cutting node). A floor can be solved once its topology is
known and, when load-bearing walls are carried up, once the floor below it is solved; without
carried walls every floor goes out in the first wave. ``finish`` assembles the building and runs
the checks. Each floor's solver seed derives from the building seed and the floor index, so the
result does not depend on the order in which parallel floors finish.
"""

from __future__ import annotations

import random
import threading
from collections.abc import Callable
from typing import Annotated, Any, TypedDict

from mansion.building.steps import (
    copy_floor,
    derived_seed,
    finish_building,
    floor_footprint,
    solve_building_floor,
)
from mansion.exceptions import InvalidBuildingError
from mansion.models.building import Building, BuildingProgram, Floor, FloorCopy, Palette
from mansion.models.graph import RoomGraph
from mansion.planning.planner import BuildingPlanner, Constraints

__all__ = ["build_graph", "run_building_graph"]

Progress = Callable[[str, int, int], None]


def _merge(old: dict[int, Any] | None, new: dict[int, Any] | None) -> dict[int, Any]:
    # Parallel branches each add their own floor index; none overwrites another's.
    return {**(old or {}), **(new or {})}


class BuildingState(TypedDict, total=False):
    program: BuildingProgram
    palette: Palette
    graphs: Annotated[dict[int, RoomGraph], _merge]
    floors: Annotated[dict[int, Floor], _merge]
    building: Building


class FloorTask(TypedDict):
    """What a fanned-out node gets through ``Send``: one floor, and what it needs to know."""

    index: int
    program: BuildingProgram
    graph: RoomGraph | None
    below: Floor | None


def build_graph(
    planner: BuildingPlanner,
    description: str,
    constraints: Constraints,
    *,
    seed: int,
    solver: dict[str, Any],
    progress: Progress | None = None,
) -> Any:
    """The compiled graph for one building (the planner and options are bound in the nodes)."""
    from langgraph.graph import END, START, StateGraph
    from langgraph.types import Send

    solved = [0]
    lock = threading.Lock()

    def report(message: str, total: int) -> None:
        if progress is not None:
            with lock:
                progress(message, solved[0], total)

    def program_node(state: BuildingState) -> dict[str, Any]:
        rng = random.Random(derived_seed(seed, "program"))
        program, palette = planner.plan_program(description, constraints, rng)
        report(f"planning {program.floor_count} floors", program.floor_count)
        return {"program": program, "palette": palette, "graphs": {}, "floors": {}}

    def to_topology(state: BuildingState) -> list[Any]:
        program = state["program"]
        return [
            Send("topology", FloorTask(index=i, program=program, graph=None, below=None))
            for i, f in enumerate(program.floors)
            if not isinstance(f, FloorCopy)
        ]

    def topology_node(task: FloorTask) -> dict[str, Any]:
        return {"graphs": {task["index"]: planner.plan_topology(task["program"], task["index"])}}

    def floors_node(state: BuildingState) -> dict[str, Any]:
        done = state.get("floors", {})
        copies = {
            i: copy_floor(done[f.copy_of], i)
            for i, f in enumerate(state["program"].floors)
            if isinstance(f, FloorCopy) and i not in done and f.copy_of in done
        }
        return {"floors": copies}

    def to_solve(state: BuildingState) -> Any:
        program, done, graphs = state["program"], state.get("floors", {}), state["graphs"]
        if len(done) == program.floor_count:
            return "finish"
        sends = []
        for i, f in enumerate(program.floors):
            if i in done or isinstance(f, FloorCopy):
                continue
            below = done.get(i - 1)
            if program.load_bearing_walls and i > 0 and below is None:
                continue
            sends.append(Send("solve", FloorTask(index=i, program=program, graph=graphs[i], below=below)))
        if not sends:  # a copy of a floor that is never solved: the program validator forbids it
            missing = [i for i in range(program.floor_count) if i not in done]
            raise InvalidBuildingError(f"floors {missing} can never be solved (their originals are missing)")
        return sends

    def solve_node(task: FloorTask) -> dict[str, Any]:
        program, index, graph = task["program"], task["index"], task["graph"]
        assert graph is not None
        report(f"floor {index}", program.floor_count)
        make = getattr(planner, "seed_planner", None)
        seed_planner = make(program, index, graph, floor_footprint(program, index)) if make else None
        floor = solve_building_floor(program, index, graph, task["below"], seed, solver, seed_planner)
        with lock:
            solved[0] += 1
        return {"floors": {index: floor}}

    def finish_node(state: BuildingState) -> dict[str, Any]:
        program = state["program"]
        report("checks", program.floor_count)
        floors = [state["floors"][i] for i in range(program.floor_count)]
        building = finish_building(
            description, seed, planner.name, program, state["palette"], floors,
            solver["min_contact"],
        )
        return {"building": building}

    g = StateGraph(BuildingState)
    g.add_node("program", program_node)
    # The fanned-out nodes take a FloorTask (the Send payload), not the graph state; LangGraph
    # accepts that at run time but its stubs only know state-typed nodes.
    g.add_node("topology", topology_node)  # type: ignore[arg-type]
    g.add_node("floors", floors_node)
    g.add_node("solve", solve_node)  # type: ignore[arg-type]
    g.add_node("finish", finish_node)
    g.add_edge(START, "program")
    g.add_conditional_edges("program", to_topology, ["topology"])
    g.add_edge("topology", "floors")
    g.add_conditional_edges("floors", to_solve, ["solve", "finish"])
    g.add_edge("solve", "floors")
    g.add_edge("finish", END)
    return g.compile()


def run_building_graph(
    planner: BuildingPlanner,
    description: str,
    constraints: Constraints,
    *,
    seed: int,
    solver: dict[str, Any],
    progress: Progress | None = None,
    max_concurrency: int = 4,
) -> Building:
    """Generate a checked building through the graph (see the module doc)."""
    graph = build_graph(planner, description, constraints, seed=seed, solver=solver, progress=progress)
    # Up to two supersteps per floor (solve, join) plus program, topology, join and finish.
    limit = 4 * (constraints.floors or 10) + 10
    state = graph.invoke({}, config={"recursion_limit": limit, "max_concurrency": max_concurrency})
    building = state["building"]
    assert isinstance(building, Building)
    return building
