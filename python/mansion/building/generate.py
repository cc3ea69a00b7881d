"""``generate_building``: the paper's global multi-floor generation, up to the floor plans.

ResolveNumericConstraints and PlanBuildingProgram (the planner's ``plan_program``), then floor by
floor GenerateFloorTopology (``plan_topology``) and SolveFloorLayout (:func:`mansion.solve_floor`),
with the load-bearing walls of each floor carried into the footprint of the next. Copies repeat
their original's graph and layout. The finished building is checked
(:func:`~mansion.building.checks.check_building`) before it is returned.

The steps both drivers share (SolveFloorLayout with its retry ladder and width relaxations,
floor copies, the checks) are in :mod:`mansion.building.steps`.

The offline planner answers in milliseconds, so its floors are solved here one after another.
Any other planner (Claude) runs through the LangGraph pipeline of
:mod:`mansion.building.graph`, which uses the same steps with the floors fanned out.
"""

from __future__ import annotations

import dataclasses
import math
import os
import random
from typing import Any

from mansion.building.steps import (
    ATTEMPTS,
    MIN_CLEAR_WIDTH,
    RELAXED_CLEAR_WIDTH,
    Progress,
    copy_floor,
    derived_seed,
    finish_building,
    floor_footprint,
    generated_weights,
    solve_building_floor,
    solver_options,
)
from mansion.exceptions import InfeasibleLayoutError, InvalidInputError, PlannerError
from mansion.floorplan import EnergyWeights
from mansion.models import Footprint
from mansion.models.building import BuildingProgram, Floor, FloorCopy
from mansion.planning.planner import BuildingPlanner, Constraints, OfflinePlanner
from mansion.planning.planners import get_planner

__all__ = [
    "ATTEMPTS",
    "MIN_CLEAR_WIDTH",
    "RELAXED_CLEAR_WIDTH",
    "copy_floor",
    "derived_seed",
    "finish_building",
    "floor_footprint",
    "generate_building",
    "solve_building_floor",
    "solver_options",
    "generated_weights",
    "PROGRAM_ATTEMPTS",
    "RELAYOUTS",
]

#: Programs tried before giving up: the seed's own, then programs relaxed step by step (optional
#: rooms left out, a larger circulation reserve; see ``ProgramOptions.relax``), each from its own
#: seed. A failed floor solve or a program that does not fit its floor moves to the next one.
PROGRAM_ATTEMPTS = 4
#: Relayouts a floor may be given at most (:func:`generate_building`'s ``relayouts``).
MAX_RELAYOUTS = 5
#: Relayouts a floor is given by default: a floor the mends leave with rooms below their minimum
#: area or width is laid out again whole once (:func:`mansion.building.steps.solve_building_floor`).
#: Measured on the offline hundreds (seeds 0-99 / 100-199): rooms below their width 22 / 14 -> 15
#: / 7, below their area 4 / 2 -> 2 / 1, for 1.461 and 1.376 times the time of the passes off in
#: two runs (none: 1.391 and 1.400; ``benches/python/bench_passes.py``); off until the racetracks
#: took the hospitals' ward floors from the solver, when it cost 1.62 times.
RELAYOUTS = 1


def check_relayouts(relayouts: object) -> None:
    """Raise :class:`InvalidInputError` unless ``relayouts`` is an integer from 0 to
    :data:`MAX_RELAYOUTS`."""
    if isinstance(relayouts, bool) or not isinstance(relayouts, int) or not 0 <= relayouts <= MAX_RELAYOUTS:
        raise InvalidInputError(f"relayouts must be an integer from 0 to {MAX_RELAYOUTS}, got {relayouts!r}")


