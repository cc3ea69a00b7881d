"""End-to-end offline generation benchmark (issue 4).

1. The hundred: seeds 0–99, the seed choosing the building type (all types in turn) and the
   number of floors (1–10, within what the type allows); reports median and total time and every
   failure.
2. A five-floor office, plans only, timed over a few seeds (goal: < 2 s each).

Run after ``pip install .`` (or ``maturin develop --release``):

    python benches/python/bench_generate.py            # both parts
    python benches/python/bench_generate.py --quick    # seeds 0–19 only
    python benches/python/bench_generate.py --widths   # the cost of the width rules (issue 14)

``--widths`` generates every seed twice, back to back, with the generator's width rules and
without any (``min_width=None``: the solver before issue 14), and reports both totals and their
ratio; interleaving keeps the machine's noise out of the ratio.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time

from mansion.building import generate_building
from mansion.building.generate import MIN_CLEAR_WIDTH
from mansion.eval.realism import BENCH_TYPES as TYPES, bench_case
from mansion.exceptions import MansionError

__all__ = ["TYPES", "case", "description"]


def case(seed: int) -> tuple[str, int]:
    """(building type, floors) of benchmark seed ``seed`` (see :func:`bench_case`)."""
    kind, floors, _ = bench_case(seed)
    return kind, floors


def description(kind: str, floors: int) -> str:
    return f"a {floors}-storey {kind.replace('_', ' ')}"


def run_hundred(seeds: range) -> int:
    times, failures = [], []
    for seed in seeds:
        kind, floors = case(seed)
        start = time.perf_counter()
        try:
            b = generate_building(description(kind, floors), building_type=kind, floors=floors, seed=seed)
            rooms = sum(len(f.layout.rooms) for f in b.floors)
            status = f"ok  {rooms:4d} rooms"
        except MansionError as exc:
            failures.append((seed, kind, floors, str(exc)))
            status = f"FAIL {type(exc).__name__}"
        dt = time.perf_counter() - start
        times.append(dt)
        print(f"seed {seed:3d} {kind:17s} {floors:2d} floors  {dt:6.2f} s  {status}", flush=True)
    print(
        f"\n{len(times)} buildings: median {statistics.median(times):.2f} s, "
        f"total {sum(times):.1f} s, max {max(times):.2f} s, failures {len(failures)}"
    )
    for seed, kind, floors, msg in failures:
        print(f"  seed {seed} {kind} {floors} floors: {msg}")
    return len(failures)


def run_widths(seeds: range) -> None:
    """Total time of the seeds with and without width rules, interleaved."""
    totals = {"with": 0.0, "without": 0.0}
    ratios = []
    for seed in seeds:
        kind, floors = case(seed)
        took = {}
        for label, width in (("without", None), ("with", MIN_CLEAR_WIDTH)):
            start = time.perf_counter()
            try:
                generate_building(
                    description(kind, floors), building_type=kind, floors=floors, seed=seed, min_width=width
                )
            except MansionError as exc:
                print(f"seed {seed} {label} width rules: {type(exc).__name__}: {exc}")
            took[label] = time.perf_counter() - start
            totals[label] += took[label]
        ratios.append(took["with"] / max(took["without"], 1e-9))
        print(f"seed {seed:3d} {kind:17s} {floors:2d} floors  without {took['without']:6.2f} s  "
              f"with {took['with']:6.2f} s", flush=True)
    print(
        f"\n{len(ratios)} buildings: without width rules {totals['without']:.1f} s, with "
        f"{totals['with']:.1f} s (total ratio {totals['with'] / totals['without']:.2f}x, "
        f"median per building {statistics.median(ratios):.2f}x)"
    )


def run_office() -> None:
    times = []
    for seed in range(5):
        start = time.perf_counter()
        generate_building("a five-storey office", floors=5, seed=seed)
        times.append(time.perf_counter() - start)
    print(
        f"five-floor office (plans only), seeds 0–4: median {statistics.median(times):.2f} s, "
        f"max {max(times):.2f} s (goal < 2 s)"
    )


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="seeds 0-19 only")
    parser.add_argument("--widths", action="store_true", help="time with and without width rules")
    args = parser.parse_args()
    if args.widths:
        run_widths(range(20) if args.quick else range(100))
        return 0
    failures = run_hundred(range(20) if args.quick else range(100))
    run_office()
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
