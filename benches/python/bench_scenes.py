"""Scenes for the offline planner's hundred (issues 5 and 6): every building of benchmark seeds
0–99 (the same cases as ``bench_generate.py``) is generated, its scenes written with objects,
and the whole building validated (every floor's house JSON, objects included, and the cores
across floors). Prints every problem and exits non-zero if any building has an error.

Then the objects over every room: #OB (footprints leaving their room by more than 1 cm), #CN
(overlapping floor objects, tucked seats excepted), #Rch (objects reached by the validator's
own flood fill), each counted from ``mansion validate``'s problems; how many rooms were
furnished, left empty, skipped (cores, circulation) or failed, with the reasons.

    python benches/python/bench_scenes.py             # seeds 0–99
    python benches/python/bench_scenes.py --seeds 0 20
    python benches/python/bench_scenes.py --no-objects
"""

from __future__ import annotations

import argparse
import re
import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from collections import Counter  # noqa: E402

from bench_generate import case, description  # noqa: E402

from mansion.building import generate_building  # noqa: E402
from mansion.exceptions import MansionError  # noqa: E402
from mansion.scene import BuildingManifest, House, Problem, validate_path, write_scenes  # noqa: E402
from mansion.scene.validate import errors  # noqa: E402


def _kind_of(reason: str) -> str:
    """A reason without the ids and counts of its room, so alike reasons count together."""
    reason = re.sub(r"\(\d+ candidates\)", "", reason.split(";")[0])
    reason = re.sub(r"room [^:]+: ", "", reason)
    return reason.split(": kept clear")[0].strip()


class ObjectTally:
    """Objects and room outcomes over many buildings."""

    def __init__(self) -> None:
        self.floor_objects = self.small = self.ob = self.cn = self.unreached = 0
        self.rooms: Counter[str] = Counter()
        self.reasons: Counter[str] = Counter()
        self.rooms_unreached: set[tuple[str, str]] = set()
        self.furnished_rooms: set[tuple[str, str]] = set()

    def add(self, manifest_path: Path, problems: list[Problem]) -> None:
        manifest = BuildingManifest.load(manifest_path)
        owner: dict[str, tuple[str, str]] = {}
        for floor in manifest.floors:
            file = manifest_path.parent / floor.house
            house = House.load(file)
            self.floor_objects += len(house.objects)
            self.small += sum(len(o.children) for o in house.objects)
            for o in house.objects:
                owner[o.id] = (str(file), o.room or "")
            record = house.metadata.mansion.furnishing if house.metadata.mansion else None
            if record is None:
                continue
            for rid, r in record.rooms.items():
                self.rooms[r.status] += 1
                if r.status == "furnished":
                    self.furnished_rooms.add((str(file), rid))
                if r.reason:
                    self.reasons[f"{r.status}: {_kind_of(r.reason)}"] += 1
        for p in problems:
            if p.rule == "object-in-room":
                self.ob += 1
            elif p.rule == "object-overlap":
                self.cn += 1
            elif p.rule == "object-reach" and p.element in owner:
                self.unreached += 1
                self.rooms_unreached.add(owner[p.element])

    def report(self) -> str:
        rch = 100.0 * (self.floor_objects - self.unreached) / max(1, self.floor_objects)
        rooms = len(self.furnished_rooms)
        full = rooms - len(self.rooms_unreached & self.furnished_rooms)
        lines = [
            f"objects: {self.floor_objects} floor objects and {self.small} small ones",
            f"#OB {self.ob}, #CN {self.cn}, #Rch {rch:.2f} % of objects; "
            f"{full}/{rooms} furnished rooms at #Rch 100 %",
            "rooms: " + ", ".join(f"{n} {k}" for k, n in sorted(self.rooms.items())),
        ]
        lines += [f"    {n:5d}  {why}" for why, n in self.reasons.most_common()]
        return "\n".join(lines)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--seeds", nargs=2, type=int, default=(0, 100), metavar=("FIRST", "END"))
    ap.add_argument("--no-objects", action="store_true", help="Scenes without objects (issue 5 alone).")
    args = ap.parse_args()
    failed, floors, scene_times = [], 0, []
    tally = ObjectTally()
    began = time.perf_counter()
    with tempfile.TemporaryDirectory() as tmp:
        for seed in range(*args.seeds):
            kind, n = case(seed)
            try:
                b = generate_building(description(kind, n), building_type=kind, floors=n, seed=seed)
                start = time.perf_counter()
                manifest = write_scenes(b, Path(tmp) / str(seed), objects=not args.no_objects)
                problems = validate_path(manifest)
                scene_times.append(time.perf_counter() - start)
                tally.add(manifest, problems)
            except MansionError as exc:
                failed.append(seed)
                print(f"seed {seed:3d} {kind:17s} {n:2d} floors  FAIL {type(exc).__name__}: {exc}")
                continue
            floors += len(b.floors)
            bad = errors(problems)
            status = "ok" if not problems else f"{len(bad)} errors, {len(problems) - len(bad)} warnings"
            print(f"seed {seed:3d} {kind:17s} {n:2d} floors  scenes+validate {scene_times[-1]:5.2f} s  {status}", flush=True)
            for p in problems[:10]:
                print(f"    {p}")
            if bad:
                failed.append(seed)
    total = args.seeds[1] - args.seeds[0]
    print(
        f"\n{total - len(failed)}/{total} buildings without an error ({floors} floors); scenes + validation "
        f"median {statistics.median(scene_times):.2f} s, max {max(scene_times):.2f} s per building"
    )
    if not args.no_objects:
        print(tally.report())
    print(f"total {time.perf_counter() - began:.0f} s (planning, layout, scenes, objects, validation)")
    if failed:
        print(f"failing seeds: {failed}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
