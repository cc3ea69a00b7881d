"""The core's measures of a room's cells (mansion-core's masks, issue 14) against what the floor
mends measured with numpy before: the counts must be the same, so the buildings are."""

from __future__ import annotations

import numpy as np

from mansion import _core
from mansion.building.merge import square_cover


def _masks(count: int, seed: int) -> list[np.ndarray]:
    """Random masks of 1 to 11 cells a side, some of them views that are not contiguous."""
    rng = np.random.default_rng(seed)
    out = []
    for i in range(count):
        h, w = rng.integers(1, 12, 2)
        mask = rng.random((h, w)) < rng.uniform(0.3, 0.95)
        out.append(mask[::-1, ::2] if i % 3 == 0 else mask)
    return out


def _pieces(mask: np.ndarray) -> int:
    """4-connected pieces of the cells, as the core draws rooms."""
    return len(_core.vectorise(np.where(mask, 0, -1).astype(np.int32)))


def test_covered_cells_are_those_square_cover_gives() -> None:
    for mask in _masks(400, 0):
        for m in range(0, 6):
            assert _core.covered_cells(mask, m) == int(square_cover(mask, m * 0.5 - 0.001, 0.5).sum())


def test_mask_pieces_are_the_pieces_vectorise_draws() -> None:
    for mask in _masks(400, 1):
        assert _core.mask_pieces(mask) == _pieces(mask)


def test_mask_passable_counts_cells_off_the_squares_and_their_pieces() -> None:
    for mask in _masks(400, 2):
        window = mask[:-1, :-1] & mask[1:, :-1] & mask[:-1, 1:] & mask[1:, 1:]
        covered = np.zeros_like(mask)
        for dy in (0, 1):
            for dx in (0, 1):
                covered[dy:dy + window.shape[0], dx:dx + window.shape[1]] |= window
        assert _core.mask_passable(mask) == (int((mask & ~covered).sum()), _pieces(window))
    # two rooms joined by a neck one cell wide: the neck's cell, and two pieces
    neck = np.array([[1, 1, 0, 1, 1], [1, 1, 1, 1, 1], [1, 1, 0, 1, 1]], dtype=bool)
    assert _core.mask_passable(neck) == (1, 2)


def test_mask_windows_are_every_rectangle_inside_the_region() -> None:
    rng = np.random.default_rng(3)
    for region in _masks(150, 4):
        if not region.any():
            continue
        own = region & (rng.random(region.shape) < 0.5)
        side, lo, hi, stretch = int(rng.integers(1, 4)), int(rng.integers(0, 12)), int(rng.integers(4, 40)), 2.0
        rr, cc = np.nonzero(region)
        r0, r1, c0, c1 = int(rr.min()), int(rr.max()) + 1, int(cc.min()), int(cc.max()) + 1
        want = sorted(
            (h, w, y, x, int(own[y:y + h, x:x + w].sum()))
            for h in range(side, r1 - r0 + 1) for w in range(side, c1 - c0 + 1)
            if lo <= h * w <= hi and max(h, w) <= stretch * min(h, w)
            for y in range(r0, r1 - h + 1) for x in range(c0, c1 - w + 1) if region[y:y + h, x:x + w].all()
        )
        found = _core.mask_windows(region, own, side, lo, hi, stretch, (r0, r1, c0, c1))
        assert found.dtype == np.int64 and found.shape[1] == 5
        assert sorted(map(tuple, found.tolist())) == want


def test_box_cover_is_the_box_and_the_covered_cells_of_it() -> None:
    for mask in _masks(300, 5):
        if not mask.any():
            assert _core.box_cover(mask, [2]) == (0, 0, 0, [0])
            continue
        rr, cc = np.nonzero(mask)
        crop = mask[rr.min():rr.max() + 1, cc.min():cc.max() + 1]
        sides = [1, 2, 3, 4]
        want = (*crop.shape, int(crop.sum()), [_core.covered_cells(crop, m) for m in sides])
        assert _core.box_cover(np.pad(mask, 2), sides) == want


def _label_grids(count: int, seed: int) -> list[np.ndarray]:
    """Random int32 label grids of 1 to 11 cells a side, labels -1 (no room) to 5 in blobs and
    runs, some of them views that are not contiguous."""
    rng = np.random.default_rng(seed)
    out = []
    for i in range(count):
        h, w = rng.integers(1, 12, 2)
        grid = rng.integers(-1, 6, (h, w)).astype(np.int32)
        # runs: copy each cell from its left or lower neighbour often, so walls are long
        for y in range(h):
            for x in range(w):
                if x and rng.random() < 0.5:
                    grid[y, x] = grid[y, x - 1]
                elif y and rng.random() < 0.4:
                    grid[y, x] = grid[y - 1, x]
        out.append(grid[::-1, ::2] if i % 3 == 0 else grid)
    return out


def test_pair_walls_are_what_adjacencies_measures_of_those_pairs() -> None:
    for grid in _label_grids(400, 6):
        all_pairs = {(a, b): (t, m) for a, b, t, m in _core.adjacencies(np.ascontiguousarray(grid))}
        pairs = [(a, b) for a in range(-1, 7) for b in range(-1, 7)]
        found = _core.pair_walls(grid, pairs)
        assert found == [all_pairs.get((min(a, b), max(a, b)), (0, 0)) if a != b else (0, 0) for a, b in pairs]


def test_cell_sums_are_the_python_loops_to_the_bit() -> None:
    rng = np.random.default_rng(7)
    for grid in _label_grids(300, 8):
        ox, oy, s = float(rng.uniform(-50, 50)), float(rng.uniform(-50, 50)), float(rng.choice([0.25, 0.5, 0.3]))
        count: dict[int, int] = {}
        sums: dict[int, list[float]] = {}
        for r, row in enumerate(grid.tolist()):
            cy = oy + (r + 0.5) * s
            for c, k in enumerate(row):
                if k < 0:
                    continue
                acc = sums.setdefault(k, [0.0, 0.0])
                acc[0] += ox + (c + 0.5) * s
                acc[1] += cy
                count[k] = count.get(k, 0) + 1
        want = [(k, count[k], sums[k][0], sums[k][1]) for k in sorted(count)]
        assert _core.cell_sums(grid, ox, oy, s) == want  # exact floats, not approximately


def test_row_runs_number_each_rows_runs_as_a_loop_over_the_rows_would() -> None:
    from mansion._grid import row_runs

    rng = np.random.default_rng(7)
    for _ in range(50):
        h, w = (int(x) for x in rng.integers(1, 12, size=2))
        mask = rng.random((h, w)) < 0.6
        ids, count = row_runs(mask)
        expected = np.zeros((h, w), dtype=np.int64)
        n = 0
        for r in range(h):
            for c in range(w):
                if mask[r, c]:
                    if c == 0 or not mask[r, c - 1]:
                        n += 1  # a run never joins the end of the row above
                    expected[r, c] = n
        assert (ids == expected).all() and count == n
