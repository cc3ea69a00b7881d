"""``solve_floor``: one floor's room graph and footprint in, a solved :class:`FloorLayout` out."""

from __future__ import annotations

import json
import math
import numbers
from collections.abc import Mapping
from typing import Any

from pydantic import ValidationError

from mansion._native import native
from mansion.exceptions import InvalidInputError, MansionError
from mansion.models.seeds import PlanFunction, SeedPlanner, planner_callback
from mansion.floorplan.weights import EnergyWeights, SolverSettings
from mansion.models import FloorLayout, Footprint, RoomGraph
from mansion.models._validation import describe_validation_error, validate_input

__all__ = ["build_options", "solve_floor"]

_U64_MAX = 2**64 - 1


def _int_arg(name: str, value: object, minimum: int, maximum: int | None = None) -> int:
    # bool is an int subclass; `retries=True` is a mistake, not 1.
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise InvalidInputError(f"{name} must be an integer, got {value!r}")
    v = int(value)
    if v < minimum or (maximum is not None and v > maximum):
        bound = f">= {minimum}" if maximum is None else f"in [{minimum}, {maximum}]"
        raise InvalidInputError(f"{name} must be {bound}, got {v}")
    return v


def _float_arg(name: str, value: object, *, positive: bool) -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise InvalidInputError(f"{name} must be a number, got {value!r}")
    v = float(value)
    if not math.isfinite(v) or (v <= 0 if positive else v < 0):
        raise InvalidInputError(f"{name} must be a finite number {'> 0' if positive else '>= 0'}, got {v!r}")
    return v


def build_options(
    *,
    cell_size: float = 0.5,
    retries: int = 10,
    batch: int = 100,
    min_contact: float = 1.0,
    hierarchical: bool = True,
    rng_seed: int = 0,
    weights: EnergyWeights | Mapping[str, Any] | None = None,
    settings: SolverSettings | Mapping[str, Any] | None = None,
) -> dict[str, Any]:
    """Check the solver arguments and return the options object the Rust solver reads.

    Every problem is an :class:`InvalidInputError` naming the argument.
    """
    w = EnergyWeights() if weights is None else validate_input(EnergyWeights, weights, "energy weights")
    s = SolverSettings() if settings is None else validate_input(SolverSettings, settings, "solver settings")
    if not isinstance(hierarchical, bool):
        raise InvalidInputError(f"hierarchical must be True or False, got {hierarchical!r}")
    return {
        "cell_size": _float_arg("cell_size", cell_size, positive=True),
        "retries": _int_arg("retries", retries, 1),
        "batch": _int_arg("batch", batch, 1),
        "min_contact": _float_arg("min_contact", min_contact, positive=False),
        "hierarchical": hierarchical,
        "rng_seed": _int_arg("rng_seed", rng_seed, 0, _U64_MAX),
        "weights": w.model_dump(mode="json"),
        **s.model_dump(mode="json"),
    }


def solve_floor(
    graph: RoomGraph | Mapping[str, Any],
    footprint: Footprint | Mapping[str, Any],
    *,
    seed_planner: SeedPlanner | PlanFunction | None = None,
    weights: EnergyWeights | Mapping[str, Any] | None = None,
    cell_size: float = 0.5,
    retries: int = 10,
    batch: int = 100,
    min_contact: float = 1.0,
    hierarchical: bool = True,
    rng_seed: int = 0,
    settings: SolverSettings | Mapping[str, Any] | None = None,
) -> FloorLayout:
    """Lay out one floor: partition the footprint's free region into the rooms of ``graph``.

    Args:
        graph: the room graph (a :class:`RoomGraph` or a dict of that shape).
        footprint: the outline, holes and cores (a :class:`Footprint` or a dict).
        seed_planner: proposes the seeds of each cut round (an object with
            ``plan(SeedRequest) -> SeedPlan`` or such a function); None uses the built-in offline
            heuristic of the Rust core.
        weights: energy weights; None uses the authors' released values.
        cell_size: grid cell size in metres.
        retries: adaptive-sampling retries per round before the Monte Carlo fallback.
        batch: candidates grown per retry.
        min_contact: shortest shared wall, in metres, that counts as a realised adjacency.
        hierarchical: cut round by round from the hub (True), or place every room in one round.
        rng_seed: seed of every random choice; same inputs and seed give the same layout.
        settings: sampling settings (radius growth, gammas, fallback size, minimum width).

    Returns:
        The solved :class:`FloorLayout`, with the cores among its rooms.

    Raises:
        InvalidInputError: a malformed graph, footprint or argument. Pydantic validation errors
            of the inputs are converted to this, with one readable line per problem.
        InfeasibleLayoutError: no retry and no fallback produced a layout that satisfies the graph.
        PlannerError: the seed planner raised or returned an unusable plan.
    """
    g = validate_input(RoomGraph, graph, "room graph")
    fp = validate_input(Footprint, footprint, "footprint")
    options = build_options(
        cell_size=cell_size,
        retries=retries,
        batch=batch,
        min_contact=min_contact,
        hierarchical=hierarchical,
        rng_seed=rng_seed,
        weights=weights,
        settings=settings,
    )
    callback = None if seed_planner is None else planner_callback(seed_planner)

    result = native().solve_floor(
        g.model_dump_json(), fp.model_dump_json(), json.dumps(options), callback
    )
    try:
        return FloorLayout.model_validate_json(result)
    except ValidationError as exc:
        # The solver and these models disagree on the result's shape: a bug, not bad input.
        raise MansionError(
            f"the solver returned a layout these models cannot read: {describe_validation_error(exc)}"
        ) from exc
