"""Properties of the single-floor solver on random orthogonal footprints and graphs.

Instances are built from random partitions of random footprints, so every graph is known to be
feasible: its rooms, areas and adjacencies are those of a real partition of the free region.
"""

from __future__ import annotations

from collections import deque

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from shapely.geometry import Polygon

import mansion
from mansion import Footprint, InfeasibleLayoutError, RoomGraph

CELL = 0.5
MIN_CONTACT_CELLS = 2  # the default min_contact of 1.0 m at 0.5 m cells


def random_mask(rng: np.random.Generator) -> np.ndarray:
    """A rectangle with up to two rectangular notches cut from its corners (image convention)."""
    h, w = int(rng.integers(10, 22)), int(rng.integers(10, 22))
    mask = np.ones((h, w), dtype=bool)
    for _ in range(int(rng.integers(0, 3))):
        nh, nw = int(rng.integers(2, h // 2)), int(rng.integers(2, w // 2))
        top, left = bool(rng.integers(0, 2)), bool(rng.integers(0, 2))
        rows = slice(0, nh) if top else slice(h - nh, h)
        cols = slice(0, nw) if left else slice(w - nw, w)
        mask[rows, cols] = False
    return mask


def random_partition(rng: np.random.Generator, mask: np.ndarray, k: int) -> np.ndarray | None:
    """Grow k regions from random cells by randomised breadth-first search."""
    cells = np.argwhere(mask)
    labels = np.full(mask.shape, -1)
    starts = cells[rng.choice(len(cells), size=k, replace=False)]
    frontier = []
    for i, (r, c) in enumerate(starts):
        labels[r, c] = i
        frontier.append((int(r), int(c)))
    while frontier:
        j = int(rng.integers(0, len(frontier)))
        r, c = frontier[j]
        free = [
            (r + dr, c + dc)
            for dr, dc in ((1, 0), (-1, 0), (0, 1), (0, -1))
            if 0 <= r + dr < mask.shape[0]
            and 0 <= c + dc < mask.shape[1]
            and mask[r + dr, c + dc]
            and labels[r + dr, c + dc] < 0
        ]
        if not free:
            frontier.pop(j)
            continue
        nr, nc = free[int(rng.integers(0, len(free)))]
        labels[nr, nc] = labels[r, c]
        frontier.append((nr, nc))
    sizes = np.bincount(labels[mask], minlength=k)
    return labels if sizes.min() >= 6 else None


def longest_contacts(labels: np.ndarray) -> dict[tuple[int, int], int]:
    """Longest straight shared segment (in cell edges) between every pair of labels."""
    out: dict[tuple[int, int], int] = {}

    def scan(a: np.ndarray, b: np.ndarray) -> None:
        for line_a, line_b in zip(a, b):
            run, prev = 0, None
            for x, y in zip(line_a, line_b):
                key = (min(x, y), max(x, y)) if x != y and x >= 0 and y >= 0 else None
                run = run + 1 if key is not None and key == prev else 1
                prev = key
                if key is not None:
                    out[key] = max(out.get(key, 0), run)

    scan(labels[:-1], labels[1:])
    scan(labels[:, :-1].T, labels[:, 1:].T)
    return out


def instance(seed: int) -> tuple[RoomGraph, Footprint, np.ndarray] | None:
    rng = np.random.default_rng(seed)
    mask = random_mask(rng)
    k = int(rng.integers(3, 8))
    labels = random_partition(rng, mask, k)
    if labels is None:
        return None
    contacts = {p: n for p, n in longest_contacts(labels).items() if n >= MIN_CONTACT_CELLS}
    sizes = np.bincount(labels[mask], minlength=k)
    hub = int(np.argmax(sizes))
    # a BFS spanning tree of the contact graph from the hub: every edge exists in the partition
    adj: dict[int, list[int]] = {i: [] for i in range(k)}
    for a, b in contacts:
        adj[a].append(b)
        adj[b].append(a)
    seen, edges, queue = {hub}, [], deque([hub])
    while queue:
        p = queue.popleft()
        for q in sorted(adj[p]):
            if q not in seen:
                seen.add(q)
                edges.append((p, q))
                queue.append(q)
    if len(seen) < k:
        return None
    nodes = [
        {
            "id": f"r{i}",
            "type": "main" if i == hub else "area",
            "area": float(sizes[i]) * CELL * CELL,
        }
        for i in range(k)
    ]
    graph = RoomGraph.model_validate(
        {"nodes": nodes, "edges": [{"source": f"r{a}", "target": f"r{b}"} for a, b in edges]}
    )
    return graph, Footprint.from_mask(mask, CELL), mask


def components(grid: np.ndarray, label: int) -> int:
    seen = np.zeros(grid.shape, dtype=bool)
    n = 0
    for r, c in np.argwhere(grid == label):
        if seen[r, c]:
            continue
        n += 1
        stack = [(r, c)]
        seen[r, c] = True
        while stack:
            y, x = stack.pop()
            for dy, dx in ((1, 0), (-1, 0), (0, 1), (0, -1)):
                yy, xx = y + dy, x + dx
                if 0 <= yy < grid.shape[0] and 0 <= xx < grid.shape[1]:
                    if grid[yy, xx] == label and not seen[yy, xx]:
                        seen[yy, xx] = True
                        stack.append((yy, xx))
    return n


def room_polygon(room: mansion.LayoutRoom) -> Polygon:
    return Polygon(room.polygon, room.holes)


def check_layout(layout: mansion.FloorLayout, footprint: Footprint, mask: np.ndarray) -> None:
    grid = layout.grid.array()
    # every free cell is assigned, nothing outside is
    assert np.array_equal(grid[::-1] >= 0, mask)
    for k, rid in enumerate(layout.grid.ids):
        assert components(grid, k) == 1, f"room {rid} is not one 4-connected piece"
    # the room polygons tile the free region exactly
    polys = [room_polygon(r) for r in layout.rooms]
    assert all(p.is_valid for p in polys)
    outline = Polygon(footprint.polygon, footprint.holes)
    union = shapely.union_all(polys)
    assert union.symmetric_difference(outline).area < 1e-9
    assert abs(sum(p.area for p in polys) - outline.area) < 1e-9, "rooms overlap"


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])
@given(st.integers(min_value=0, max_value=10**9))
def test_layouts_tile_the_free_region(seed: int) -> None:
    built = instance(seed)
    if built is None:
        return
    graph, footprint, mask = built
    try:
        layout = mansion.solve_floor(graph, footprint, cell_size=CELL, retries=4, batch=40)
    except InfeasibleLayoutError as e:
        assert "rejected" in str(e)
        return
    check_layout(layout, footprint, mask)
    # the same seed gives the same layout
    again = mansion.solve_floor(graph, footprint, cell_size=CELL, retries=4, batch=40)
    assert again.grid == layout.grid


