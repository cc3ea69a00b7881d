"""Scenes for the offline planner's hundred (issue 5): every building of benchmark seeds 0–99
(the same cases as ``bench_generate.py``) is generated, its scenes written, and the whole
building validated (every floor's house JSON and the cores across floors). Prints every problem
and exits non-zero if any building fails.

    python benches/python/bench_scenes.py             # seeds 0–99
    python benches/python/bench_scenes.py --seeds 0 20
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_generate import case, description  # noqa: E402

from mansion.building import generate_building  # noqa: E402
from mansion.exceptions import MansionError  # noqa: E402
from mansion.scene import validate_path, write_scenes  # noqa: E402


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--seeds", nargs=2, type=int, default=(0, 100), metavar=("FIRST", "END"))
    args = ap.parse_args()
    failed, floors, scene_times = [], 0, []
    with tempfile.TemporaryDirectory() as tmp:
        for seed in range(*args.seeds):
            kind, n = case(seed)
            try:
                b = generate_building(description(kind, n), building_type=kind, floors=n, seed=seed)
                start = time.perf_counter()
                manifest = write_scenes(b, Path(tmp) / str(seed))
                problems = validate_path(manifest)
                scene_times.append(time.perf_counter() - start)
            except MansionError as exc:
                failed.append(seed)
                print(f"seed {seed:3d} {kind:17s} {n:2d} floors  FAIL {type(exc).__name__}: {exc}")
                continue
            floors += len(b.floors)
            status = "ok" if not problems else f"{len(problems)} problems"
            print(f"seed {seed:3d} {kind:17s} {n:2d} floors  scenes+validate {scene_times[-1]:5.2f} s  {status}", flush=True)
            for p in problems[:10]:
                print(f"    {p}")
            if problems:
                failed.append(seed)
    total = args.seeds[1] - args.seeds[0]
    print(
        f"\n{total - len(failed)}/{total} buildings valid ({floors} floors); scenes + validation "
        f"median {statistics.median(scene_times):.2f} s, max {max(scene_times):.2f} s per building"
    )
    if failed:
        print(f"failing seeds: {failed}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
