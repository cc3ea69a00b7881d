"""Placement checks computed from geometry alone, independently of the Rust engine: footprints,
the agent's free space on a grid, and its flood fill. ``mansion eval placement`` scores the
engine's output with them and ``mansion validate`` checks written house JSONs with them.

A cell is free when its centre lies in the room, at least the agent's radius from every solid
wall (the outline without its doors and openings) and from every object footprint. The flood
fill is 4-connected, by repeated dilation inside the free cells (numpy).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
import shapely
from numpy.typing import NDArray
from shapely.geometry import LineString, MultiLineString, Polygon

from mansion._grid import row_runs

__all__ = ["PASSAGE_MARGIN", "FreeSpace", "corners_within", "footprint", "passable", "rectangle", "solid_walls"]

#: An agent passes a doorway or opening only if it is this much wider than the agent (m).
PASSAGE_MARGIN = 0.1

Pt = tuple[float, float]
Mask = NDArray[np.bool_]


def footprint(center: Pt, width: float, depth: float, yaw: float) -> Polygon:
    """An object's footprint on the plan (x, y) — the scene's (x, z) — with AI2-THOR's yaw in
    degrees (0 faces +y, 90 faces +x): its corners turned by -yaw about the centre. Computed
    directly rather than by shapely's box, rotate and translate: the same corners to 1e-14 m in a
    fifth of the time (22 against 100 µs; the validator builds one per object)."""
    a = math.radians(-yaw)
    cos, sin = math.cos(a), math.sin(a)
    # as shapely.affinity.rotate does: a quarter turn is exact, not cos = 6e-17
    cos = 0.0 if abs(cos) < 2.5e-16 else cos
    sin = 0.0 if abs(sin) < 2.5e-16 else sin
    cx, cy = center
    hw, hd = width / 2, depth / 2
    # shapely's box order (counter-clockwise from the lower right corner)
    return Polygon([(cos * x - sin * y + cx, sin * x + cos * y + cy)
                    for x, y in ((hw, -hd), (hw, hd), (-hw, hd), (-hw, -hd))])


def passable(width: float, radius: float) -> bool:
    """Whether an agent of ``radius`` gets through a way ``width`` wide: narrower, a doorway or
    opening is no entrance (a gap left where no door asset fitted)."""
    return width >= 2 * radius + PASSAGE_MARGIN - 1e-9


def solid_walls(ring: Sequence[Pt], gaps: Sequence[tuple[Pt, Pt]]) -> MultiLineString:
    """The room's outline without the ``gaps`` (doors and openings, segments of the outline)."""
    solid = LineString([*ring, ring[0]])
    for a, b in gaps:
        solid = solid.difference(LineString([a, b]).buffer(1e-9, cap_style="flat"))
    parts = [g for g in getattr(solid, "geoms", [solid]) if g.length > 0]
    return MultiLineString([list(g.coords) for g in parts])


def _segments(shape: shapely.Geometry) -> NDArray[np.float64]:
    """The straight pieces of a line or polygon's boundary as rows (ax, ay, bx, by)."""
    rows = []
    for part in shapely.get_parts(shapely.boundary(shape) if shape.geom_type.endswith("Polygon") else shape):
        for line in shapely.get_parts(part):
            xy = np.asarray(line.coords)[:, :2]
            if len(xy) > 1:
                rows.append(np.hstack([xy[:-1], xy[1:]]))
    return np.vstack(rows) if rows else np.zeros((0, 4))


Rect = tuple[float, float, float, float, float, float]
#: shapely's type id of a Polygon.
_POLYGON = 3


def rectangle(shape: shapely.Geometry) -> Rect | None:
    """(centre x, y, unit axis x, y, half length, half width) of a rectangle (a footprint), or
    None for any other shape."""
    if shape.geom_type != "Polygon":
        return None
    xy = shapely.get_coordinates(shape)
    if len(xy) != 5:  # four corners and the closing point, no holes
        return None
    return _corners_rectangle(xy[:4].tolist())


