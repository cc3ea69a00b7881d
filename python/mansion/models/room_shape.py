"""Measures of one room's polygon, in metres (issue 14): how much of it is narrower than a
width, whether it holds a square, how elongated its box is. ``mansion eval realism`` counts rooms
with them, and the building stage uses the same measures to judge a floor's layout, so the two
never disagree."""

from __future__ import annotations

import functools

import shapely
from shapely.geometry.base import BaseGeometry

__all__ = [
    "EPS", "SHARE_EPS", "TOLERANCE", "box_aspect", "fits_square", "mostly_narrower", "narrow_share", "opening",
]

#: Share of a room's area that may be narrower than a limit before the room is flagged.
TOLERANCE = 0.10
#: Rounding noise of the areas compared with :data:`TOLERANCE`: a room with exactly a tenth of
#: its area narrow (2 cells of 20) is not "more than 10 %".
SHARE_EPS = 1e-9

#: A millimetre: a room exactly 1 m wide holds a 1 m square.
EPS = 1e-3


def _half(width: float, inclusive: bool) -> float:
    """Half of ``width``, a millimetre over when parts exactly ``width`` wide count as narrow
    (``inclusive``), a millimetre under when they do not."""
    return width / 2 + (EPS if inclusive else -EPS)


def opening(shape: BaseGeometry, width: float, inclusive: bool = False) -> BaseGeometry:
    """Morphological opening with a ``width`` square: what of ``shape`` a square of that side,
    moved around inside it, can cover (mitred buffers keep orthogonal corners square)."""
    r = _half(width, inclusive)
    return shape.buffer(-r, join_style="mitre").buffer(r, join_style="mitre")


def _wide_box(shape: BaseGeometry, width: float) -> bool:
    """Whether ``shape`` is an axis-aligned rectangle at least a little over ``width`` each way:
    then a square of that side covers all of it, told without buffering (most rooms are)."""
    x0, y0, x1, y1 = shape.bounds
    return (
        min(x1 - x0, y1 - y0) >= width + 2 * EPS and shape.geom_type == "Polygon"
        and not shape.interiors and abs(shape.area - (x1 - x0) * (y1 - y0)) < 1e-9
    )


def narrow_share(shape: BaseGeometry, width: float, inclusive: bool = False) -> float:
    """Share of ``shape``'s area in parts narrower than ``width`` (``inclusive``: or exactly
    that wide); 0 for an empty shape."""
    if shape.area <= 0 or _wide_box(shape, width):
        return 0.0
    return _narrow_share(shape.wkb, width, inclusive)


@functools.lru_cache(maxsize=1 << 16)
def _narrow_share(wkb: bytes, width: float, inclusive: bool) -> float:
    """:func:`narrow_share` of the shape ``wkb`` holds. The floor's mends judge the same rooms
    again and again (every room of a floor after each merge, recut or hand-off, most of them
    unchanged), and the opening is the dearest measure: cached by the shape's exact bytes."""
    shape = shapely.from_wkb(wkb)
    kept = opening(shape, width, inclusive).intersection(shape).area
    return max(0.0, 1.0 - kept / shape.area)


def mostly_narrower(shape: BaseGeometry, width: float, inclusive: bool = False) -> bool:
    """More than :data:`TOLERANCE` of ``shape``'s area in parts narrower than ``width``
    (``inclusive``: or exactly that wide): a sliver at 1 m, a room below its type's clear width."""
    return narrow_share(shape, width, inclusive) > TOLERANCE + SHARE_EPS


def fits_square(shape: BaseGeometry, side: float, inclusive: bool = False) -> bool:
    """True when a ``side`` × ``side`` axis-aligned square (``inclusive``: a hair larger) fits
    inside ``shape``."""
    if _wide_box(shape, side):
        return True
    return _fits_square(shape.wkb, side, inclusive)


@functools.lru_cache(maxsize=1 << 16)
def _fits_square(wkb: bytes, side: float, inclusive: bool) -> bool:
    """:func:`fits_square` of the shape ``wkb`` holds, cached as :func:`_narrow_share` is."""
    return not shapely.from_wkb(wkb).buffer(-_half(side, inclusive), join_style="mitre").is_empty


def box_aspect(shape: BaseGeometry) -> float:
    """Longest side of the axis-aligned bounding box over its shortest."""
    x0, y0, x1, y1 = shape.bounds
    short = min(x1 - x0, y1 - y0)
    return float("inf") if short <= 0 else max(x1 - x0, y1 - y0) / short
