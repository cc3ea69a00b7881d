"""``mansion dataset`` throughput benchmark (issue 12).

Generates the first N buildings of the default dataset (mix residential 50 % / office 30 % /
public 20 %, 2–10 floors, <= 500 m² per floor, seed 0: plans, furnished scenes, validation, no
pictures) with each engine in turn into a fresh folder, and reports:

- buildings per minute (wall clock) and the time 1,000 buildings would take at that rate;
- the cost per floor (worker seconds per generated floor; copies are floors too);
- where the time goes, from the timings every job returns (planning, solving, checks, scenes with
  objects, writing, validation), and the objects' share of the scenes, measured by rebuilding the
  scenes of a sample of the buildings without objects;
- peak memory per worker (the largest ``ru_maxrss`` a job saw in its worker);
- the Ray engine's throughput against the local engine's, on this one machine.

The first N buildings follow the mix within a building (golden-ratio draw), and their floor
counts are uniform over 2–10, so N of 40–60 estimates the whole dataset; the extrapolation uses
the measured rate. Run from the repository root:

    PYTHONPATH=python python benches/python/bench_dataset.py --n 48 --workers 2
    PYTHONPATH=python python benches/python/bench_dataset.py --n 48 --engines local --no-validate
    # the same figures for a dataset made by `mansion dataset` (a resumed run: give its wall time)
    PYTHONPATH=python python benches/python/bench_dataset.py --summarise world --wall 1800
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import statistics
import sys
import tempfile
import time
from collections import defaultdict
from pathlib import Path
from typing import Any

from mansion.dataset import DatasetSettings, make_dataset
from mansion.dataset.job import STAGES
from mansion.dataset.store import load_records


def _objects_share(root: Path, records: list[dict[str, Any]], sample: int) -> dict[str, float]:
    """Seconds of the scenes with and without objects over ``sample`` buildings (evenly spread)."""
    from mansion.models.building import Building
    from mansion.scene import build_scenes

    chosen = records[:: max(1, len(records) // max(sample, 1))][:sample]
    bare = full = 0.0
    for r in chosen:
        building = Building.load(root / "buildings" / r["id"] / "building.json")
        t = time.perf_counter()
        build_scenes(building, objects=False)
        bare += time.perf_counter() - t
        t = time.perf_counter()
        build_scenes(building, objects=True)
        full += time.perf_counter() - t
    return {"buildings": len(chosen), "scenes_without_objects": round(bare, 2), "scenes_with_objects": round(full, 2)}


def figures(records: list[dict[str, Any]], wall: float, load: float | None, failures: int) -> dict[str, Any]:
    """The throughput figures of a dataset's building records made in ``wall`` seconds."""
    stages: dict[str, float] = defaultdict(float)
    cpu_stages: dict[str, float] = defaultdict(float)
    for r in records:
        for k, v in r["timings"].items():
            stages[k] += v
        for k, v in r.get("cpu_timings", {}).items():
            cpu_stages[k] += v
    cpu_seconds = sum(r.get("cpu_seconds", 0.0) for r in records)
    worker_seconds = sum(r["seconds"] for r in records)
    floors = sum(r["floors"] for r in records)
    by_floors: dict[int, list[float]] = defaultdict(list)
    for r in records:
        by_floors[r["floors"]].append(r["seconds"])
    return {
        # other work on the machine: 1-minute load average at the start and the end
        "load_average": [round(load, 1), round(os.getloadavg()[0], 1)] if load is not None else None,
        "buildings": len(records),
        "failures": failures,
        "floors": floors,
        "wall_seconds": round(wall, 1),
        "buildings_per_minute": round(60 * len(records) / wall, 2),
        "minutes_for_1000": round(1000 * wall / max(len(records), 1) / 60, 1),
        "worker_seconds_per_floor": round(worker_seconds / max(floors, 1), 2),
        "worker_seconds_per_building": round(worker_seconds / max(len(records), 1), 2),
        "median_seconds_by_floors": {k: round(statistics.median(v), 2) for k, v in sorted(by_floors.items())},
        "stage_share_percent": {
            k: round(100 * stages[k] / max(worker_seconds, 1e-9), 1) for k in (*STAGES, "solver") if k in stages
        },
        # CPU time is what a busy machine does not inflate: the time of 1,000 buildings on
        # this machine's two cores with nothing else running, from the CPU the jobs used
        "cpu_seconds_per_building": round(cpu_seconds / max(len(records), 1), 2),
        "cpu_seconds_per_floor": round(cpu_seconds / max(floors, 1), 2),
        "idle_minutes_for_1000_on_2_cores": round(1000 * cpu_seconds / max(len(records), 1) / 2 / 60, 1),
        "cpu_stage_share_percent": {
            k: round(100 * cpu_stages[k] / max(cpu_seconds, 1e-9), 1)
            for k in (*STAGES, "solver") if k in cpu_stages
        },
        "peak_memory_mb_per_worker": max((r["peak_memory_mb"] for r in records), default=0.0),
    }


def run(engine: str, n: int, workers: int, settings: DatasetSettings, sample: int) -> dict[str, Any]:
    root = Path(tempfile.mkdtemp(prefix=f"bench-dataset-{engine}-"))
    try:
        load = os.getloadavg()[0]
        start = time.perf_counter()
        summary = make_dataset(root / "ds", n, settings, workers=workers, engine=engine)
        wall = time.perf_counter() - start
        records = load_records(root / "ds")
        result = {"engine": engine, **figures(records, wall, load, summary["failures"])}
        if sample and engine == "local":
            result["objects"] = _objects_share(root / "ds", records, sample)
        return result
    finally:
        shutil.rmtree(root, ignore_errors=True)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, default=48)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--engines", default="local,ray")
    parser.add_argument("--no-validate", action="store_true")
    parser.add_argument("--objects-sample", type=int, default=6)
    parser.add_argument("--json", type=Path, help="also write the results here")
    parser.add_argument("--summarise", type=Path, metavar="DIR",
                        help="report the figures of a dataset already made in DIR instead")
    parser.add_argument("--wall", type=float, help="with --summarise: the wall-clock seconds it took")
    args = parser.parse_args()
    if args.summarise:
        failures = sum(1 for _ in (args.summarise / "failures").glob("*.json")) \
            if (args.summarise / "failures").is_dir() else 0
        records = load_records(args.summarise)
        wall = args.wall or max(sum(r["seconds"] for r in records) / max(args.workers, 1), 1e-9)
        print(json.dumps(figures(records, wall, None, failures), indent=1))
        return
    settings = DatasetSettings.parse(seed=args.seed, validate=not args.no_validate)
    results = []
    for engine in args.engines.split(","):
        result = run(engine, args.n, args.workers, settings, args.objects_sample)
        results.append(result)
        print(json.dumps(result, indent=1), flush=True)
    if len(results) == 2:
        a, b = results
        print(f"{b['engine']} / {a['engine']} throughput: {b['buildings_per_minute'] / a['buildings_per_minute']:.2f}")
    if args.json:
        args.json.write_text(json.dumps(results, indent=1) + "\n")
    sys.exit(0)


if __name__ == "__main__":
    main()
