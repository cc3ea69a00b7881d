"""The hub's spine: the circulation a floor's layout lays to its cores, whatever the program says.

In a floor's first cut round the solver keeps, for the hub, a path from the deepest cell of the
floor (the one farthest from its envelope) to every core, as wide as the hub's width rule
(``spine`` in crates/mansion-core/src/solve.rs); the rooms cannot take it. On a floor whose cores
stand far apart (a school with a stair at each end and lifts on a side) that path is two to four
times the corridor the program would otherwise plan, and what it takes beyond the hub's target
comes out of the rooms, mostly out of the wings cut last (issue 14). The program therefore plans
the hub at least as large as this spine (:func:`spine_area`), estimated on the same 0.5 m grid
the generator lays floors on, the same way: a breadth-first tree from the floor's deepest cell,
each core reached along its tree path, every path cell the corner of a square as wide as the rule.
"""

from __future__ import annotations

import math
from collections import deque
from collections.abc import Sequence

import numpy as np
from shapely import contains_xy
from shapely.geometry import Polygon

from mansion.models.building import BuildingCore
from mansion.planning.footprints import Outline

__all__ = ["SPINE_CELL", "spine_area"]

#: The grid the estimate is taken on: the generator's cell size (``generate_building(cell_size=)``).
SPINE_CELL = 0.5


def _grid(outline: Outline, cores: Sequence[BuildingCore], cell: float) -> tuple[np.ndarray, np.ndarray]:
    """(inside, core label or -1) on a grid over ``outline``'s box with a one-cell border; cells
    belong where their centres fall."""
    shape = Polygon(*outline)
    x0, y0, x1, y1 = shape.bounds
    w = math.ceil((x1 - x0) / cell) + 2
    h = math.ceil((y1 - y0) / cell) + 2
    xs = x0 + (np.arange(w) - 0.5) * cell
    ys = y0 + (np.arange(h) - 0.5) * cell
    gx, gy = np.meshgrid(xs, ys)
    floor = contains_xy(shape, gx, gy)
    label = np.full((h, w), -1, dtype=np.int64)
    for k, core in enumerate(cores):
        box = (gx > core.x[0]) & (gx < core.x[1]) & (gy > core.y[0]) & (gy < core.y[1])
        label[box & floor] = k
    return floor & (label < 0), label


def _bfs(inside: np.ndarray, sources: list[int]) -> tuple[list[int], dict[int, int]]:
    """Breadth-first order and predecessors over ``inside`` (flattened), neighbours in the
    solver's order (left, right, up, down)."""
    w = inside.shape[1]
    flat = inside.ravel()
    prev = {s: s for s in sources}
    order: list[int] = []
    queue = deque(sources)
    while queue:
        c = queue.popleft()
        order.append(c)
        for nb in (c - 1, c + 1, c - w, c + w):
            if flat[nb] and nb not in prev:
                prev[nb] = c
                queue.append(nb)
    return order, prev


def spine_area(
    outline: Outline, cores: Sequence[BuildingCore], width: float, cell: float = SPINE_CELL
) -> float:
    """The area (m²) of the spine the solver keeps for a floor's hub to reach ``cores`` (those
    on the floor) through ``outline``, at a width rule of ``width`` m; 0 without cores."""
    if not cores:
        return 0.0
    inside, label = _grid(outline, cores, cell)
    h, w = inside.shape
    flat = inside.ravel()
    cells = np.flatnonzero(flat)
    if cells.size == 0:
        return 0.0
    envelope = [int(c) for c in cells if not (flat[c - 1] and flat[c + 1] and flat[c - w] and flat[c + w])]
    dist = np.full(flat.size, -1)
    dist[envelope] = 0
    order, prev = _bfs(inside, envelope)
    for c in order:
        if dist[c] < 0:
            dist[c] = dist[prev[c]] + 1
    deepest = int(dist[cells].max())
    centre = int(min(c for c in cells if dist[c] == deepest))
    order, prev = _bfs(inside, [centre])
    labels = label.ravel()
    path = {centre}
    for k in range(len(cores)):
        end = next(
            (c for c in order if any(labels[nb] == k for nb in (c - 1, c + 1, c - w, c + w))), None
        )
        while end is not None and end != centre:
            path.add(end)
            end = prev[end]
    rule = max(2, math.ceil(width / cell - 1e-9))
    kept = np.zeros((h, w), dtype=bool)
    for c in path:
        y, x = divmod(c, w)
        kept[y : y + rule, x : x + rule] = True
    return float((kept & inside).sum()) * cell * cell