def _footprint_outline(footprint: Footprint | str | os.PathLike[str] | None) -> Any:
    if footprint is None:
        return None
    fp = footprint if isinstance(footprint, Footprint) else Footprint.load(footprint)
    return ([tuple(p) for p in fp.polygon], [[tuple(p) for p in h] for h in fp.holes])


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
    weights: EnergyWeights | None = None,
    min_width: float | None = MIN_CLEAR_WIDTH,
    relayouts: int = RELAYOUTS,
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
        weights: energy weights of every floor's solve; None: :func:`generated_weights` (the
            paper's weights with the aspect term, which keeps rooms from stretching beyond 3 : 1), not
            the solver's T2D-tuned defaults. Those follow seeds closely, which pays when seeds are
            true centroids; here seeds are the planner's guesses and room areas matter more.
            Measured over the offline hundred (seeds 0–99): the paper's weights solve all 100
            buildings, the T2D-tuned ones fail 2; mean room area error over seeds 0–39 is 17.2 %
            against 19.8 %.
        min_width: the narrowest clear width (m) any room may have, floor-wide; the rooms'
            own widths from the design table (up to :data:`~mansion.planning.topology.MAX_NODE_WIDTH`)
            come on top. None: no width rule at all (the solver as the paper describes it; rooms
            then keep slivers and one-cell necks).
        relayouts: times a floor the mends leave with rooms below their minimum area or width
            is laid out again whole under a seed of its own, keeping the layout with fewer such
            rooms (offline planner; see
            :func:`mansion.building.steps.solve_building_floor`). :data:`RELAYOUTS` (1) by
            default: it cuts the offline hundred's rooms below their width from 22 to 15, for
            1.376-1.461 times the generation time of the realism passes off against 1.391-1.400
            without; 0 for the fastest layout.
        progress: called as ``progress(message, done, total)`` as floors are solved.

    Raises:
        InvalidInputError: bad arguments (floors outside 1–10, an area over the cap, ...).
        PlannerError: the planner cannot program this building.
        InfeasibleLayoutError: a floor failed every attempt (the message names it).
        InvalidBuildingError: the result failed a check (a bug, reported rather than written).
    """
    if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
        raise InvalidInputError(f"seed must be an integer >= 0, got {seed!r}")
    if min_width is not None and (
        isinstance(min_width, bool) or not isinstance(min_width, (int, float))
        or not math.isfinite(min_width) or min_width <= 0
    ):
        raise InvalidInputError(f"min_width must be a positive number of metres or None, got {min_width!r}")
    check_relayouts(relayouts)
    if not isinstance(description, str) or not description.strip():
        raise InvalidInputError("the description is empty; say what to build")
    plan = get_planner(planner)
    constraints = Constraints(
        floors=floors, area=area, outline=_footprint_outline(footprint),
        max_floor_area=max_floor_area, building_type=building_type, load_bearing=load_bearing,
    )
    solver = solver_options(cell_size, retries, batch, min_contact, weights, min_width)
    if not isinstance(plan, OfflinePlanner):
        # LLM planners wait on the network: the LangGraph pipeline fans the floors out. It is
        # imported only here so the offline path never loads langgraph.
        from mansion.building.graph import run_building_graph

        return run_building_graph(
            plan, description, constraints, seed=seed, solver=solver, progress=progress
        )
    failures: list[str] = []
    for attempt in range(PROGRAM_ATTEMPTS):
        rng = random.Random(
            derived_seed(seed, "program") if attempt == 0 else derived_seed(seed, "program", attempt)
        )
        relaxed = dataclasses.replace(constraints, relax=min(attempt, 2))
        try:
            program, palette = plan.plan_program(description, relaxed, rng)
        except PlannerError as exc:
            if attempt == PROGRAM_ATTEMPTS - 1:
                raise
            failures.append(f"program {attempt + 1}: {exc}")
            continue
        try:
            done = _solve_floors(plan, program, seed, solver, progress, description,
                                 drop_widths=attempt == PROGRAM_ATTEMPTS - 1, relayouts=relayouts)
        except (InfeasibleLayoutError, InvalidInputError) as exc:
            # InvalidInputError here is the solver refusing a program larger than its floor.
            if attempt == PROGRAM_ATTEMPTS - 1:
                raise type(exc)(
                    f"no program could be laid out after {PROGRAM_ATTEMPTS} attempts; last: {exc}"
                ) from None
            failures.append(f"program {attempt + 1}: {exc}")
            continue
        if failures:
            note = f"program re-planned {len(failures)} time(s), relaxed to level {min(attempt, 2)}: " + " | ".join(failures)
            done[0] = done[0].model_copy(update={"relaxations": [*done[0].relaxations, note]})
        if progress:
            progress("checks", program.floor_count, program.floor_count)
        return finish_building(description, seed, plan.name, program, palette, done, min_contact)
    raise AssertionError("unreachable")


def _solve_floors(
    plan: BuildingPlanner, program: BuildingProgram, seed: int, solver: dict[str, Any], progress: Progress | None,
    description: str, *, drop_widths: bool = True, relayouts: int = RELAYOUTS,
) -> list[Floor]:
    """Every floor of ``program``, solved one after another (copies repeat their original);
    ``description``'s position words seed the rounds (:mod:`mansion.floorplan.text_seeds`);
    ``drop_widths`` as for :func:`solve_building_floor`."""
    total = program.floor_count
    done: list[Floor] = []
    for index in range(total):
        entry = program.floors[index]
        if progress:
            progress(f"floor {index}", index, total)
        if isinstance(entry, FloorCopy):
            done.append(copy_floor(done[entry.copy_of], index))
            continue
        graph = plan.plan_topology(program, index)
        below = done[index - 1] if index > 0 else None
        done.append(solve_building_floor(program, index, graph, below, seed, solver, description=description,
                                         drop_widths=drop_widths, relayouts=relayouts))
    return done
