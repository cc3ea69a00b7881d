"""Tasks in buildings (issue 10).

1. ``--hundred DIR``: the hundred buildings of ``bench_generate.py`` (seeds 0–99; generated into
   DIR once, reused when DIR already holds them); ``--n`` tasks sampled per building (seed =
   building seed); the oracle and the baseline run on every task. Prints success, retrieved,
   navigated, cross-floor share, the candidates rejected by reason, and every task the oracle
   failed (there should be none).
2. ``--perf``: medians of loading a ~500 m² floor, one ``GoToObject`` across it, the oracle on a
   four-floor task, a rendered observation (goals: 200 ms, 20 ms, 1 s, 50 ms).

    python benches/python/bench_tasks.py --hundred /tmp/hundred --n 10
    python benches/python/bench_tasks.py --perf
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from collections import Counter
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_generate import case, description  # noqa: E402

from mansion.building import generate_building  # noqa: E402
from mansion.scene import write_scenes  # noqa: E402
from mansion.sim import BuildingEnv  # noqa: E402
from mansion.sim.agents import BaselineAgent, OracleAgent  # noqa: E402
from mansion.sim.evaluate import run_task, score  # noqa: E402
from mansion.sim.tasks import sample_tasks  # noqa: E402


def hundred(root: Path, seeds: range) -> list[Path]:
    out = []
    for seed in seeds:
        folder = root / f"b{seed:03d}"
        if not (folder / "scenes" / "manifest.json").is_file():
            kind, n = case(seed)
            b = generate_building(description(kind, n), building_type=kind, floors=n, seed=seed)
            write_scenes(b, folder / "scenes")
        out.append(folder)
    return out


def run_hundred(root: Path, n: int, seeds: range) -> int:
    began = time.perf_counter()
    rejected: Counter[str] = Counter()
    candidates = 0
    results: dict[str, list] = {"oracle": [], "baseline": []}
    multi_tasks = multi_cross = no_tasks = 0
    for folder in hundred(root, seeds):
        report = sample_tasks(folder, n, seed=int(folder.name[1:]))
        rejected.update(report.rejected)
        candidates += report.candidates
        env = BuildingEnv(folder)
        if len(env.building.floors) > 1:
            multi_tasks += len(report.tasks)
            multi_cross += sum(t.crosses_floors for t in report.tasks)
        if not report.tasks:
            no_tasks += 1
        line = [f"{folder.name} {len(env.building.floors):2d} floors {len(report.tasks):2d} tasks"]
        for name, agent in (("oracle", OracleAgent), ("baseline", BaselineAgent)):
            outs = [run_task(env, t, agent) for t in report.tasks]
            results[name] += outs
            line.append(f"{name} {sum(o.success for o in outs)}/{len(outs)}")
            for o in outs:
                if name == "oracle" and not o.success:
                    print(f"  ORACLE FAILED {o.id}: {o.last_reason}")
        print("  ".join(line), flush=True)
    print(f"\n{len(seeds)} buildings, {no_tasks} without tasks; {candidates} candidates, rejected:")
    for why, k in rejected.most_common():
        print(f"  {k:5d}  {why}")
    print(f"multi-floor buildings: {multi_cross}/{multi_tasks} tasks cross floors "
          f"({100.0 * multi_cross / max(1, multi_tasks):.1f} %)")
    for name, outs in results.items():
        s = score(outs, name)
        print(f"{name:8s} tasks {s.tasks}  success {s.success:.1f} %  (retrieved {s.retrieved:.1f} %, "
              f"navigated {s.navigated:.1f} %)  cross-floor {s.cross_floor}  mean path {s.mean_path_length:.1f} m  "
              f"mean steps {s.mean_steps:.1f}")
    print(f"total {time.perf_counter() - began:.0f} s")
    return sum(not o.success for o in results["oracle"])


def _median_ms(fn, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return 1000 * statistics.median(times)


def run_perf() -> None:
    with tempfile.TemporaryDirectory() as tmp:
        # a four-floor office of 500 m² floors: floor 1 is the big floor the walks cross
        b = generate_building("a four-storey office", floors=4, area=500, seed=1)
        write_scenes(b, Path(tmp) / "scenes")
        env = BuildingEnv(tmp)
        env.reset(options={"floor": 1})
        st = env.state
        area = sum(p.area for p in st.polygons.values())
        from mansion.sim.world import FloorState

        def load() -> None:
            s = FloorState(env.building.floor_state(1).house, {})
            s.grid  # noqa: B018
            s.landmarks  # noqa: B018

        def load_from_disk() -> None:
            from mansion.sim.world import Building

            Building(Path(tmp)).floor_state(1).grid  # noqa: B018

        print(f"floor 1: {area:.0f} m², {len(st.objects)} objects, grid {st.grid.shape[0]}×{st.grid.shape[1]} cells")
        print(f"load a floor (house parsed): grid + landmarks  median {_median_ms(load, 15):.1f} ms (goal 200)")
        print(f"load a floor from its JSON file              median {_median_ms(load_from_disk, 15):.1f} ms")
        # GoToObject across the floor: from the spawn to the object farthest from it, and back
        objs = sorted((i for i in st.objects.values() if i.parent is None), key=lambda i: i.distance(env.x, env.z))
        far, near = objs[-1].id, objs[0].id
        hops = [far, near] * 10
        times = []
        for oid in hops:
            env.state.grid._dist_cache.clear()  # no help from an earlier search
            t = time.perf_counter()
            res = env.GoToObject(oid)
            times.append(time.perf_counter() - t)
            assert res.success, res
        print(f"GoToObject across the floor ({env.path_length / len(hops):.1f} m a walk)  median "
              f"{1000 * statistics.median(times):.1f} ms (goal 20)")
        tasks = [t for t in sample_tasks(tmp, 12, seed=0).tasks if len(t.floors) >= 2]
        times, ok = [], 0
        for task in tasks:
            t = time.perf_counter()
            ok += run_task(env, task, OracleAgent).success
            times.append(time.perf_counter() - t)
        print(f"oracle, whole task on the four-floor office ({len(tasks)} cross-floor tasks, {ok} solved)  "
              f"median {1000 * statistics.median(times):.0f} ms (goal 1000)")
        env2 = BuildingEnv(tmp, image=True)
        env2.reset(options={"floor": 1})
        env2.top_down()
        print(f"rendered observation (192 px, the floor already drawn)  median {_median_ms(env2.top_down, 50):.1f} ms (goal 50)")
        print(f"whole observation with image  median {_median_ms(env2._observe, 50):.1f} ms")
        from mansion.sim.render import FloorPainter

        print(f"drawing the floor the observations are cropped from (once per floor)  median "
              f"{_median_ms(lambda: FloorPainter(env2.state), 10):.1f} ms")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--hundred", type=Path, help="folder for the hundred buildings (generated once)")
    ap.add_argument("--n", type=int, default=10, help="tasks per building")
    ap.add_argument("--seeds", nargs=2, type=int, default=(0, 100), metavar=("FIRST", "END"))
    ap.add_argument("--perf", action="store_true")
    args = ap.parse_args()
    failed = 0
    if args.hundred:
        failed = run_hundred(args.hundred, args.n, range(*args.seeds))
    if args.perf or not args.hundred:
        run_perf()
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
