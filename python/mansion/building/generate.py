"""``generate_building``: the paper's global multi-floor generation, up to the floor plans.

ResolveNumericConstraints and PlanBuildingProgram (the planner's ``plan_program``), then floor by
floor GenerateFloorTopology (``plan_topology``) and SolveFloorLayout (:func:`mansion.solve_floor`),
with the load-bearing walls of each floor carried into the footprint of the next. Copies repeat
their original's graph and layout. The finished building is checked
(:func:`~mansion.building.checks.check_building`) before it is returned.

A floor whose solve fails is retried with other solver seeds, then with its ``adjacent`` edges
dropped, then (only for carried walls) without the carried walls; each relaxation is recorded on
the floor. When every attempt fails, :class:`InfeasibleLayoutError` names the floor.
"""

from __future__ import annotations

import hashlib
import os
import random
from collections.abc import Callable
from typing import Any

from mansion.building.checks import check_building
from mansion.building.load_bearing import (
    SkeletonSeedPlanner,
    carry_walls,
    first_round_groups,
    first_round_regions,
    first_round_walls,
    retarget_first_round,
)
from mansion.exceptions import InfeasibleLayoutError, InvalidInputError
from mansion.floorplan import SeedPlanner, solve_floor
from mansion.models import Core, FloorLayout, Footprint, RoomGraph
from mansion.models.building import Building, Floor, FloorCopy, RoomCard
from mansion.planning.planner import BuildingPlanner, Constraints, get_planner

__all__ = ["ATTEMPTS", "generate_building"]

#: Solver attempts per floor: two plain seeds, then without adjacent edges, then without walls.
ATTEMPTS = 4

Progress = Callable[[str, int, int], None]


def derived_seed(seed: int, *parts: object) -> int:
    """A u64 seed for one purpose, stable across Python versions and runs (unlike hash())."""
    text = ":".join(str(p) for p in (seed, *parts)).encode()
    return int.from_bytes(hashlib.blake2b(text, digest_size=8).digest(), "little")


def _footprint_outline(footprint: Footprint | str | os.PathLike[str] | None) -> Any:
    if footprint is None:
        return None
    fp = footprint if isinstance(footprint, Footprint) else Footprint.load(footprint)
    return ([tuple(p) for p in fp.polygon], [[tuple(p) for p in h] for h in fp.holes])


def _room_cards(graph: RoomGraph, notes: dict[str, str]) -> list[RoomCard]:
    return [
        RoomCard(
            id=n.id, room_type=n.room_type, floor_material=n.floor_material or "",
            wall_material=n.wall_material or "", open_relation=n.open_relation,
            notes=notes.get(n.id, ""),
        )
        for n in graph.nodes
    ]


def _without_adjacent(graph: RoomGraph) -> RoomGraph:
    return RoomGraph(nodes=graph.nodes, edges=[e for e in graph.edges if e.kind == "access"])


def _solve(
    index: int,
    graph: RoomGraph,
    footprint: Footprint,
    planner: SeedPlanner | None,
    seed: int,
    solver: dict[str, Any],
) -> tuple[FloorLayout, RoomGraph, Footprint, int, int, list[str]]:
    errors = []
    for attempt in range(ATTEMPTS):
        relax: list[str] = []
        g, fp, sp = graph, footprint, planner
        if attempt >= 2 and any(e.kind == "adjacent" for e in graph.edges):
            g = _without_adjacent(g)
            relax.append("adjacent edges dropped")
        if attempt >= 3 and footprint.fixed_walls:
            fp = footprint.model_copy(update={"fixed_walls": []})
            sp = None
            relax.append("carried walls dropped")
        rng_seed = derived_seed(seed, "floor", index, attempt)
        try:
            layout = solve_floor(g, fp, seed_planner=sp, rng_seed=rng_seed, **solver)
        except InfeasibleLayoutError as exc:
            errors.append(f"attempt {attempt + 1}: {exc}")
            continue
        return layout, g, fp, rng_seed, attempt + 1, relax
    raise InfeasibleLayoutError(
        f"floor {index} could not be laid out in {ATTEMPTS} attempts; " + " | ".join(errors[-2:])
    )


