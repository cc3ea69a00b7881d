"""Class-wise IoU of a predicted label map against the ground truth (the T2D protocol's scores).

Both maps hold class indices; 0 is ``outside`` and is not a class. Two rooms of the same type
count as one class. Over the classes present in the prediction or the ground truth:

- micro-IoU = Σ|pred ∩ gt| / Σ|pred ∪ gt|;
- macro-IoU = mean of |pred ∩ gt| / |pred ∪ gt|.

Both are fractions in [0, 1] here; reports multiply by 100.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, NamedTuple

from mansion.exceptions import InvalidInputError

if TYPE_CHECKING:
    import numpy.typing as npt

__all__ = ["PlanIoU", "plan_iou"]


class PlanIoU(NamedTuple):
    micro: float
    macro: float


def plan_iou(pred: npt.ArrayLike, gt: npt.ArrayLike) -> PlanIoU:
    """Micro- and macro-IoU of one plan. A plan with no room class in either map scores 0."""
    import numpy as np

    p = np.asarray(pred)
    g = np.asarray(gt)
    if p.shape != g.shape:
        raise InvalidInputError(f"prediction shape {p.shape} differs from ground truth {g.shape}")
    if (p < 0).any() or (g < 0).any():
        raise InvalidInputError("label maps hold class indices, which cannot be negative")
    classes = np.union1d(np.unique(p), np.unique(g))
    classes = classes[classes != 0]
    if classes.size == 0:
        return PlanIoU(0.0, 0.0)
    inter = np.array([np.count_nonzero((p == k) & (g == k)) for k in classes], dtype=np.float64)
    union = np.array([np.count_nonzero((p == k) | (g == k)) for k in classes], dtype=np.float64)
    return PlanIoU(float(inter.sum() / union.sum()), float(np.mean(inter / union)))