def corners_within(rect: Rect, shape: shapely.Geometry, margin: float) -> bool:
    """Whether every point of ``shape`` lies in the rectangle grown by ``margin`` on each side
    (then so does a convex shape, a footprint)."""
    cx, cy, ux, uy, hu, hv = rect
    xy = shapely.get_coordinates(shape)
    dx, dy = xy[:, 0] - cx, xy[:, 1] - cy
    return bool((np.abs(dx * ux + dy * uy) <= hu + margin).all() and (np.abs(dy * ux - dx * uy) <= hv + margin).all())


def _corners_rectangle(corners: list[list[float]]) -> Rect | None:
    """:func:`rectangle` of a polygon's four corners, in ring order."""
    (x0, y0), (x1, y1), (x2, y2), (x3, y3) = corners
    ux, uy, vx, vy = x1 - x0, y1 - y0, x3 - x0, y3 - y0
    lu, lv = math.hypot(ux, uy), math.hypot(vx, vy)
    if (lu <= 0 or lv <= 0 or abs(ux * vx + uy * vy) > 1e-9 * lu * lv
            or abs(x0 + ux + vx - x2) > 1e-9 or abs(y0 + uy + vy - y2) > 1e-9):
        return None
    return (x0 + x2) / 2, (y0 + y2) / 2, ux / lu, uy / lu, lu / 2, lv / 2


def _distance2(rect: Rect, x: NDArray[np.float64], y: NDArray[np.float64]) -> NDArray[np.float64]:
    """Squared distance from the points to the rectangle (0 inside)."""
    cx, cy, ux, uy, hu, hv = rect
    dx, dy = x - cx, y - cy
    a = np.maximum(np.abs(dx * ux + dy * uy) - hu, 0.0)
    b = np.maximum(np.abs(dy * ux - dx * uy) - hv, 0.0)
    return a * a + b * b


