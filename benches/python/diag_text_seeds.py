"""Evaluation-only diagnostic of the offline text seeds on T2D (never used by the method).

For each plan and room, compares the seed that ``--planner text`` would start from with the room's
true centroid (cells), and groups the error by what the text said about the room:

- ``corner`` / ``side`` / ``centre``: its strongest position statement (``corner-wrong`` /
  ``side-wrong`` when a compass word puts it in the other half of the plan from its true centroid:
  the text's error, which no seed solve can mend);
- ``relation``: relations only; ``none``: nothing read about it;
- ``swapped``: a room of a type the plan has twice or more, whose seed is nearer another same-type
  room's true centroid than its own (a matching error, counted on top of its kind).

It also checks the units the seed solve relies on: stated width/depth (feet) against the true
room box (cells), on both axes, so the feet → cells scale and which axis "wide" is are measured,
not assumed; and each position word against the true centroid (is "north" a smaller image row?).

    PYTHONPATH=python python benches/python/diag_text_seeds.py --data ../shared/data/t2d-dev --limit 150 \
        --weights corner=16,unplaced_to_neighbours=1

``--weights`` overrides fields of :class:`mansion.planning.spatial_seeds.SeedWeights` (the seed
sets ``--planner text`` tries are :data:`mansion.eval.text_placement.VARIANTS`).

Ground truth is read here only to score; the seeds come from ``text_problem``/``place_seeds``.
"""

from __future__ import annotations

import argparse
import math
import statistics
from collections import defaultdict
from pathlib import Path

import numpy as np

from mansion.eval.t2d import GRID, iter_plans, node_id, plan_ids
from mansion.eval.text_placement import text_problem
from mansion.planning.spatial_language import DIRECTIONS
from mansion.planning.spatial_layout import LayoutWeights, rectangle_seeds
from mansion.planning.spatial_seeds import SeedWeights, place_seeds

_FEET = 0.3048


