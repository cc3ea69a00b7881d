"""``evaluate_floorplans``: run the solver on T2D plans under the MA protocol and score it.

Each plan is solved from what :func:`mansion.eval.t2d.protocol_inputs` exposes (free mask,
room types, seeds, target areas, adjacency), rasterised back to the 64×64 frame and compared
with ``label64`` class by class (:func:`mansion.eval.iou.plan_iou`). A plan the solver cannot
lay out is a failure and scores 0, as in the paper.
"""

from __future__ import annotations

import multiprocessing
import os
import time
from collections.abc import Callable, Sequence
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

from pydantic import BaseModel, Field

from mansion._io import atomic_write_text
from mansion.exceptions import InvalidInputError, MansionError, PlannerError
from mansion.floorplan import EnergyWeights, FixedSeedPlanner, SolverSettings, solve_floor
from mansion.eval.iou import plan_iou
from mansion.eval.t2d import (
    CELL_SIZE, GRID, T2DPlan, iter_plans, plan_ids, plans_folder, protocol_inputs, solver_to_mask,
)

if TYPE_CHECKING:
    from mansion.agents.llm import LLMClient

__all__ = ["EvalReport", "PlanResult", "evaluate_floorplans", "solve_plan", "write_gallery"]

Mode = Literal["hierarchical", "flat"]
#: Where the seeds come from: the protocol's ground-truth centroids (MA), or the plan's description
#: (the paper's end-to-end setting) read by Claude or, offline, by :mod:`mansion.planning.spatial_language`.
SeedSource = Literal["ground_truth", "anthropic", "text"]


class PlanResult(BaseModel):
    """The score of one plan (percentages) and how the solver got there."""

    id: str
    micro: float
    macro: float
    failed: bool
    error: str | None = None
    fallback: bool = False
    backtracks: int = 0
    rooms: int
    seconds: float
    #: The seeds the solver used when they did not come from the ground truth (solver frame).
    seeds: dict[str, tuple[float, float]] | None = None
    #: No seed set read from the text could be laid out: the solver's own heuristic seeded it.
    heuristic_seeds: bool = False


class EvalReport(BaseModel):
    """Scores over a set of plans, as ``--json`` writes them (IoUs in percent)."""

    micro: float
    macro: float
    plans: int
    failures: int
    fallbacks: int = Field(description="Plans where the Monte Carlo fallback won a round.")
    seconds: float
    mode: Mode
    seeds: SeedSource = "ground_truth"
    rng_seed: int = 0
    weights: EnergyWeights
    settings: SolverSettings
    per_plan: list[PlanResult]

    def save(self, path: str | os.PathLike[str]) -> Path:
        return atomic_write_text(path, self.model_dump_json(indent=2) + "\n")

    def subset(self, keep: Callable[[str], bool]) -> tuple[float, float, int]:
        """Micro, macro and plan count over the plans whose id passes ``keep``."""
        chosen = [p for p in self.per_plan if keep(p.id)]
        if not chosen:
            return (0.0, 0.0, 0)
        n = len(chosen)
        return (sum(p.micro for p in chosen) / n, sum(p.macro for p in chosen) / n, n)


def solve_plan(
    plan: T2DPlan,
    *,
    mode: Mode = "hierarchical",
    weights: EnergyWeights | None = None,
    settings: SolverSettings | None = None,
    rng_seed: int = 0,
    seeds: dict[str, tuple[float, float]] | None = None,
    heuristic: bool = False,
) -> Any:
    """Solve one plan under the protocol; returns the predicted 64×64 class map (row 0 = top)
    and the layout. ``seeds`` (node id → solver-frame point) replace the ground-truth centroids;
    ``heuristic=True`` uses neither (the solver's own offline seed heuristic).
    Raises :class:`MansionError` when the solver fails."""
    inputs = protocol_inputs(plan)
    layout = solve_floor(
        inputs.graph,
        inputs.footprint,
        seed_planner=None if heuristic else FixedSeedPlanner(inputs.seeds if seeds is None else seeds),
        weights=weights,
        settings=settings,
        cell_size=CELL_SIZE,
        # one cell: the data's walls between neighbours are often only a few cells long
        min_contact=CELL_SIZE,
        hierarchical=mode == "hierarchical",
        rng_seed=rng_seed,
    )
    return solver_to_mask(layout.grid, inputs.classes), layout


#: Random seeds of the solver the heuristic fallback of ``seeds="text"`` tries in turn (the
#: plans that reach it are the ones no seed set read from the text can be laid out for).
HEURISTIC_TRIES = 8