def test_feasible_graphs_are_solved_with_every_edge_realised() -> None:
    solved = total = 0
    failures = []
    for seed in range(400):
        built = instance(seed)
        if built is None:
            continue
        graph, footprint, mask = built
        total += 1
        try:
            layout = mansion.solve_floor(graph, footprint, cell_size=CELL)
        except InfeasibleLayoutError as e:
            failures.append((seed, str(e)))
            continue
        check_layout(layout, footprint, mask)
        for e in graph.edges:
            adj = layout.adjacency(e.source, e.target)
            assert adj is not None and adj.longest >= 1.0 - 1e-9, (seed, e)
        solved += 1
    assert total >= 200
    assert solved / total >= 0.99, f"solved {solved}/{total}; failures: {failures[:5]}"


def test_fixed_walls_are_never_straddled() -> None:
    mask = np.ones((12, 16), dtype=bool)  # 8 m × 6 m at 0.5 m cells
    base = Footprint.from_mask(mask, CELL)
    # a load-bearing wall at x = 4 m from the floor's bottom edge up to y = 4.5 m
    footprint = base.model_copy(update={"fixed_walls": [((4.0, 0.0), (4.0, 4.5))]})
    graph = RoomGraph.model_validate(
        {
            "nodes": [
                {"id": "hall", "type": "main", "area": 16.0},
                {"id": "a", "type": "area", "area": 12.0},
                {"id": "b", "type": "area", "area": 10.0},
                {"id": "c", "type": "area", "area": 10.0},
            ],
            "edges": [
                {"source": "hall", "target": "a"},
                {"source": "hall", "target": "b"},
                {"source": "hall", "target": "c"},
            ],
        }
    )
    for seed in range(5):
        layout = mansion.solve_floor(graph, footprint, cell_size=CELL, rng_seed=seed)
        check_layout(layout, footprint, mask)
        grid = layout.grid.array()
        for row in range(9):  # rows whose cells lie below y = 4.5 m
            assert grid[row, 7] != grid[row, 8], f"seed {seed}: a room straddles the wall at row {row}"


def test_infeasible_round_raises_a_clear_error() -> None:
    # two rooms that must both touch a tiny stair core in a corner cannot both get 1 m of wall
    footprint = Footprint.model_validate(
        {
            "polygon": [(0, 0), (6, 0), (6, 6), (0, 6)],
            "cores": [{"id": "stair", "type": "stair", "x": (0, 1), "y": (0, 1)}],
        }
    )
    graph = RoomGraph.model_validate(
        {
            "nodes": [
                {"id": "hall", "type": "main", "area": 10.0},
                {"id": "a", "type": "area", "area": 12.0},
                {"id": "b", "type": "area", "area": 12.0},
                {"id": "stair", "type": "stair", "area": 0.0},
            ],
            "edges": [
                {"source": "hall", "target": "a"},
                {"source": "hall", "target": "b"},
                {"source": "hall", "target": "stair"},
                {"source": "a", "target": "stair"},
                {"source": "b", "target": "stair"},
            ],
        }
    )
    with pytest.raises(InfeasibleLayoutError, match="rejected"):
        mansion.solve_floor(graph, footprint, retries=2, batch=20, settings={"fallback_samples": 40})
