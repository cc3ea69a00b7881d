"""Random search of the energy weights on the simplex, on T2D plans with even ids.

The solver keeps the candidate of lowest energy, and the energy is linear in the weights, so only
their ratios matter: the search samples the simplex (Dirichlet(1, …, 1) over the five weights)
and scales every sample to the same total. A second, local phase then perturbs the best weights
found so far (log-normal noise on each weight, narrowing from σ = 0.5 to 0.1, back onto the
simplex). The objective is the mean of micro- and macro-IoU on the even plan ids; odd ids and
the whole set are reported for the winner only, so they stay unseen while searching.
"""

from __future__ import annotations

import math
import os
import random
from collections.abc import Callable
from pathlib import Path

from pydantic import BaseModel

from mansion._io import atomic_write_text
from mansion.eval.floorplan import EvalReport, Mode, evaluate_floorplans
from mansion.eval.t2d import plan_ids
from mansion.exceptions import InvalidInputError
from mansion.floorplan import EnergyWeights, SolverSettings

__all__ = ["TuneReport", "TuneTrial", "perturb", "sample_simplex", "tune_weights"]

_FIELDS = ("ratio", "seed", "drift", "wall", "corner")
#: Every sample is scaled to this total (the package defaults' order of magnitude).
WEIGHT_TOTAL = 20.0


class TuneTrial(BaseModel):
    weights: EnergyWeights
    micro: float
    macro: float
    failures: int

    @property
    def objective(self) -> float:
        return (self.micro + self.macro) / 2.0


class TuneReport(BaseModel):
    """The search: every trial on the even ids, and the winner on odd ids and on all plans."""

    mode: Mode
    samples: int
    refine: int
    seed: int
    trials: list[TuneTrial]
    best: EnergyWeights
    even: tuple[float, float, int]
    odd: tuple[float, float, int]
    all: tuple[float, float, int]
    failures: int

    def save(self, path: str | os.PathLike[str]) -> Path:
        return atomic_write_text(path, self.model_dump_json(indent=2) + "\n")


def sample_simplex(rng: random.Random, total: float = WEIGHT_TOTAL) -> EnergyWeights:
    """A uniform sample of the weight simplex, scaled to ``total``."""
    draws = [rng.expovariate(1.0) for _ in _FIELDS]
    s = sum(draws)
    return EnergyWeights(**{f: round(total * d / s, 4) for f, d in zip(_FIELDS, draws)})


def perturb(rng: random.Random, w: EnergyWeights, sigma: float, total: float = WEIGHT_TOTAL) -> EnergyWeights:
    """``w`` with each weight scaled by exp(N(0, σ)), put back on the simplex of ``total``.

    A weight of 0 stays 0 only if the noise cannot lift it; a small floor lets the local search
    switch a term back on."""
    raw = [max(getattr(w, f), 0.02 * total) * math.exp(rng.gauss(0.0, sigma)) for f in _FIELDS]
    s = sum(raw)
    return EnergyWeights(**{f: round(total * r / s, 4) for f, r in zip(_FIELDS, raw)})


def _is_even(pid: str) -> bool:
    return pid.isdigit() and int(pid) % 2 == 0


def tune_weights(
    data: str | os.PathLike[str],
    *,
    samples: int = 40,
    refine: int = 20,
    seed: int = 0,
    mode: Mode = "hierarchical",
    settings: SolverSettings | None = None,
    start: EnergyWeights | None = None,
    workers: int | None = None,
    on_trial: Callable[[int, TuneTrial, TuneTrial], None] | None = None,
) -> TuneReport:
    """Search ``samples`` random weight vectors (plus ``start``, default the package defaults, as
    trial 0), then ``refine`` perturbations of the best so far, on the even plan ids; return the
    best with its scores on odd ids and on all plans.

    ``on_trial(index, trial, best_so_far)`` is called after each trial.
    """
    if samples < 0 or refine < 0:
        raise InvalidInputError(f"samples and refine must be >= 0, got {samples} and {refine}")
    ids = plan_ids(data)
    even = [i for i in ids if _is_even(i)]
    odd = [i for i in ids if not _is_even(i)]
    if not even:
        raise InvalidInputError(f"no plans with even numeric ids in {str(data)!r} to tune on")
    rng = random.Random(seed)
    candidates = [start if start is not None else EnergyWeights()]
    candidates += [sample_simplex(rng) for _ in range(samples)]
    trials: list[TuneTrial] = []
    best: TuneTrial | None = None

    def run(w: EnergyWeights) -> TuneTrial:
        nonlocal best
        r = evaluate_floorplans(data, mode=mode, ids=even, weights=w, settings=settings, workers=workers)
        trial = TuneTrial(weights=w, micro=r.micro, macro=r.macro, failures=r.failures)
        trials.append(trial)
        if best is None or trial.objective > best.objective:
            best = trial
        if on_trial:
            on_trial(len(trials) - 1, trial, best)
        return trial

    for w in candidates:
        run(w)
    for j in range(refine):
        assert best is not None
        sigma = 0.5 - 0.4 * j / max(1, refine - 1)
        run(perturb(rng, best.weights, sigma))
    assert best is not None
    held_out: EvalReport | None = (
        evaluate_floorplans(data, mode=mode, ids=odd, weights=best.weights, settings=settings, workers=workers)
        if odd
        else None
    )
    odd_score = (held_out.micro, held_out.macro, held_out.plans) if held_out else (0.0, 0.0, 0)
    n_even, n_odd = len(even), odd_score[2]
    total = n_even + n_odd
    all_score = (
        (best.micro * n_even + odd_score[0] * n_odd) / total,
        (best.macro * n_even + odd_score[1] * n_odd) / total,
        total,
    )
    return TuneReport(
        mode=mode,
        samples=samples,
        refine=refine,
        seed=seed,
        trials=trials,
        best=best.weights,
        even=(best.micro, best.macro, n_even),
        odd=odd_score,
        all=all_score,
        failures=best.failures + (held_out.failures if held_out else 0),
    )
