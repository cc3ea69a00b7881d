# Type stub of the compiled Rust binding (crates/mansion-py), checked against the built module by
# `python -m mypy.stubtest mansion._core` (tests/test_stubs.py). All JSON shapes are described in
# the Python models: mansion.models (graph, footprint, layout) and mansion.models.seeds.
from collections.abc import Callable

import numpy as np
import numpy.typing as npt

__all__ = ["__version__", "solve_floor", "rasterise", "mask_outline", "vectorise", "adjacencies", "covered_cells", "box_cover", "mask_pieces", "mask_passable", "mask_windows", "pair_walls", "cell_sums", "grow_candidates", "place_room", "place_rooms"]

__version__: str

def solve_floor(
    graph_json: str,
    footprint_json: str,
    options_json: str,
    seed_planner: Callable[[str], str] | None = None,
) -> str:
    """Solve one floor; returns the FloorLayout JSON. Raises mansion.exceptions errors."""

def rasterise(
    footprint_json: str, cell_size: float
) -> tuple[npt.NDArray[np.int32], tuple[float, float]]:
    """(rows, cols) int32 grid, row 0 at the bottom: -1 outside, -2 free, k >= 0 the k-th core;
    and the grid's origin in metres."""

def mask_outline(
    mask: npt.NDArray[np.uint8],
) -> tuple[list[tuple[int, int]], list[list[tuple[int, int]]]]:
    """Outer ring and hole rings of a (rows, cols) mask, row 0 at the bottom, in grid vertices."""

def vectorise(
    labels: npt.NDArray[np.int32],
) -> list[tuple[int, list[tuple[int, int]], list[list[tuple[int, int]]]]]:
    """(label, outer ring, holes) for each label >= 0 of an int32 grid, in grid vertices."""

def adjacencies(labels: npt.NDArray[np.int32]) -> list[tuple[int, int, int, int]]:
    """(label a, label b, shared cell edges, longest straight run of them), a < b, for each pair
    of labels >= 0 of an int32 grid sharing a wall, as the solver measures a layout's."""

def covered_cells(mask: npt.NDArray[np.bool_], m: int) -> int:
    """Cells of a boolean mask that some m x m block of its cells covers."""

def box_cover(mask: npt.NDArray[np.bool_], sides: list[int]) -> tuple[int, int, int, list[int]]:
    """(rows, columns) of the box of a boolean mask's cells, its cells, and for each of sides the
    cells some block of that side covers."""

def mask_pieces(mask: npt.NDArray[np.bool_]) -> int:
    """Number of 4-connected pieces of a boolean mask's cells."""

def mask_passable(mask: npt.NDArray[np.bool_]) -> tuple[int, int]:
    """(cells no 2 x 2 block of a boolean mask covers, pieces those blocks make joined by a side)."""

def mask_windows(
    region: npt.NDArray[np.bool_],
    own: npt.NDArray[np.bool_],
    side: int,
    lo: int,
    hi: int,
    stretch: float,
    bounds: tuple[int, int, int, int],
) -> npt.NDArray[np.int64]:
    """(h, w, row, column, cells of own held) of each rectangle of cells inside region within its
    box (r0, r1, c0, c1): sides at least side, lo to hi cells, long side at most stretch times
    the short; an int64 array (n, 5)."""

def pair_walls(labels: npt.NDArray[np.int32], pairs: list[tuple[int, int]]) -> list[tuple[int, int]]:
    """(shared cell edges, longest straight run of them) of each pair of labels in pairs in an
    int32 label grid (negative = no room), as adjacencies measures them; (0, 0) where none."""

def cell_sums(labels: npt.NDArray[np.int32], ox: float, oy: float, s: float) -> list[tuple[int, int, float, float]]:
    """Per label of an int32 label grid, in label order: (label, cells, sum of the cells' centres'
    x, of their y), cell (r, c) centred at (ox + (c + 0.5) s, oy + (r + 0.5) s), summed row by row."""

def grow_candidates(
    labels: npt.NDArray[np.int32],
    region: int,
    seeds: npt.NDArray[np.float64],
    targets: npt.NDArray[np.float64],
    batch: int,
    rng_seed: int,
    radius: float,
    growth: str = "balanced",
) -> npt.NDArray[np.int32]:
    """Grow `batch` candidate partitions of `region` from perturbed seeds (for benchmarks);
    `growth` is the rectangular phase's rule, "balanced" or "longest"."""

def place_room(request_json: str) -> str:
    """Furnish one room from a PlacementRequest JSON; returns the Placement JSON."""

def place_rooms(requests_json: list[str]) -> list[str]:
    """Furnish many rooms in parallel: one Placement JSON per room, or
    ``{"error": {"kind": ..., "message": ...}}`` for a room that failed."""