def generate_building(
    description: str,
    *,
    floors: int | None = None,
    area: float | None = None,
    footprint: Footprint | str | os.PathLike[str] | None = None,
    planner: str | BuildingPlanner = "offline",
    seed: int = 0,
    building_type: str | None = None,
    max_floor_area: float = 500.0,
    load_bearing: bool | None = None,
    cell_size: float = 0.5,
    retries: int = 10,
    batch: int = 100,
    min_contact: float = 1.0,
    progress: Progress | None = None,
) -> Building:
    """Generate a checked multi-floor building (plans only) from a plain-language description.

    Args:
        description: the request, e.g. "a four-storey hospital with two elevators".
        floors: number of floors (1–10); None reads it from the description or the type.
        area: gross area per floor in m² (at most ``max_floor_area``); None: from the description
            or the building type.
        footprint: a :class:`Footprint` (or a JSON file of one) whose outline and courtyards every
            floor uses; None: synthesised. Its cores and fixed walls are not used: the planner
            places the cores.
        planner: "offline", "anthropic", or a :class:`BuildingPlanner`.
        seed: the same seed and inputs give the same building.
        building_type: force a type ("hospital", "office", ...) instead of reading it.
        load_bearing: carry first-round walls up as fixed walls; None: the type's default (on
            for apartment blocks and offices).
        cell_size, retries, batch, min_contact: passed to :func:`mansion.solve_floor`.
        progress: called as ``progress(message, done, total)`` as floors are solved.

    Raises:
        InvalidInputError: bad arguments (floors outside 1–10, an area over the cap, ...).
        PlannerError: the planner cannot program this building.
        InfeasibleLayoutError: a floor failed every attempt (the message names it).
        InvalidBuildingError: the result failed a check (a bug, reported rather than written).
    """
    if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
        raise InvalidInputError(f"seed must be an integer >= 0, got {seed!r}")
    if not isinstance(description, str) or not description.strip():
        raise InvalidInputError("the description is empty; say what to build")
    plan = get_planner(planner)
    constraints = Constraints(
        floors=floors, area=area, outline=_footprint_outline(footprint),
        max_floor_area=max_floor_area, building_type=building_type, load_bearing=load_bearing,
    )
    rng = random.Random(derived_seed(seed, "program"))
    program, palette = plan.plan_program(description, constraints, rng)
    total = program.floor_count
    solver = {"cell_size": cell_size, "retries": retries, "batch": batch, "min_contact": min_contact}
    done: list[Floor] = []
    for index in range(total):
        entry = program.floors[index]
        if progress:
            progress(f"floor {index}", index, total)
        if isinstance(entry, FloorCopy):
            source = done[entry.copy_of]
            done.append(source.model_copy(update={"index": index, "copy_of": entry.copy_of}))
            continue
        graph = plan.plan_topology(program, index)
        floor_program = program.floor_program(index)
        fp = Footprint(
            polygon=floor_program.outline, holes=floor_program.holes,
            cores=[Core(id=c.id, type=c.type, x=c.x, y=c.y) for c in program.cores if index in c.floors],
        )
        seed_planner: SeedPlanner | None = None
        if program.load_bearing_walls and index > 0 and done[index - 1].carried_walls:
            below = done[index - 1]
            walls = carry_walls(below.carried_walls, fp)
            if walls:
                fp = fp.model_copy(update={"fixed_walls": walls})
                regions = first_round_regions(below.layout, below.graph)
                ours = {g for g in first_round_groups(graph).values()}
                # Same first round as below: match its areas and seed it in the same places.
                if ours == set(regions):
                    graph = retarget_first_round(graph, {k: a for k, (a, _) in regions.items()})
                    seed_planner = SkeletonSeedPlanner(
                        graph.hub.id, {k: p for k, (_, p) in regions.items()}
                    )
        layout, graph, fp, rng_seed, attempts, relax = _solve(
            index, graph, fp, seed_planner, seed, solver
        )
        notes = {r.id: r.notes for r in floor_program.rooms}
        done.append(
            Floor(
                index=index, graph=graph, footprint=fp, layout=layout,
                room_cards=_room_cards(graph, notes), rng_seed=rng_seed, attempts=attempts,
                relaxations=relax,
                carried_walls=first_round_walls(layout, graph) if program.load_bearing_walls else [],
            )
        )
    if progress:
        progress("checks", total, total)
    building = Building(
        description=description, seed=seed, planner=plan.name, program=program, palette=palette,
        floors=done,
    )
    check_building(building, min_contact=min_contact)
    return building
