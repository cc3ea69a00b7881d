"""The pictures the LLM planners look at: a floor outline, and a cut round's parent region.

Small PNGs (a few hundred pixels a side is enough for a model to read the shape and the labels,
and keeps the image tokens cheap), drawn with a bare matplotlib ``Figure`` so the caller's
backend is never touched. Axes carry metre ticks because the model answers in metres.
"""

from __future__ import annotations

import io
from collections.abc import Sequence
from typing import TYPE_CHECKING

from shapely.geometry import Polygon

from mansion.models.footprint import Ring

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = ["outline_png", "region_png"]

Box = tuple[str, str, tuple[float, float], tuple[float, float]]  # (id, type, x, y)


def _ring_patch(ax: Axes, ring: Ring, holes: Sequence[Ring], **style: object) -> None:
    from matplotlib.patches import PathPatch
    from matplotlib.path import Path as MplPath

    verts: list[tuple[float, float]] = []
    codes: list[int] = []
    for r in [ring, *holes]:
        verts += [(float(p[0]), float(p[1])) for p in [*r, r[0]]]
        codes += [int(MplPath.MOVETO)] + [int(MplPath.LINETO)] * (len(r) - 1) + [int(MplPath.CLOSEPOLY)]
    ax.add_patch(PathPatch(MplPath(verts, codes), **style))


def _figure(bounds: tuple[float, float, float, float], title: str) -> tuple[object, Axes]:
    from matplotlib.figure import Figure

    x0, y0, x1, y1 = bounds
    w, h = max(x1 - x0, 1.0), max(y1 - y0, 1.0)
    scale = 6.0 / max(w, h)
    fig = Figure(figsize=(max(2.5, w * scale) + 0.8, max(2.5, h * scale) + 0.8), dpi=90)
    ax = fig.add_subplot(1, 1, 1)
    ax.set_xlim(x0 - 1, x1 + 1)
    ax.set_ylim(y0 - 1, y1 + 1)
    ax.set_aspect("equal")
    ax.grid(True, linewidth=0.3, alpha=0.5)
    ax.set_title(title, fontsize=9)
    ax.tick_params(labelsize=7)
    return fig, ax


def _png(fig: object) -> bytes:
    buf = io.BytesIO()
    fig.savefig(buf, format="png")  # type: ignore[attr-defined]
    return buf.getvalue()


def _cores(ax: Axes, cores: Sequence[Box]) -> None:
    from matplotlib.patches import Rectangle

    for cid, kind, x, y in cores:
        ax.add_patch(
            Rectangle((x[0], y[0]), x[1] - x[0], y[1] - y[0], facecolor="#f2d7a6",
                      edgecolor="#8a5a00", hatch="///", linewidth=1.0)
        )
        ax.text((x[0] + x[1]) / 2, (y[0] + y[1]) / 2, f"{cid}\n({kind})", ha="center",
                va="center", fontsize=6)


def outline_png(outline: Ring, holes: Sequence[Ring] = (), title: str = "ground floor") -> bytes:
    """The floor's boundary (and courtyards) on a metre grid."""
    poly = Polygon(outline, holes)
    fig, ax = _figure(poly.bounds, f"{title}: {poly.area:.0f} m² (x right, y up, metres)")
    _ring_patch(ax, outline, holes, facecolor="#e8eef7", edgecolor="black", linewidth=1.5)
    return _png(fig)


def region_png(
    outline: Ring,
    holes: Sequence[Ring],
    cores: Sequence[Box],
    placed: Sequence[tuple[str, Ring, Sequence[Ring]]],
    region: Ring,
    region_holes: Sequence[Ring],
    parent: str,
) -> bytes:
    """The whole floor: rooms already placed in grey with their ids, the cores hatched, and the
    parent region being cut in blue."""
    poly = Polygon(outline, holes)
    fig, ax = _figure(poly.bounds, f"cutting {parent!r} (blue); metres, x right, y up")
    _ring_patch(ax, outline, holes, facecolor="white", edgecolor="black", linewidth=1.5)
    for rid, ring, rholes in placed:
        _ring_patch(ax, ring, rholes, facecolor="#d9d9d9", edgecolor="#555555", linewidth=0.8)
        c = Polygon(ring, rholes).representative_point()
        ax.text(c.x, c.y, rid, ha="center", va="center", fontsize=6)
    _ring_patch(ax, region, region_holes, facecolor="#9cc3ea", edgecolor="#1f5fa8", linewidth=1.2)
    _cores(ax, cores)
    return _png(fig)
