"""Runs of cells along a grid's rows, for any stage (the banks' run lengths, the placement
check's spread along free runs): one vectorised pass instead of a loop over rows."""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

__all__ = ["row_runs"]


def row_runs(mask: NDArray[np.bool_]) -> tuple[NDArray[np.int64], int]:
    """Each True cell of ``mask``'s run of True cells along its row (axis 1), numbered from 1 in
    row-major order (0: not in ``mask``), and the number of runs."""
    h, w = mask.shape
    # a blocked column after each row keeps runs from joining across rows
    padded = np.zeros((h, w + 1), dtype=bool)
    padded[:, :w] = mask
    flat = padded.ravel()
    starts = flat & ~np.concatenate(([False], flat[:-1]))
    run = np.cumsum(starts) * flat
    return run.reshape(h, w + 1)[:, :w], int(run.max(initial=0))