def _kind(statements: list) -> str:
    dirs = [s.direction for s in statements if s.kind == "position" and s.direction]
    if any(d != "centre" and all(DIRECTIONS[d]) for d in dirs):
        return "corner"
    if any(d != "centre" for d in dirs):
        return "side"
    if dirs:
        return "centre"
    if any(s.kind == "relation" for s in statements):
        return "relation"
    return "none"


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--data", default="/work/shared/data/t2d-dev")
    ap.add_argument("--limit", type=int, default=150)
    ap.add_argument("--worst", type=int, default=15)
    ap.add_argument("--weights", default="", help="SeedWeights overrides, e.g. relation=0,overlap=0")
    ap.add_argument("--rectangles", default=None, help="score the rectangle layout's seeds instead "
                    "(spatial_layout.rectangle_seeds started from the seeds above), with LayoutWeights "
                    "overrides, e.g. '' or gap=0.5")
    args = ap.parse_args()
    overrides = SeedWeights(**{k: (type(getattr(SeedWeights(), k))(v) if not isinstance(getattr(SeedWeights(), k), bool) else v == "1") for k, v in (kv.split("=") for kv in args.weights.split(",") if kv)})
    layout_weights = LayoutWeights(**{k: float(v) for k, v in (kv.split("=") for kv in (args.rectangles or "").split(",") if kv)})
    errs: dict[str, list[float]] = defaultdict(list)
    axis_errs: dict[str, list[tuple[float, float]]] = defaultdict(list)
    swapped = 0
    multi = 0
    scale_w: list[float] = []  # stated width (m) / true box width (cells)
    scale_d: list[float] = []
    scale_cross: list[float] = []
    dir_ok = dir_n = 0
    worst: list[tuple[float, str, str, str, tuple, tuple]] = []
    plan_err: list[tuple[float, str]] = []
    ids = plan_ids(args.data)[: args.limit]
    for pid, plan in iter_plans(args.data, ids):
        description = (Path(args.data) / "text" / f"{pid}.txt").read_text(encoding="utf-8")
        p = text_problem(plan, description)
        seeds, _ = place_seeds(p.reading, p.rooms, p.free, p.adjacency, weights=overrides)
        if args.rectangles is not None:
            seeds = rectangle_seeds(p.reading, p.rooms, p.free, p.adjacency, start=seeds, weights=layout_weights)
        true = {node_id(r): (r.centroid[0] / 4, GRID - r.centroid[1] / 4) for r in plan.rooms}
        boxes = {node_id(r): r.bbox for r in plan.rooms}
        by_type: dict[str, list[str]] = defaultdict(list)
        for r in plan.rooms:
            by_type[r.type].append(node_id(r))
        pe = []
        rr_, cc_ = np.nonzero(p.free.mask)
        mid = ((cc_.min() + cc_.max() + 1) / 2, (rr_.min() + rr_.max() + 1) / 2)
        for room in p.rooms:
            st = p.reading.about(room.id)
            k = _kind(st)
            if k in ("corner", "side"):
                # does every position word agree with the true centroid's half of the plan?
                tx_, ty_ = true[room.id]
                good = all(
                    (not DIRECTIONS[s.direction][0] or (tx_ - mid[0]) * DIRECTIONS[s.direction][0] > 0)
                    and (not DIRECTIONS[s.direction][1] or (ty_ - mid[1]) * DIRECTIONS[s.direction][1] > 0)
                    for s in st if s.kind == "position" and s.direction and s.direction != "centre"
                )
                k = f"{k}{'' if good else '-wrong'}"
            sx, sy = seeds[room.id]
            tx, ty = true[room.id]
            e = math.hypot(sx - tx, sy - ty)
            errs[k].append(e)
            axis_errs[k].append((sx - tx, sy - ty))
            pe.append(e)
            worst.append((e, pid, room.id, k, (round(sx, 1), round(sy, 1)), (round(tx, 1), round(ty, 1))))
            same = by_type[room.room_type]
            if len(same) > 1:
                multi += 1
                near = min(same, key=lambda o: math.hypot(sx - true[o][0], sy - true[o][1]))
                if near != room.id:
                    swapped += 1
            for s in st:
                if s.kind == "size" and s.width and s.depth and boxes[room.id]:
                    x0, y0, x1, y1 = boxes[room.id]
                    bw, bd = (x1 - x0) / 4, (y1 - y0) / 4
                    scale_w.append(s.width / bw)
                    scale_d.append(s.depth / bd)
                    scale_cross.append(s.width / bd)
                if s.kind == "position" and s.direction and s.direction != "centre":
                    dx, dy = DIRECTIONS[s.direction]
                    rr, cc = np.nonzero(p.free.mask)
                    mx, my = (cc.min() + cc.max() + 1) / 2, (rr.min() + rr.max() + 1) / 2
                    ok = (not dx or (tx - mx) * dx > 0) and (not dy or (ty - my) * dy > 0)
                    dir_ok += ok
                    dir_n += 1
        plan_err.append((statistics.mean(pe), pid))
    print(f"{len(ids)} plans")
    print(f"{'kind':10s} {'n':>5s} {'mean':>6s} {'median':>6s} {'p90':>6s}  mean|dx| mean|dy|  mean dx  mean dy (cells, seed - true)")
    allv = []
    for k in ("corner", "corner-wrong", "side", "side-wrong", "centre", "relation", "none"):
        v = errs.get(k, [])
        allv += v
        if not v:
            continue
        ax = np.array(axis_errs[k])
        print(f"{k:10s} {len(v):5d} {statistics.mean(v):6.2f} {statistics.median(v):6.2f} {np.percentile(v, 90):6.2f}"
              f"  {np.abs(ax[:, 0]).mean():7.2f} {np.abs(ax[:, 1]).mean():7.2f} {ax[:, 0].mean():8.2f} {ax[:, 1].mean():8.2f}")
    print(f"{'all':10s} {len(allv):5d} {statistics.mean(allv):6.2f} {statistics.median(allv):6.2f} {np.percentile(allv, 90):6.2f}")
    print(f"same-type rooms whose seed is nearer a sibling's true centroid: {swapped} / {multi}")
    if scale_w:
        print(f"stated width m / true box width cells: median {statistics.median(scale_w):.3f};"
              f" depth / depth {statistics.median(scale_d):.3f}; width / depth (crossed) {statistics.median(scale_cross):.3f}")
        lw = np.log(np.array(scale_w))
        lc = np.log(np.array(scale_cross))
        print(f"  spread (std of log): width->x {lw.std():.3f}, width->y {lc.std():.3f}  (n={len(scale_w)})")
    print(f"position words agreeing with the true centroid's half (y up = north): {dir_ok} / {dir_n}")
    print("worst rooms:")
    for row in sorted(worst, reverse=True)[: args.worst]:
        print("  ", f"{row[0]:5.1f}", *row[1:])
    print("worst plans (mean seed error):", [f"{pid}:{e:.1f}" for e, pid in sorted(plan_err, reverse=True)[:10]])


if __name__ == "__main__":
    main()
