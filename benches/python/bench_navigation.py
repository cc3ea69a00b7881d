"""Navigability of scenes (issue 17): over many buildings, the robot's view of every floor.

For each floor (a house JSON) of each building folder given (or generated: ``--generate N
--seed S`` builds the offline hundred's cases), with an agent of ``--radius`` keeping
``--margin`` (clear passages >= 2 · (radius + margin)):

- rooms and cores the agent cannot reach from the spawn with every object removed (and how many
  of them an agent passing 0.5 m necks, one solver cell, would reach);
- rooms whose doors and openings fall apart inside them: by their shape alone (a strip narrower
  than the agent), and with their furniture placed;
- doorsteps the furniture shuts off from the spawn;
- ground floors without a door to the outside (ProcTHOR's convention: ``room0 == room1``).

The same functions as ``mansion validate`` (:mod:`mansion.scene.navigation`).

    python benches/python/bench_navigation.py /tmp/hundred/*/scenes
    python benches/python/bench_navigation.py --generate 100 --seed 0 --json nav.json
"""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
from collections import Counter
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_generate import case, description  # noqa: E402

from mansion.building import generate_building  # noqa: E402
from mansion.scene import BuildingManifest, House, write_scenes  # noqa: E402
from mansion.scene import navigation as nav  # noqa: E402


def _houses(folder: Path) -> list[tuple[int, House]]:
    for manifest in (folder / "manifest.json", folder / "scenes" / "manifest.json"):
        if manifest.is_file():
            m = BuildingManifest.load(manifest)
            return [(f.index, House.load(manifest.parent / f.house)) for f in m.floors]
    return [(k, House.load(p)) for k, p in enumerate(sorted(folder.glob("*.json")))]


def measure(folder: Path, radius: float, margin: float, tally: Counter[str], examples: dict[str, list[str]]) -> None:
    for index, house in _houses(folder):
        where = f"{folder}:{index}"
        tally["floors"] += 1
        tally["rooms"] += len(house.rooms)
        cores = {r.id for r in house.rooms if r.metadata and r.metadata.core}
        tally["cores"] += len(cores)
        lost = nav.unreachable_rooms(house, radius=radius, margin=margin)
        if lost is None:
            tally["floors without a usable spawn"] += 1
            lost = [r.id for r in house.rooms]
        tally["unreachable rooms (objects removed)"] += len(lost)
        tally["unreachable cores (objects removed)"] += len(set(lost) & cores)
        if lost:
            tally["floors with an unreachable room"] += 1
            # behind necks of 0.5 m (one solver cell): reached once 0.5 m passages let it through
            wider = nav.unreachable_rooms(house, radius=0.25, margin=0.0)
            if wider is not None:
                tally["  of them reached through 0.5 m passages"] += len(set(lost) - set(wider))
            examples["unreachable"].append(f"{where} {', '.join(lost[:4])}")
        for cut in nav.disconnected_entrances(house, radius=radius, margin=margin):
            key = "rooms with doors cut apart by furniture" if cut.furniture else "rooms with doors cut apart by their shape"
            tally[key] += 1
            examples[key].append(f"{where} {cut.room}")
        blocked = nav.blocked_entrances(house, radius=radius, margin=margin)
        tally["doorsteps the furniture shuts off"] += len(blocked)
        examples["doorsteps the furniture shuts off"] += [f"{where} {room} ({door})" for room, door in blocked]
        if index == 0:
            tally["ground floors"] += 1
            if not any(d.room0 == d.room1 for d in house.doors):
                tally["ground floors without an outside door"] += 1
                examples["no outside door"].append(where)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("folders", nargs="*", type=Path, help="Building folders (with manifest.json or scenes/manifest.json).")
    ap.add_argument("--generate", type=int, default=0, help="Generate this many offline buildings instead.")
    ap.add_argument("--seed", type=int, default=0, help="First seed of --generate.")
    ap.add_argument("--radius", type=float, default=nav.AGENT_RADIUS)
    ap.add_argument("--margin", type=float, default=nav.MARGIN)
    ap.add_argument("--json", type=Path, help="Write the figures here too.")
    ap.add_argument("--examples", type=int, default=5, help="Examples printed per finding.")
    args = ap.parse_args()
    tally: Counter[str] = Counter({k: 0 for k in (
        "floors", "rooms", "cores", "unreachable rooms (objects removed)",
        "unreachable cores (objects removed)", "  of them reached through 0.5 m passages",
        "floors with an unreachable room",
        "rooms with doors cut apart by their shape", "rooms with doors cut apart by furniture",
        "doorsteps the furniture shuts off", "ground floors", "ground floors without an outside door",
        "floors without a usable spawn")})
    examples: dict[str, list[str]] = {"unreachable": [], "no outside door": []}
    examples.setdefault("rooms with doors cut apart by furniture", [])
    examples.setdefault("rooms with doors cut apart by their shape", [])
    examples.setdefault("doorsteps the furniture shuts off", [])
    with tempfile.TemporaryDirectory() as tmp:
        folders = list(args.folders)
        for seed in range(args.seed, args.seed + args.generate):
            kind, n = case(seed)
            b = generate_building(description(kind, n), building_type=kind, floors=n, seed=seed)
            folders.append(write_scenes(b, Path(tmp) / str(seed)).parent)
        for folder in folders:
            measure(folder, args.radius, args.margin, tally, examples)
    print(f"agent radius {args.radius} m + margin {args.margin} m (passages >= {2 * (args.radius + args.margin):.2f} m), "
          f"{len(folders)} buildings")
    for key, n in tally.items():
        print(f"  {key:45s} {n}")
    for key, items in examples.items():
        for line in items[: args.examples]:
            print(f"    {key}: {line}")
    if args.json:
        args.json.write_text(json.dumps({"radius": args.radius, "margin": args.margin,
                                         "buildings": len(folders), **tally}, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
