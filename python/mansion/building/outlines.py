"""Rooms' outlines as shapely polygons, and the measures of them the floor's mends ask of the same
rooms again and again (issue 14): whether a room is unfit or below its clear width. Both are
cached by the outline's coordinates, so a room no mend moved is neither drawn nor measured again."""

from __future__ import annotations

from shapely.geometry import Polygon

from mansion.building.merge import USABLE_SIDE
from mansion.models.layout import LayoutRoom
from mansion.models.room_shape import EPS, fits_square, mostly_narrower

__all__ = ["outline", "shape_measure"]

#: Rooms' shapes measured by :func:`shape_measure`, at most (then the cache starts afresh): the
#: mends and the floors laid out again ask of the same rooms again and again (the two took 2.6 s
#: of the hundred's 35 s, measuring shapely outlines).
SHAPES_CACHE = 1 << 12
_SHAPES: dict[tuple[object, ...], str | bool] = {}
#: Rooms' outlines drawn by :func:`outline`, at most (then the cache starts afresh): drawing a
#: shapely polygon took a tenth of the mends' time, most of it for rooms drawn before.
OUTLINES_CACHE = 1 << 12
_OUTLINES: dict[tuple[object, ...], Polygon] = {}


def _coords(room: LayoutRoom) -> tuple[object, ...]:
    """``room``'s outline and holes as tuples: the caches' key."""
    return tuple(room.polygon), tuple(tuple(h) for h in room.holes)


def outline(room: LayoutRoom, coords: tuple[object, ...] | None = None) -> Polygon:
    """``room``'s outline (with its holes) as a shapely polygon, cached by its coordinates
    (``coords``: :func:`_coords` of it, where the caller has them). Shapely's polygons do not
    change, so one may serve every caller."""
    key = _coords(room) if coords is None else coords
    found = _OUTLINES.get(key)
    if found is None:
        if len(_OUTLINES) >= OUTLINES_CACHE:
            _OUTLINES.clear()
        found = _OUTLINES[key] = Polygon(room.polygon, room.holes)
    return found


def shape_measure(room: LayoutRoom, what: tuple[str, object]) -> str | bool:
    """The why of :func:`mansion.building.steps.unfit_rooms` (``("unfit", min_area)``; "" for a
    fit room) or whether the room is below its clear width (``("narrow", width)``, room_shape's
    :func:`~mansion.models.room_shape.mostly_narrower`) of ``room``'s outline, cached by the
    outline."""
    coords = _coords(room)
    key = (what, *coords)
    found = _SHAPES.get(key)
    if found is None:
        if len(_SHAPES) >= SHAPES_CACHE:
            _SHAPES.clear()
        shape = outline(room, coords)
        kind, value = what
        if kind == "narrow":
            found = mostly_narrower(shape, value)  # type: ignore[arg-type]
        elif value is not None and shape.area < value - EPS:  # type: ignore[operator]
            found = f"laid out at {shape.area:.1f} m², below its {value:g} m² minimum"
        elif not fits_square(shape, USABLE_SIDE, inclusive=True):
            found = f"laid out with no usable {USABLE_SIDE:g} m square"
        else:
            found = ""
        _SHAPES[key] = found
    return found
