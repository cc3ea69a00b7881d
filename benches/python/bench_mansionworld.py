"""Interoperation with the MANSION authors' layout (issue 18), over many buildings: each offline
building exported with ``mansion export --format mansionworld``, read back and compared (the
round trip of tests/test_mansionworld.py: the same rooms, doors, cores and objects, and the same
bytes when written again), and read by ``mansion_api``'s own JSON-reading functions (room
polygons, landmarks, the room graph and its door lookup, edge states, current room, landmark
floors: ``check_with_mansion_api`` of the same test module; needs ``pip install
'mansion[mansionworld]'``). With ``--validate`` the export also goes through ``mansion validate``.

    python benches/python/bench_mansionworld.py --generate 100 --seed 0 --json mw.json
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import sys
import tempfile
import time
import traceback
from collections import Counter
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parents[1] / "tests"))

from bench_generate import case, description  # noqa: E402
from test_mansionworld import assert_round_trip, check_with_mansion_api  # noqa: E402

from mansion.building import generate_building  # noqa: E402
from mansion.exceptions import MansionError  # noqa: E402
from mansion.export.mansionworld import write_mansionworld  # noqa: E402
from mansion.scene import write_scenes  # noqa: E402
from mansion.scene.validate import errors, validate_path  # noqa: E402


def _first_line(exc: BaseException) -> str:
    text = str(exc).strip().splitlines()
    return f"{type(exc).__name__}: {text[0][:200] if text else ''}"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--generate", type=int, default=100, help="How many offline buildings (seeds --seed ...).")
    ap.add_argument("--seed", type=int, default=0, help="First seed.")
    ap.add_argument("--validate", action="store_true", help="Also run mansion validate on each export.")
    ap.add_argument("--json", type=Path, help="Write the figures here too.")
    args = ap.parse_args()
    api = importlib.util.find_spec("mansion_api") is not None
    tally: Counter[str] = Counter({k: 0 for k in (
        "buildings", "generation failed", "exported", "round trip passed", "mansion_api checks passed",
        "floors", "rooms", "door edges", "open-space edges", "openings", "openings their graph misses",
        "floors their graph joins whole")})
    failures: list[str] = []
    start = time.perf_counter()
    with tempfile.TemporaryDirectory() as tmp:
        for seed in range(args.seed, args.seed + args.generate):
            kind, n = case(seed)
            tally["buildings"] += 1
            root = Path(tmp) / str(seed)
            try:
                b = generate_building(description(kind, n), building_type=kind, floors=n, seed=seed)
                write_scenes(b, root / "scenes")
            except MansionError as exc:
                tally["generation failed"] += 1
                failures.append(f"seed {seed} ({kind}, {n}): generation {_first_line(exc)}")
                continue
            out = root / "mansionworld"
            try:
                write_mansionworld(root, out)
                tally["exported"] += 1
                assert_round_trip(root, out, root / "again")
                tally["round trip passed"] += 1
                if api:
                    counts = check_with_mansion_api(out)
                    tally["mansion_api checks passed"] += 1
                    tally.update(counts)
                if args.validate:
                    found = errors(validate_path(out))
                    tally["exports with validate errors"] += int(bool(found))
            except (AssertionError, MansionError, KeyError, ValueError) as exc:
                failures.append(f"seed {seed} ({kind}, {n}): {_first_line(exc)}")
                traceback.print_exc(limit=3)
            print(f"seed {seed:3d} {kind:14s} {n:2d} floors: {len(failures)} failing so far", flush=True)
    elapsed = time.perf_counter() - start
    print(f"{tally['buildings']} buildings in {elapsed:.0f} s; mansion_api {'installed' if api else 'NOT installed'}")
    for key, v in tally.items():
        print(f"  {key:35s} {v}")
    for line in failures:
        print(f"  FAIL {line}")
    if args.json:
        args.json.write_text(json.dumps({"mansion_api": api, **tally, "failures": failures}, indent=1) + "\n")
    return 1 if failures else 0


if __name__ == "__main__":
    raise SystemExit(main())