def _heuristic_solve(plan: T2DPlan, *, rng_seed: int, **kw: Any) -> Any:
    """:func:`solve_plan` with the solver's own seed heuristic, under up to
    :data:`HEURISTIC_TRIES` random seeds; the last failure is raised when none lays it out."""
    error: MansionError | None = None
    for k in range(HEURISTIC_TRIES):
        try:
            return solve_plan(plan, rng_seed=rng_seed + k, heuristic=True, **kw)
        except MansionError as exc:
            error = exc
    assert error is not None
    raise error


class FromText(BaseModel):
    """A job's seeds are to be read from this description in the worker (``seeds="text"``)."""

    description: str


Job = tuple[str, str, Mode, EnergyWeights, SolverSettings, int, "dict[str, tuple[float, float]] | str | FromText | None"]


def _score_one(job: Job) -> tuple[PlanResult, Any]:
    pid, path, mode, weights, settings, rng_seed, seeds = job
    t0 = time.perf_counter()
    plan = T2DPlan.load(path)
    try:
        if isinstance(seeds, str):  # the seed planner failed on this plan: a failure, scored 0
            raise MansionError(seeds)
        if isinstance(seeds, FromText):
            from mansion.eval.text_placement import solve_from_text, text_energy, text_settings

            seeds, pred, layout = solve_from_text(
                plan, seeds.description,
                lambda s: solve_plan(plan, mode=mode, weights=weights, settings=settings, rng_seed=rng_seed, seeds=s),
                lambda: _heuristic_solve(plan, mode=mode, weights=weights, settings=settings, rng_seed=rng_seed),
                # the solves under the solver's other random seeds, each kind of
                # text_placement.SOLVE_KINDS in turn (the shaped energy, the longest-side growth)
                lambda s, k: solve_plan(
                    plan, mode=mode, weights=text_energy(k, weights), settings=text_settings(k, settings),
                    rng_seed=rng_seed + k, seeds=s,
                ),
            )
            heuristic = seeds is None
        else:
            heuristic = False
            pred, layout = solve_plan(
                plan, mode=mode, weights=weights, settings=settings, rng_seed=rng_seed, seeds=seeds
            )
    except MansionError as exc:
        return (
            PlanResult(
                id=pid, micro=0.0, macro=0.0, failed=True, error=str(exc), rooms=len(plan.rooms),
                seconds=time.perf_counter() - t0,
            ),
            None,
        )
    score = plan_iou(pred, plan.label_array())
    result = PlanResult(
        id=pid,
        micro=100.0 * score.micro,
        macro=100.0 * score.macro,
        failed=False,
        fallback=layout.diagnostics.fallback_used,
        backtracks=layout.diagnostics.backtracks,
        rooms=len(plan.rooms),
        seconds=time.perf_counter() - t0,
        seeds=seeds,
        heuristic_seeds=heuristic,
    )
    return result, pred


