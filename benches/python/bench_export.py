"""Export a ten-storey building (issue 13): ``mansion export`` to GLB and to USD, timed.

A ten-storey office (two stairs, two elevators, every floor furnished) is generated once with the
offline planner and written to a temporary folder; then the whole export (reading the house
JSONs, building the model, writing the file) is timed ``--repeat`` times per format and the
median reported; the preview picture is timed once. Exits non-zero when an export takes 10 s or
more (the issue's bound).

    python benches/python/bench_export.py                 # --repeat 5
    python benches/python/bench_export.py --repeat 3 --no-preview
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from pathlib import Path

from mansion.building import generate_building
from mansion.export import building_model, export_building
from mansion.scene import write_scenes

DESCRIPTION = "a ten-storey office with two elevators"
LIMIT = 10.0


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--no-preview", action="store_true")
    args = parser.parse_args(argv)

    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp) / "building"
        start = time.perf_counter()
        building = generate_building(DESCRIPTION, floors=10, seed=args.seed)
        write_scenes(building, folder / "scenes")
        print(f"generated {DESCRIPTION!r} (seed {args.seed}) in {time.perf_counter() - start:.1f} s")
        model = building_model(folder)
        kinds: dict[str, int] = {}
        for node, _ in model.root.walk():
            kinds[node.kind] = kinds.get(node.kind, 0) + 1
        print("model: " + ", ".join(f"{v} {k}" for k, v in sorted(kinds.items())))

        worst = 0.0
        for fmt, name in (("gltf", "building.glb"), ("usd", "building.usd")):
            times = []
            for _ in range(args.repeat):
                t = time.perf_counter()
                out = export_building(folder, fmt, Path(tmp) / name)
                times.append(time.perf_counter() - t)
            median = statistics.median(times)
            worst = max(worst, median)
            print(f"{fmt:5s} median {median:.2f} s over {args.repeat} (min {min(times):.2f}, max {max(times):.2f}); "
                  f"{out.stat().st_size / 1e6:.1f} MB")
        if not args.no_preview:
            from mansion.export.preview import render_preview

            t = time.perf_counter()
            render_preview(building_model(folder), Path(tmp) / "preview.png")
            print(f"preview {time.perf_counter() - t:.2f} s (model + picture)")
    if worst >= LIMIT:
        print(f"FAIL: an export took {worst:.2f} s (limit {LIMIT:.0f} s)")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
