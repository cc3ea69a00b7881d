"""Room widths of the offline hundred (issues 14 and 17): how many rooms keep parts narrower than
their minimum width, and how many floors have a hub or corridor with a neck narrower than the
floor-wide minimum clear width (:data:`mansion.building.generate.MIN_CLEAR_WIDTH`).

Widths are measured on the laid-out polygons with shapely: a room's part narrower than ``w`` is
what a morphological opening by a ``w × w`` square removes (erosion then dilation, mitred, which
on axis-aligned polygons is exactly the square). A room counts as too narrow when that part holds
more than 0.05 m² (a fifth of a 0.5 m cell).

``--assign-widths`` gives the planner's nodes a minimum width where they have none (1.0 m for
rooms, 1.5 m for the hub and ``area`` nodes such as corridors), to try the solver before the
planners fill widths from the design table. ``--no-widths`` switches every width rule off (the
solver as it was), for the figures before.

    python benches/python/bench_widths.py --assign-widths          # seeds 0–99
    python benches/python/bench_widths.py --no-widths --seeds 0 20
"""

from __future__ import annotations

import argparse
import time
from typing import Any

from shapely.geometry import Polygon

import mansion.building.generate as gen
import mansion.building.steps as steps
from bench_generate import case, description
from mansion.exceptions import MansionError
from mansion.models import RoomGraph
from mansion.planning.planner import OfflinePlanner

#: Narrow parts smaller than this (m²) are rounding, not a strip.
SLACK = 0.05
CIRCULATION = ("main", "area")


def narrow_area(poly: Polygon, width: float) -> float:
    """Area of the parts of ``poly`` that no ``width × width`` square inside it covers."""
    r = width / 2 - 0.01  # a centimetre of slack: erosion to a hairline is numerically empty
    opened = poly.buffer(-r, join_style="mitre").buffer(r, join_style="mitre")
    return max(0.0, poly.area - opened.intersection(poly).area)


def assigned(node: Any) -> float:
    """The width ``--assign-widths`` gives a node without one."""
    return 1.5 if node.type in CIRCULATION else 1.0


def assign_widths(graph: RoomGraph) -> RoomGraph:
    nodes = [
        n if n.is_core or n.min_width is not None else n.model_copy(update={"min_width": assigned(n)})
        for n in graph.nodes
    ]
    return RoomGraph(nodes=nodes, edges=graph.edges)


def measure(seeds: range, assign: bool) -> dict[str, Any]:
    rooms = narrow = floors = necks = relaxed = failures = 0
    times = []
    for seed in seeds:
        kind, n = case(seed)
        start = time.perf_counter()
        try:
            b = gen.generate_building(description(kind, n), building_type=kind, floors=n, seed=seed)
        except MansionError as exc:
            failures += 1
            print(f"seed {seed}: FAIL {exc}")
            continue
        times.append(time.perf_counter() - start)
        for f in b.floors:
            floors += 1
            relaxed += any("width" in r for r in f.relaxations)
            nodes = {n.id: n for n in f.graph.nodes}
            neck = False
            for room in f.layout.rooms:
                node = nodes.get(room.id)
                if node is None or node.is_core:
                    continue
                poly = Polygon(room.polygon, room.holes)
                own = node.min_width or (assigned(node) if assign else 0.0)
                width = max(own, gen.MIN_CLEAR_WIDTH)
                rooms += 1
                narrow += narrow_area(poly, width) > SLACK
                if node.type in CIRCULATION and narrow_area(poly, gen.MIN_CLEAR_WIDTH) > SLACK:
                    neck = True
            necks += neck
    return {
        "buildings": len(seeds), "failures": failures, "floors": floors, "rooms": rooms,
        "narrow": narrow, "necks": necks, "relaxed": relaxed, "seconds": sum(times),
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, nargs=2, default=(0, 100), metavar=("FROM", "TO"))
    ap.add_argument("--assign-widths", action="store_true")
    ap.add_argument("--no-widths", action="store_true")
    args = ap.parse_args()
    plan = OfflinePlanner.plan_topology
    if args.no_widths:
        # the solver without width rules; rooms are still measured against the rules
        steps.floor_settings = lambda cell_size, width=None: steps.SolverSettings()  # type: ignore[assignment]
        OfflinePlanner.plan_topology = lambda self, p, i: steps._widths_at_most(plan(self, p, i), None)  # type: ignore[method-assign]
    elif args.assign_widths:
        OfflinePlanner.plan_topology = lambda self, p, i: assign_widths(plan(self, p, i))  # type: ignore[method-assign]
    m = measure(range(*args.seeds), args.assign_widths)
    print(
        f"{m['buildings']} buildings ({m['failures']} failed), {m['floors']} floors, "
        f"{m['rooms']} rooms in {m['seconds']:.1f} s\n"
        f"rooms with parts narrower than their minimum width: {m['narrow']} "
        f"({100 * m['narrow'] / max(m['rooms'], 1):.1f} %)\n"
        f"floors whose hub or corridors have a neck under {gen.MIN_CLEAR_WIDTH:g} m: {m['necks']}\n"
        f"floors with a width rule relaxed: {m['relaxed']}"
    )


if __name__ == "__main__":
    main()
