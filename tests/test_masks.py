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
