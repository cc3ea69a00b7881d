"""What the realism passes cost (issue 14's bound: generation no more than 1.5× slower): the
offline buildings of :func:`mansion.eval.realism.bench_case` generated with every pass on (the
solver's repair and rebalance, then the floor's mends: recut, merges, widths, dissolve, and
``--relayouts``; the banks layout of hotels', schools' and hospitals' floors) and with every pass off (the same solver
settings without repair and rebalance, which also leaves the mends and the second layouts out, and
every floor to the cut rounds), building by building in turn, the order
alternating so neither side always runs on a warm cache.

Process time, so other work on the machine counts less than in wall time; run it with
``RAYON_NUM_THREADS=1`` so the solver's candidates are not spread over cores the clock does not
see the same way. The ratio of the totals is the figure the issue bounds; the median of the
per-building ratios is printed beside it, as a building's share of hard floors varies.

    RAYON_NUM_THREADS=1 python benches/python/bench_passes.py                  # seeds 0-99
    RAYON_NUM_THREADS=1 python benches/python/bench_passes.py --relayouts 1 --seeds 0 20
"""

from __future__ import annotations

import argparse
import statistics
import time
from collections.abc import Callable
from typing import Any

import mansion.building.steps as steps
from mansion.building import generate_building
from mansion.building.generate import RELAYOUTS
from mansion.eval.realism import bench_case


def passes_off(cell_size: float, *args: Any, **kwargs: Any) -> Any:
    """:func:`steps.floor_settings` without the repair and the rebalance: with ``repair`` off the
    floor's steps run neither the mends nor the second layouts."""
    return ON(cell_size, *args, **kwargs).model_copy(update={"repair": False, "rebalance": False})


ON: Callable[..., Any] = steps.floor_settings
BANKS = steps.BANKS


def timed(seed: int, on: bool, relayouts: int) -> float:
    """Process seconds to generate building ``seed`` with every pass on or off."""
    kind, floors, text = bench_case(seed)
    steps.floor_settings = ON if on else passes_off
    steps.BANKS = on
    try:
        start = time.process_time()
        generate_building(text, building_type=kind, floors=floors, seed=seed, relayouts=relayouts if on else 0)
        return time.process_time() - start
    finally:
        steps.floor_settings = ON
        steps.BANKS = BANKS


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seeds", type=int, nargs=2, default=(0, 100), metavar=("FIRST", "END"))
    ap.add_argument(
        "--relayouts", type=int, default=RELAYOUTS, help="the on side's relayouts (generate --relayouts; default: the default's)",
    )
    ap.add_argument("--per-building", action="store_true", help="print each building's two times")
    args = ap.parse_args()
    total = {True: 0.0, False: 0.0}
    ratios = []
    for seed in range(*args.seeds):
        took = {}
        for on in ((True, False) if seed % 2 else (False, True)):
            took[on] = timed(seed, on, args.relayouts)
            total[on] += took[on]
        ratios.append(took[True] / took[False])
        if args.per_building:
            print(seed, bench_case(seed)[0], f"off {took[False]:.2f} s", f"on {took[True]:.2f} s", flush=True)
    print(
        f"passes off {total[False]:.1f} s, on {total[True]:.1f} s: {total[True] / total[False]:.3f}x "
        f"(median per building {statistics.median(ratios):.3f}x)"
    )


if __name__ == "__main__":
    main()