def evaluate_floorplans(
    data: str | os.PathLike[str],
    *,
    mode: Mode = "hierarchical",
    limit: int | None = None,
    ids: Sequence[str] | None = None,
    weights: EnergyWeights | None = None,
    settings: SolverSettings | None = None,
    rng_seed: int = 0,
    workers: int | None = None,
    progress: Callable[[int, int], None] | None = None,
    seeds: SeedSource = "ground_truth",
    client: LLMClient | None = None,
) -> EvalReport:
    """Solve and score the plans of ``data`` (``DIR/plans/<id>.json``).

    ``ids`` picks plans (default: all, in id order), ``limit`` keeps the first N of them.
    ``workers`` processes solve plans side by side (default: the machine's cores); the result does
    not depend on it. ``progress(done, total)`` is called after each plan.
    ``seeds="anthropic"`` has Claude place the seeds from ``DIR/text/<id>.txt`` first (one request
    per plan, through ``client``, default an :class:`LLMClient` from the environment); a plan whose
    seeds cannot be planned counts as a failure. ``seeds="text"`` reads the same files offline
    (:func:`mansion.eval.text_placement.solve_from_text`, in the workers) and, unless ``weights``
    are given, solves under :data:`mansion.eval.text_placement.TEXT_ENERGY`.
    """
    if mode not in ("hierarchical", "flat"):
        raise InvalidInputError(f"mode must be 'hierarchical' or 'flat', got {mode!r}")
    if limit is not None and limit < 1:
        raise InvalidInputError(f"limit must be >= 1, got {limit}")
    if weights is not None:
        w = weights
    elif seeds == "text":
        from mansion.eval.text_placement import TEXT_ENERGY

        w = TEXT_ENERGY
    else:
        w = EnergyWeights()
    s = settings if settings is not None else SolverSettings()
    chosen = list(ids) if ids is not None else plan_ids(data)
    if limit is not None:
        chosen = chosen[:limit]
    if not chosen:
        raise InvalidInputError(f"no plans to evaluate in {str(data)!r}")
    folder = plans_folder(data)
    planned: dict[str, dict[str, tuple[float, float]] | str | FromText | None] = dict.fromkeys(chosen)
    if seeds == "anthropic":
        planned.update(_text_seeds(Path(data), folder, chosen, client))
    elif seeds == "text":
        planned.update({pid: FromText(description=_read_text(Path(data), pid)) for pid in chosen})
    elif seeds != "ground_truth":
        raise InvalidInputError(f"seeds must be 'ground_truth', 'anthropic' or 'text', got {seeds!r}")
    jobs: list[Job] = [
        (pid, str(folder / f"{pid}.json"), mode, w, s, rng_seed, planned[pid]) for pid in chosen
    ]
    n_workers = max(1, os.cpu_count() or 1) if workers is None else max(1, workers)

    t0 = time.perf_counter()
    results: list[PlanResult] = []
    if n_workers == 1 or len(jobs) == 1:
        for job in jobs:
            results.append(_score_one(job)[0])
            if progress:
                progress(len(results), len(jobs))
    else:
        # Plans are independent; chunks keep the per-task overhead small. Workers are spawned,
        # not forked: a fork of a process whose rayon pool already runs has no pool threads, and
        # its first parallel solve would wait for them forever.
        context = multiprocessing.get_context("spawn")
        with ProcessPoolExecutor(max_workers=n_workers, mp_context=context) as pool:
            for result, _ in pool.map(_score_one, jobs, chunksize=4):
                results.append(result)
                if progress:
                    progress(len(results), len(jobs))
    seconds = time.perf_counter() - t0
    n = len(results)
    return EvalReport(
        micro=sum(r.micro for r in results) / n,
        macro=sum(r.macro for r in results) / n,
        plans=n,
        failures=sum(r.failed for r in results),
        fallbacks=sum(r.fallback for r in results),
        seconds=seconds,
        mode=mode,
        seeds=seeds,
        rng_seed=rng_seed,
        weights=w,
        settings=s,
        per_plan=results,
    )


def _text_seeds(
    data: Path, folder: Path, ids: list[str], client: LLMClient | None
) -> dict[str, dict[str, tuple[float, float]] | str]:
    """Claude's seeds for each plan, or the error message when it could not give valid ones."""
    from mansion.agents.llm import LLMClient as Client
    from mansion.eval.text_seeds import plan_text_seeds

    llm = client if client is not None else Client()
    out: dict[str, dict[str, tuple[float, float]] | str] = {}
    for pid in ids:
        text_path = data / "text" / f"{pid}.txt"
        try:
            description = text_path.read_text(encoding="utf-8")
        except OSError as exc:
            raise InvalidInputError(f"no description for plan {pid}: {text_path} ({exc.strerror})") from exc
        try:
            out[pid] = plan_text_seeds(llm, T2DPlan.load(folder / f"{pid}.json"), description)
        except PlannerError as exc:
            out[pid] = f"seed planning failed: {exc}"
    return out


def _read_text(data: Path, pid: str) -> str:
    text_path = data / "text" / f"{pid}.txt"
    try:
        return text_path.read_text(encoding="utf-8")
    except OSError as exc:
        raise InvalidInputError(f"no description for plan {pid}: {text_path} ({exc.strerror})") from exc


def write_gallery(
    data: str | os.PathLike[str],
    report: EvalReport,
    out: str | os.PathLike[str],
    *,
    count: int = 5,
) -> list[Path]:
    """PNG comparisons of the ``count`` best and worst plans of a report (re-solved: the solver
    is deterministic, so they are the very layouts that were scored)."""
    from mansion.eval.gallery import plot_comparison

    ranked = sorted(report.per_plan, key=lambda r: (r.micro, r.id))
    worst = ranked[:count]
    best = [r for r in reversed(ranked[-count:]) if r not in worst]
    written: list[Path] = []
    for tag, group in (("best", best), ("worst", worst)):
        for rank, r in enumerate(group, 1):
            _, plan = next(iter_plans(data, [r.id]))
            if r.failed:
                import numpy as np

                pred = np.zeros((GRID, GRID), dtype=np.int32)
            else:
                pred, _ = solve_plan(
                    plan, mode=report.mode, weights=report.weights, settings=report.settings,
                    rng_seed=report.rng_seed, seeds=r.seeds, heuristic=r.heuristic_seeds,
                )
            title = f"{tag} {rank}: plan {r.id} — micro {r.micro:.1f}, macro {r.macro:.1f}"
            if r.failed:
                title += " (failed)"
            written.append(
                plot_comparison(plan.label_array(), pred, plan.classes, Path(out) / f"{tag}_{rank}_{r.id}.png", title=title)
            )
    return written
