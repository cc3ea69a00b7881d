"""Drawing a solved floor to PNG or SVG with matplotlib.

Uses a bare ``matplotlib.figure.Figure`` (no pyplot), so it never changes the caller's backend or
opens a window, and works on machines without a display.
"""

from __future__ import annotations

import io
import os
from pathlib import Path
from typing import TYPE_CHECKING

from mansion._io import atomic_write_bytes
from mansion.exceptions import InvalidInputError
from mansion.models import FloorLayout, LayoutRoom

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure
    from shapely.geometry import Point as ShapelyPoint
    from shapely.geometry import Polygon

__all__ = ["draw_layout", "layout_bounds", "plot_layout", "room_label", "save_figure"]

_FORMATS = {".png": "png", ".svg": "svg"}


def room_label(room: LayoutRoom) -> str:
    """The text drawn in a room: its id, its room type when that differs, and its area."""
    lines = [room.id]
    if room.room_type != room.id:
        lines.append(room.room_type)
    lines.append(f"{room.area:.1f} m²")
    return "\n".join(lines)


def _label_point(poly: Polygon) -> ShapelyPoint:
    """A point well inside the room: the centroid when it is about as far from the walls as the
    pole of inaccessibility (so rectangles get centred labels), else that pole (so L- and U-shaped
    rooms keep their labels clear of the walls); point_on_surface if both fail."""
    from shapely.ops import polylabel

    try:
        pole = polylabel(poly, tolerance=0.05)
    except Exception:
        return poly.point_on_surface()
    if not poly.contains(pole):
        return poly.point_on_surface()
    centroid = poly.centroid
    walls = poly.boundary  # outline and holes
    if poly.contains(centroid) and walls.distance(centroid) >= 0.8 * walls.distance(pole):
        return centroid
    return pole


def _draw_room(ax: Axes, room: LayoutRoom, colour: object, points_per_metre: float) -> None:
    from matplotlib.patches import PathPatch
    from matplotlib.path import Path as MplPath
    from shapely.geometry import Polygon
    from shapely.geometry.polygon import orient

    # Outer ring counter-clockwise and holes clockwise, so the fill leaves the holes empty.
    poly = orient(Polygon(room.polygon, room.holes), sign=1.0)
    vertices: list[tuple[float, float]] = []
    codes: list[int] = []  # matplotlib's path codes are small ints
    for ring in (poly.exterior, *poly.interiors):
        coords = list(ring.coords)
        vertices.extend((float(x), float(y)) for x, y in coords)
        codes.extend(
            [int(MplPath.MOVETO)] + [int(MplPath.LINETO)] * (len(coords) - 2) + [int(MplPath.CLOSEPOLY)]
        )
    patch = PathPatch(
        MplPath(vertices, codes),
        facecolor=colour,
        edgecolor="black",
        linewidth=1.2,
        hatch="///" if room.is_core else None,
        zorder=1,
    )
    ax.add_patch(patch)

    anchor = _label_point(poly)
    label = room_label(room)
    lines = label.split("\n")
    # Fit the label to the room's bounding box: ~0.6 em per character, ~1.25 em per line.
    x0, y0, x1, y1 = poly.bounds
    def fit(across: float, along: float) -> float:
        by_width = 0.9 * across * points_per_metre / (0.6 * max(len(line) for line in lines))
        by_height = 0.9 * along * points_per_metre / (1.25 * len(lines))
        return min(by_width, by_height)

    upright, turned = fit(x1 - x0, y1 - y0), fit(y1 - y0, x1 - x0)
    # Tall narrow rooms read better with the label turned a quarter.
    rotation = 90.0 if upright < 7.0 and turned > upright * 1.5 else 0.0
    size = max(4.0, min(10.0, max(upright, turned) if rotation else upright))
    ax.text(
        anchor.x,
        anchor.y,
        label,
        ha="center",
        va="center",
        rotation=rotation,
        fontsize=size,
        zorder=2,
        linespacing=1.1,
        # A light backing keeps the text readable on dark fills and on the cores' hatching.
        bbox={"boxstyle": "round,pad=0.15", "facecolor": "white", "edgecolor": "none", "alpha": 0.6},
    )


def layout_bounds(layout: FloorLayout) -> tuple[float, float, float, float]:
    """(x0, y0, x1, y1) of every room of the layout, in metres."""
    xs = [x for room in layout.rooms for x, _ in room.polygon]
    ys = [y for room in layout.rooms for _, y in room.polygon]
    return min(xs), min(ys), max(xs), max(ys)


def draw_layout(
    ax: Axes,
    layout: FloorLayout,
    points_per_metre: float,
    *,
    title: str | None = None,
    bounds: tuple[float, float, float, float] | None = None,
) -> None:
    """Draw every room of ``layout`` on ``ax`` (labels sized for ``points_per_metre``); axes in
    metres with equal aspect, limited to ``bounds`` (default: the layout's own)."""
    from matplotlib import colormaps

    x0, y0, x1, y1 = bounds or layout_bounds(layout)
    palette = colormaps["tab20"]
    n_colour = 0
    for room in layout.rooms:
        if room.is_core:
            colour: object = (0.82, 0.82, 0.82, 1.0)
        else:
            colour = palette(n_colour % palette.N)
            n_colour += 1
        _draw_room(ax, room, colour, points_per_metre)
    pad = 0.02 * max(x1 - x0, y1 - y0)
    ax.set_xlim(x0 - pad, x1 + pad)
    ax.set_ylim(y0 - pad, y1 + pad)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    if title:
        ax.set_title(title)


def plot_layout(
    layout: FloorLayout, path: str | os.PathLike[str], *, title: str | None = None
) -> Path:
    """Draw ``layout`` to ``path`` (PNG or SVG, chosen by the suffix), atomically.

    Each room is filled with its own colour and outlined, labelled with its id (and room type when
    different) and its area in m² at a point inside the room; cores (stairs, elevators) are
    hatched. Axes are in metres with equal aspect. Returns the path written.
    """
    from matplotlib.figure import Figure

    target = Path(path)
    _format_of(target)
    if not layout.rooms:
        raise InvalidInputError("cannot plot a layout without rooms")

    x0, y0, x1, y1 = layout_bounds(layout)
    width, height = max(x1 - x0, 1e-6), max(y1 - y0, 1e-6)
    fig_w = 10.0
    fig_h = max(3.0, min(14.0, fig_w * height / width + 0.8))
    # Points per metre on paper (equal aspect: the tighter axis sets the scale), to size labels.
    points_per_metre = 72.0 * 0.85 * min(fig_w / width, fig_h / height)

    fig = Figure(figsize=(fig_w, fig_h))
    ax = fig.add_subplot()
    draw_layout(ax, layout, points_per_metre, title=title)
    fig.tight_layout()
    return save_figure(fig, target)


def _format_of(target: Path) -> str:
    fmt = _FORMATS.get(target.suffix.lower())
    if fmt is None:
        raise InvalidInputError(
            f"cannot plot to {str(target)!r}: the file name must end in .png or .svg"
        )
    return fmt


def save_figure(fig: Figure, path: str | os.PathLike[str]) -> Path:
    """Write a matplotlib figure to ``path`` (PNG or SVG by suffix), atomically."""
    target = Path(path)
    fmt = _format_of(target)
    buf = io.BytesIO()
    if fmt == "svg":
        # No timestamp, so the same layout gives the same file.
        fig.savefig(buf, format="svg", metadata={"Date": None})
    else:
        fig.savefig(buf, format="png", dpi=150)
    return atomic_write_bytes(target, buf.getvalue())
