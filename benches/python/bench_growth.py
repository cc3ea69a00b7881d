"""Time the Rust growth stage (``mansion._core.grow_candidates``) against the numpy reference.

    python benches/python/bench_growth.py [--batch 100] [--repeat 5] [--json OUT]

The case: a 64×64 grid whose free region is a square with a 20×16 notch cut from its top-right
corner (3,776 cells), cut into 7 rooms whose targets sum to 90 % of the free cells; the other
10 % stays with the region label (the parent). Both implementations grow ``--batch`` candidates
from the same perturbed seeds; the medians over ``--repeat`` runs are reported per candidate,
with the ratio reference ÷ Rust. Both outputs are checked for the same invariants, so the two
timings are of equal work.

Rust runs on rayon's thread pool, sized once per process from ``RAYON_NUM_THREADS``. The
in-process Rust timing uses the environment as given; unless ``RAYON_NUM_THREADS`` is already
set, the script also re-runs itself with ``RAYON_NUM_THREADS=1`` in a child process to get the
single-thread figure (the reference is single-threaded), so one run reports both.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from reference_growth import grow_candidates_reference, label_components  # noqa: E402

REFERENCE_BUDGET_S = 60.0  # the reference is timed on fewer candidates if 100 would take longer

# --------------------------------------------------------------------------------------------
# the case
# --------------------------------------------------------------------------------------------

SIZE = 64
NOTCH_W, NOTCH_H = 20, 16
REGION = 0
# (name, share of the free cells, planned seed (x, y) in cell units); shares sum to 0.90
ROOMS = [
    ("living", 0.20, (14.0, 14.0)),
    ("bed 1", 0.15, (14.0, 46.0)),
    ("bed 2", 0.13, (32.0, 53.0)),
    ("kitchen", 0.12, (38.0, 13.0)),
    ("bed 3", 0.12, (55.0, 14.0)),
    ("study", 0.10, (54.0, 36.0)),
    ("bath", 0.08, (34.0, 33.0)),
]
RADIUS = 3.0  # ≈ the solver's r_base + k·a/|Ω| = 2 + 8·0.15 for a mid-sized room
RNG_SEED = 12345


def build_case() -> dict[str, Any]:
    """The benchmark case: labels, region, seeds, targets."""
    labels = np.full((SIZE, SIZE), REGION, dtype=np.int32)
    labels[SIZE - NOTCH_H :, SIZE - NOTCH_W :] = -1  # row 0 is the bottom: the notch is top right
    free = int((labels == REGION).sum())
    shares = np.array([r[1] for r in ROOMS])
    targets = shares * free
    seeds = np.array([r[2] for r in ROOMS], dtype=np.float64) + 0.5  # cell centres
    assert (labels[seeds[:, 1].astype(int), seeds[:, 0].astype(int)] == REGION).all()
    return {
        "labels": labels,
        "region": REGION,
        "seeds": seeds,
        "targets": targets,
        "free": free,
        "names": [r[0] for r in ROOMS],
    }


# --------------------------------------------------------------------------------------------
# invariants
# --------------------------------------------------------------------------------------------


def check(out: np.ndarray, case: dict[str, Any]) -> dict[str, Any]:
    """The invariants both implementations must meet, and their area accuracy."""
    labels, region, targets = case["labels"], case["region"], case["targets"]
    free = labels == region
    first = max(int(labels.max()) + 1, region + 1)
    n = out.shape[0]
    flat = out[:, free]  # (batch, free cells)
    all_assigned = (flat >= 0).all(axis=1)
    outside_kept = (out[:, ~free] == labels[~free]).all(axis=1)
    areas = np.stack([(flat == first + k).sum(axis=1) for k in range(len(targets))], axis=1)
    present = (areas > 0).all(axis=1)
    rel_err = np.abs(areas - targets[None, :]) / targets[None, :]
    one_piece = np.zeros(n, dtype=bool)
    for b in range(n):
        one_piece[b] = all(label_components(np.pad(out[b] == first + k, 1))[1] == 1 for k in range(len(targets)))
    parent_share = (flat == region).sum(axis=1) / free.sum()
    res = {
        "candidates": n,
        "all_free_assigned": float(all_assigned.mean()),
        "outside_untouched": float(outside_kept.mean()),
        "all_rooms_present": float(present.mean()),
        "rooms_in_one_piece": float(one_piece.mean()),
        "mean_rel_area_error": float(rel_err.mean()),
        "max_rel_area_error": float(rel_err.max()),
        "mean_parent_share": float(parent_share.mean()),
    }
    res["ok"] = bool(
        all_assigned.all()
        and outside_kept.all()
        and present.mean() >= 0.8
        and res["mean_rel_area_error"] <= 0.25
    )
    return res


# --------------------------------------------------------------------------------------------
# timing
# --------------------------------------------------------------------------------------------


def _time(fn, repeat: int) -> tuple[list[float], Any]:
    times, out = [], None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return times, out


def time_rust(case: dict[str, Any], batch: int, repeat: int, growth: str) -> tuple[list[float], np.ndarray]:
    from mansion import _core

    def run(n: int = batch) -> np.ndarray:
        return _core.grow_candidates(
            case["labels"], case["region"], case["seeds"], case["targets"], n, RNG_SEED, RADIUS, growth
        )

    run(min(batch, 8))  # warm-up: thread pool, page faults
    return _time(run, repeat)


def time_reference(case: dict[str, Any], batch: int, repeat: int, growth: str) -> tuple[list[float], np.ndarray, int]:
    def run(n: int) -> np.ndarray:
        return grow_candidates_reference(
            case["labels"], case["region"], case["seeds"], case["targets"], n, RNG_SEED, RADIUS, growth
        )

    # a probe on a few candidates (also the warm-up) decides whether the whole batch fits the budget
    probe_n = min(batch, 5)
    t0 = time.perf_counter()
    run(probe_n)
    per = (time.perf_counter() - t0) / probe_n
    n = batch if per * batch <= REFERENCE_BUDGET_S else max(probe_n, int(REFERENCE_BUDGET_S / per))
    times, out = _time(lambda: run(n), repeat)
    return times, out, n


def rust_single_thread(batch: int, repeat: int, growth: str) -> dict[str, Any] | None:
    """Rust timings from a child process with RAYON_NUM_THREADS=1."""
    env = dict(os.environ, RAYON_NUM_THREADS="1")
    cmd = [
        sys.executable, str(Path(__file__).resolve()), "--rust-only", "--batch", str(batch),
        "--repeat", str(repeat), "--growth", growth,
    ]
    p = subprocess.run(cmd, env=env, capture_output=True, text=True)
    if p.returncode != 0:
        print(f"single-thread child failed:\n{p.stderr}", file=sys.stderr)
        return None
    return json.loads(p.stdout)


def summarise(times: list[float], n: int) -> dict[str, Any]:
    med = statistics.median(times)
    return {
        "candidates": n,
        "times_s": times,
        "median_s": med,
        "us_per_candidate": med / n * 1e6,
    }


# --------------------------------------------------------------------------------------------
# report
# --------------------------------------------------------------------------------------------


def report(res: dict[str, Any]) -> None:
    ref = res["reference"]
    rows = []
    for key, title in (("rust_1_thread", "Rust, RAYON_NUM_THREADS=1"), ("rust", f"Rust, {res['rust_threads']}")):
        r = res.get(key)
        if r is None:
            continue
        rows.append((title, r["candidates"], r["median_s"], r["us_per_candidate"], ref["us_per_candidate"] / r["us_per_candidate"], r["checks"]))
    scaled = "" if ref["candidates"] == res["batch"] else " (scaled)"
    rows.append(("numpy reference" + scaled, ref["candidates"], ref["median_s"], ref["us_per_candidate"], 1.0, ref["checks"]))

    case = res["case"]
    header = (
        f"growth stage: {case['grid']} grid, {case['free_cells']} free cells, {case['rooms']} rooms "
        f"(targets {case['target_share']:.0%} of free), batch {res['batch']}, median of {res['repeat']}"
    )
    cols = ("implementation", "cand.", "median s", "µs/cand.", "ref ÷ this", "area err", "rooms", "assigned", "ok")
    cells = [
        (name, str(n), f"{med:.4f}", f"{us:,.1f}", f"{ratio:,.1f}", f"{ch['mean_rel_area_error']:.3f}", f"{ch['all_rooms_present']:.0%}", f"{ch['all_free_assigned']:.0%}", "yes" if ch["ok"] else "NO")
        for name, n, med, us, ratio, ch in rows
    ]
    try:
        from rich.console import Console
        from rich.table import Table

        t = Table(title=header)
        for col in cols:
            t.add_column(col, justify="left" if col == "implementation" else "right", no_wrap=True)
        for row in cells:
            t.add_row(*row)
        Console(width=max(Console().width, 120)).print(t)
    except ImportError:
        print(header)
        widths = [max(len(c), *(len(r[i]) for r in cells)) for i, c in enumerate(cols)]
        for row in (cols, *cells):
            print("  ".join(v.ljust(wd) if i == 0 else v.rjust(wd) for i, (v, wd) in enumerate(zip(row, widths))))
    load = res["machine"]["loadavg_at_start"][0]
    print(f"load average at start {load:.2f} on {res['machine']['cpus']} CPUs" + (" (machine not idle: timings may be noisy)" if load > 0.25 * (res["machine"]["cpus"] or 1) else ""))
    print("ref ÷ this: reference µs per candidate over this implementation's; area err: mean |area - target| / target")
    for key, title in (("rust_1_thread", "Rust 1 thread"), ("rust", "Rust default"), ("reference", "reference")):
        if res.get(key):
            ch = res[key]["checks"]
            print(
                f"{title}: mean relative area error {ch['mean_rel_area_error']:.3f} (max {ch['max_rel_area_error']:.3f}), "
                f"rooms present {ch['all_rooms_present']:.0%}, rooms in one piece {ch['rooms_in_one_piece']:.0%}, "
                f"free cells assigned {ch['all_free_assigned']:.0%}, parent keeps {ch['mean_parent_share']:.1%} of the region"
            )
    if scaled:
        print(
            f"note: the reference would take over {REFERENCE_BUDGET_S:g} s for {res['batch']} candidates; "
            f"it was timed on {ref['candidates']} candidates and is reported per candidate."
        )


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--batch", type=int, default=100, help="candidates per timed call (default 100)")
    ap.add_argument("--repeat", type=int, default=5, help="timed calls per implementation; the median is reported (default 5)")
    ap.add_argument("--json", metavar="OUT", help="also write the results as JSON to OUT")
    ap.add_argument("--no-single-thread", action="store_true", help="skip the RAYON_NUM_THREADS=1 child run")
    ap.add_argument("--growth", choices=("balanced", "longest"), default="balanced", help="rectangular phase's side rule, for both implementations (default balanced)")
    ap.add_argument("--rust-only", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args()
    case = build_case()

    if args.rust_only:  # child mode: Rust timings as JSON on stdout
        times, out = time_rust(case, args.batch, args.repeat, args.growth)
        print(json.dumps(dict(summarise(times, args.batch), checks=check(out, case))))
        return 0

    threads_env = os.environ.get("RAYON_NUM_THREADS")
    res: dict[str, Any] = {
        "batch": args.batch,
        "repeat": args.repeat,
        "rng_seed": RNG_SEED,
        "radius": RADIUS,
        "growth": args.growth,
        "case": {
            "grid": f"{SIZE}x{SIZE}",
            "notch": f"{NOTCH_W}x{NOTCH_H} top right",
            "free_cells": case["free"],
            "rooms": len(ROOMS),
            "targets": case["targets"].tolist(),
            "target_share": float(case["targets"].sum() / case["free"]),
            "seeds": case["seeds"].tolist(),
        },
        "rust_threads": f"RAYON_NUM_THREADS={threads_env}" if threads_env else f"default threads ({os.cpu_count()} CPUs)",
        "machine": {"python": platform.python_version(), "numpy": np.__version__, "cpus": os.cpu_count(), "platform": platform.platform(), "loadavg_at_start": list(os.getloadavg())},
    }

    if threads_env is None and not args.no_single_thread:
        res["rust_1_thread"] = rust_single_thread(args.batch, args.repeat, args.growth)

    times, out = time_rust(case, args.batch, args.repeat, args.growth)
    res["rust"] = dict(summarise(times, args.batch), checks=check(out, case))

    times, out, n = time_reference(case, args.batch, args.repeat, args.growth)
    res["reference"] = dict(summarise(times, n), checks=check(out, case))

    ref_us = res["reference"]["us_per_candidate"]
    res["ratio_reference_over_rust"] = ref_us / res["rust"]["us_per_candidate"]
    if res.get("rust_1_thread"):
        res["ratio_reference_over_rust_1_thread"] = ref_us / res["rust_1_thread"]["us_per_candidate"]

    report(res)
    if args.json:
        Path(args.json).write_text(json.dumps(res, indent=2) + "\n")
        print(f"wrote {args.json}")
    ok = res["rust"]["checks"]["ok"] and res["reference"]["checks"]["ok"]
    if not ok:
        print("invariant check FAILED", file=sys.stderr)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