def _segment_distance2(seg: NDArray[np.float64] | Sequence[float], x: NDArray[np.float64],
                       y: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Squared distance from the points to the segment (ax, ay, bx, by), and where along it (0 to
    1, unclamped) each point projects."""
    ax, ay, bx, by = seg
    wx, wy = x - ax, y - ay
    dx, dy = bx - ax, by - ay
    n2 = dx * dx + dy * dy
    t = (wx * dx + wy * dy) / n2 if n2 > 0 else np.zeros_like(wx)
    u = np.clip(t, 0.0, 1.0)
    ex, ey = wx - u * dx, wy - u * dy
    return ex * ex + ey * ey, t


def _window(xs: NDArray[np.float64], ys: NDArray[np.float64], bounds: tuple[float, float, float, float],
            pad: float) -> tuple[slice, slice] | None:
    """The grid rows and columns whose centres lie in ``bounds`` grown by ``pad``."""
    x0, y0, x1, y1 = bounds
    i0, i1 = np.searchsorted(ys, y0 - pad), np.searchsorted(ys, y1 + pad, "right")
    j0, j1 = np.searchsorted(xs, x0 - pad), np.searchsorted(xs, x1 + pad, "right")
    return (slice(int(i0), int(i1)), slice(int(j0), int(j1))) if i0 < i1 and j0 < j1 else None


def _solid_segments(ring: Sequence[Pt], gaps: Sequence[tuple[Pt, Pt]]) -> NDArray[np.float64]:
    """:func:`solid_walls` as rows (ax, ay, bx, by), by interval arithmetic along each edge of the
    ring (a gap is a stretch of one edge) rather than shapely differences: 0.7 ms of a room's
    grid otherwise, and the same pieces to 1e-9 m."""
    rows = []
    n = len(ring)
    for k in range(n):
        (ax, ay), (bx, by) = ring[k], ring[(k + 1) % n]
        dx, dy = bx - ax, by - ay
        length = math.hypot(dx, dy)
        if length <= 0:
            continue
        ux, uy = dx / length, dy / length
        pieces = [(0.0, length)]
        for (px, py), (qx, qy) in gaps:
            # on this edge's line (both ends within 1e-9 m of it): its stretch along the edge
            if abs((px - ax) * uy - (py - ay) * ux) > 1e-9 or abs((qx - ax) * uy - (qy - ay) * ux) > 1e-9:
                continue
            s0, s1 = sorted(((px - ax) * ux + (py - ay) * uy, (qx - ax) * ux + (qy - ay) * uy))
            pieces = [part for lo, hi in pieces
                      for part in ((lo, min(hi, s0)), (max(lo, s1), hi)) if part[1] > part[0]]
        rows += [(ax + ux * lo, ay + uy * lo, ax + ux * hi, ay + uy * hi) for lo, hi in pieces]
    return np.asarray(rows, dtype=float).reshape(-1, 4)


def _inside(poly: Polygon, gx: NDArray[np.float64], gy: NDArray[np.float64]) -> Mask:
    """``shapely.contains_xy(poly, gx, gy)`` on the grid ``gx, gy`` (a meshgrid). A polygon
    without holes whose edges are all axis-aligned (every room of ours, and of ProcTHOR's) is
    tested row by row instead: a point is inside when an odd number of the vertical edges that
    span its row lie to its right (the half-open rule counts a vertex once), and never on an
    edge (as a point on the outline is not contained). With axis-aligned edges every crossing
    is an edge's own x, so the answer is exact; 25 times faster on rooms that are no
    rectangle."""
    xy = shapely.get_coordinates(poly)
    if poly.interiors or len(xy) < 4:
        return np.asarray(shapely.contains_xy(poly, gx, gy))
    a, b = xy[:-1], xy[1:]
    vertical, horizontal = a[:, 0] == b[:, 0], a[:, 1] == b[:, 1]
    if not (vertical | horizontal).all():
        return np.asarray(shapely.contains_xy(poly, gx, gy))
    xs, ys = gx[0], gy[:, 0]
    inside = np.zeros(gx.shape, dtype=bool)
    edge = np.zeros(gx.shape, dtype=bool)
    for (ax, ay), (bx, by), upright in zip(a.tolist(), b.tolist(), vertical.tolist(), strict=True):
        lo, hi = (ay, by) if ay < by else (by, ay)
        if upright:
            if lo == hi:
                continue  # a repeated point
            rows = np.flatnonzero((ys >= lo) & (ys < hi))  # (ay > y) != (by > y)
            inside[rows] ^= xs < ax
            edge[np.flatnonzero((ys >= lo) & (ys <= hi)), :] |= xs == ax
        else:
            left, right = (ax, bx) if ax < bx else (bx, ax)
            edge[ys == ay, :] |= (xs >= left) & (xs <= right)
    return inside & ~edge


def _near_segments(gx: NDArray[np.float64], gy: NDArray[np.float64], segments: NDArray[np.float64],
                   radius: float) -> Mask:
    """Which grid points lie closer than ``radius`` to one of the segments (rows ax, ay, bx, by)."""
    near = np.zeros(gx.shape, dtype=bool)
    if not len(segments):
        return near
    xs, ys = gx[0], gy[:, 0]
    r = radius - 1e-12
    # every segment's window of the grid (as :func:`_window`) in four calls
    lo = np.minimum(segments[:, :2], segments[:, 2:])
    hi = np.maximum(segments[:, :2], segments[:, 2:])
    i0, i1 = np.searchsorted(ys, lo[:, 1] - r).tolist(), np.searchsorted(ys, hi[:, 1] + r, "right").tolist()
    j0, j1 = np.searchsorted(xs, lo[:, 0] - r).tolist(), np.searchsorted(xs, hi[:, 0] + r, "right").tolist()
    for k, seg in enumerate(segments):
        if i0[k] < i1[k] and j0[k] < j1[k]:
            win = (slice(i0[k], i1[k]), slice(j0[k], j1[k]))
            near[win] |= _segment_distance2(seg, gx[win], gy[win])[0] < r * r
    return near


def _blocked(gx: NDArray[np.float64], gy: NDArray[np.float64], shapes: Sequence[shapely.Geometry],
             radius: float) -> Mask:
    """Which grid points lie closer than ``radius`` to one of the shapes (inside a polygon
    counts). Measured with numpy in each shape's window of the grid (one formula for a
    rectangle, one per edge for other shapes) rather than by a prepared shapely ``dwithin`` per
    point over the shapes' union: the validator's rooms of a seven-storey hospital build their
    grids about four times faster (12 → 3 ms a room), cell for cell the same."""
    near = np.zeros(gx.shape, dtype=bool)
    xs, ys = gx[0], gy[:, 0]
    r = radius - 1e-12
    r2 = r * r
    # every shape's kind, points and box read in one call each (a room holds dozens)
    shapes = np.asarray(shapes, dtype=object)
    kinds = shapely.get_type_id(shapes).tolist()
    counts = shapely.get_num_coordinates(shapes).tolist()
    coords = shapely.get_coordinates(shapes).tolist()
    boxes = shapely.bounds(shapes).tolist()
    first = 0
    for shape, kind, count, bounds in zip(shapes, kinds, counts, boxes, strict=True):
        at, first = first, first + count
        if count == 0:  # empty
            continue
        # a polygon of four corners and the closing point has no holes
        rect = _corners_rectangle(coords[at:at + 4]) if kind == _POLYGON and count == 5 else None
        if rect is not None:
            win = _window(xs, ys, bounds, r)
            if win is not None:
                near[win] |= _distance2(rect, gx[win], gy[win]) < r2
            continue
        near |= _near_segments(gx, gy, _segments(shape), radius)
        if shape.geom_type.endswith("Polygon"):
            win = _window(xs, ys, bounds, 0.0)
            if win is not None:
                near[win] |= shapely.contains_xy(shape, gx[win], gy[win])
    return near


@dataclass
class FreeSpace:
    """The agent's free space in one room on a grid of ``cell`` metres."""

    px: NDArray[np.float64]
    py: NDArray[np.float64]
    shape: tuple[int, int]
    open: Mask  # inside the room and clear of the solid walls
    free: Mask  # open and clear of every object
    #: the runs of ``free`` (False) and ``open`` (True) along rows and columns, numbered by the
    #: first flood of each (the masks are read, never changed)
    _numbered: dict[bool, tuple[tuple[NDArray[np.int64], int], tuple[NDArray[np.int64], int]]] = field(
        default_factory=dict, repr=False, compare=False)

    @classmethod
    def build(
        cls, ring: Sequence[Pt], gaps: Sequence[tuple[Pt, Pt]], obstacles: Sequence[Polygon],
        radius: float, cell: float = 0.05,
    ) -> FreeSpace:
        poly = Polygon(ring)
        x0, y0, x1, y1 = poly.bounds
        w, h = max(1, math.ceil((x1 - x0) / cell)), max(1, math.ceil((y1 - y0) / cell))
        gx, gy = np.meshgrid(x0 + (np.arange(w) + 0.5) * cell, y0 + (np.arange(h) + 0.5) * cell)
        open_ = _inside(poly, gx, gy) & ~_near_segments(gx, gy, _solid_segments(ring, gaps), radius)
        free = open_ & ~_blocked(gx, gy, obstacles, radius) if obstacles else open_.copy()
        return cls(gx.ravel(), gy.ravel(), (h, w), open_.ravel(), free.ravel())

    def in_front_of(self, a: Pt, b: Pt, reach: float) -> Mask:
        """Cells within ``reach`` of the segment a–b whose projection falls on it: where an
        agent stands just inside a door or opening."""
        out = self._around(LineString([a, b]), reach)
        k = np.flatnonzero(out)
        d2, t = _segment_distance2((a[0], a[1], b[0], b[1]), self.px[k], self.py[k])
        out[k] = (d2 < reach * reach) & (t >= 0.0) & (t <= 1.0)
        return out

    def _around(self, shape: Polygon | LineString, dist: float) -> Mask:
        """Cells within ``dist`` of the shape's bounding box: the only ones worth measuring."""
        x0, y0, x1, y1 = shape.bounds
        return np.asarray((self.px > x0 - dist) & (self.px < x1 + dist)
                          & (self.py > y0 - dist) & (self.py < y1 + dist))

    def flood(self, seeds: Mask, empty: bool = False) -> Mask:
        """The free cells 4-connected to the free ``seeds`` (with ``empty``, the open cells: the
        room as if it held no object)."""
        free = (self.open if empty else self.free).reshape(self.shape)
        reached = seeds.reshape(self.shape) & free
        # Alternate sweeps along rows and columns: each marks every run of free cells that holds
        # a reached cell, so a path needs one sweep per turn, not one step per cell. A sweep
        # that adds nothing ends it: the other direction's sweep, just done, is closed already.
        # The runs depend on the mask alone: numbered once per mask, for every flood of it.
        if empty not in self._numbered:
            (rows, n_rows), (columns, n_columns) = _runs(free), _runs(free.T)
            self._numbered[empty] = ((rows, n_rows), (columns.T, n_columns))
        (rows, n_rows), (columns, n_columns) = self._numbered[empty]
        reached = _spread(reached, rows, n_rows)
        count, along_rows = int(np.count_nonzero(reached)), False
        while True:
            reached = _spread(reached, rows, n_rows) if along_rows else _spread(reached, columns, n_columns)
            now = int(np.count_nonzero(reached))
            if now == count:
                return reached.ravel()
            count, along_rows = now, not along_rows

    def reaches(
        self, reached: Mask, fp: Polygon, reach: float,
        front: tuple[Pt, float, float] | None = None,
    ) -> bool:
        """Whether a reached cell lies within ``reach`` of the footprint; with ``front`` (the
        object's centre, yaw and depth) only cells on its front side count."""
        return self.reaches_each(reached, [fp], reach, [front])[0]

    def reaches_each(
        self, reached: Mask, fps: Sequence[Polygon], reach: float,
        fronts: Sequence[tuple[Pt, float, float] | None] | None = None,
    ) -> list[bool]:
        """:meth:`reaches` of each footprint (with its front, when ``fronts`` are given): the
        footprints' kinds, points and boxes read, and their windows of the grid found, in one
        call each (a room holds dozens of objects)."""
        h, w = self.shape
        xs, ys = self.px[:w], self.py[::w]
        gx, gy, grid = self.px.reshape(h, w), self.py.reshape(h, w), reached.reshape(h, w)
        shapes = np.asarray(fps, dtype=object)
        kinds = shapely.get_type_id(shapes).tolist()
        counts = shapely.get_num_coordinates(shapes).tolist()
        coords = shapely.get_coordinates(shapes).tolist()
        boxes = shapely.bounds(shapes).reshape(-1, 4)
        # the rows and columns whose centres lie within ``reach`` of each box (as _window)
        i0 = np.searchsorted(ys, boxes[:, 1] - reach).tolist()
        i1 = np.searchsorted(ys, boxes[:, 3] + reach, "right").tolist()
        j0 = np.searchsorted(xs, boxes[:, 0] - reach).tolist()
        j1 = np.searchsorted(xs, boxes[:, 2] + reach, "right").tolist()
        out: list[bool] = []
        first = 0
        for n, fp in enumerate(fps):
            at, first = first, first + counts[n]
            if counts[n] == 0 or i0[n] >= i1[n] or j0[n] >= j1[n]:
                out.append(False)
                continue
            win = (slice(i0[n], i1[n]), slice(j0[n], j1[n]))
            k = np.nonzero(grid[win])
            x, y = gx[win][k], gy[win][k]
            rect = _corners_rectangle(coords[at:at + 4]) if kinds[n] == _POLYGON and counts[n] == 5 else None
            if rect is not None:
                near = _distance2(rect, x, y) < reach * reach
            else:
                near = shapely.distance(shapely.points(x, y), fp) < reach
            front = fronts[n] if fronts is not None else None
            if front is not None and near.any():
                (cx, cy), yaw, depth = front
                fx, fy = math.sin(math.radians(yaw)), math.cos(math.radians(yaw))
                near &= (x - cx) * fx + (y - cy) * fy >= depth / 2 - 1e-9
            out.append(bool(near.any()))
        return out


def _runs(free: Mask) -> tuple[NDArray[np.int64], int]:
    """Each free cell's run along its row (axis 1), numbered from 1 (0: not free), and the
    number of runs."""
    return row_runs(free)


def _spread(reached: Mask, runs: NDArray[np.int64], count: int) -> Mask:
    """Every run (numbered as by :func:`_runs`) that holds a reached cell, all reached."""
    hit = np.zeros(count + 1, dtype=bool)
    hit[runs[reached]] = True
    hit[0] = False
    return np.asarray(hit[runs])