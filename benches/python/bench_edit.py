"""Scene editing for a task (issue 11): the paper's example on many generated two-floor offices.

For each seed, "a two-storey office with a staff kitchen on the top floor" is generated (into
DIR once, reused after) and edited offline for ``examples/tasks/snack_and_drink.json``. Prints
how many buildings the task was made executable in, the failed preconditions by reason, the
edits made, the edited floors' `mansion validate` errors (there should be none) and the median
editing time (checks, provisioning, the oracle's walk and saving the variant).

    python benches/python/bench_edit.py --root /tmp/edit-bench --seeds 20
"""

from __future__ import annotations

import argparse
import statistics
import time
from collections import Counter
from pathlib import Path

from mansion.building import generate_building
from mansion.edit import EditSpec, edit_building, load_variant
from mansion.exceptions import MansionError
from mansion.scene import write_scenes
from mansion.scene.validate import validate_path

DESCRIPTION = "a two-storey office with a staff kitchen on the top floor"
SPEC = Path(__file__).resolve().parents[2] / "examples" / "tasks" / "snack_and_drink.json"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--root", type=Path, required=True, help="Folder for the buildings (reused).")
    ap.add_argument("--seeds", type=int, default=20)
    args = ap.parse_args()
    spec = EditSpec.load(SPEC)
    done, seconds, errors = 0, [], 0
    failed: Counter[str] = Counter()
    edits: Counter[str] = Counter()
    for seed in range(args.seeds):
        folder = args.root / f"office-{seed:03d}"
        if not (folder / "scenes" / "manifest.json").is_file():
            try:
                write_scenes(generate_building(DESCRIPTION, floors=2, seed=seed), folder / "scenes")
            except MansionError as exc:
                failed[f"not generated: {str(exc)[:100]}"] += 1
                print(f"seed {seed}: not generated ({exc})")
                continue
        start = time.perf_counter()
        r = edit_building(folder, spec, name="snack-and-drink")
        seconds.append(time.perf_counter() - start)
        if not r.ok:
            why = (r.failed or "").split(": ", 2)  # "precondition not met", the precondition, why
            failed[f"{why[1]}: {why[2].split(' (')[0]}" if len(why) == 3 else r.failed or ""] += 1
            print(f"seed {seed}: {r.failed}")
            continue
        done += 1
        edits.update(e.split(" ")[0] for e in r.edits)
        for p in load_variant(folder, "snack-and-drink").patch:
            errors += sum(q.severity == "error" for q in validate_path(r.variant / "scenes" / p.house))
    print(f"\n{done} / {args.seeds} seeds: the task made executable (the oracle did it)")
    print(f"edits: {dict(edits)}; validate errors on edited floors: {errors}")
    print(f"median edit time {statistics.median(seconds):.2f} s (max {max(seconds):.2f} s)")
    for why, k in failed.most_common():
        print(f"  failed {k:3d}: {why}")


if __name__ == "__main__":
    main()
