"""Rooms as rectangles, laid out from what a description says: seeds from a small continuous solve.

:func:`mansion.planning.spatial_seeds.place_seeds` moves one point per room over the free cells.
A point cannot say where a room's *walls* are, and the text mostly speaks of walls: a room "in the
northeast corner" has its north and east walls on the plan's; "with the common room to the south"
puts the common room's north wall against this room's south wall; the plan's adjacency makes two
rooms share a wall; and the rooms tile the floor without overlapping. :func:`layout_rectangles`
makes each room a rectangle of its target area (its shape free between 1:4 and 4:1, drawn toward a
stated width and depth) and moves all of them at once by gradient descent on:

- *position*: the edge(s) of the room named by a compass word on the free region's matching
  edge(s); "centre": the room's centre on the region's;
- *relation*: "A north of B": A's centre at least ``gap`` half-sizes north of B's, and (due
  north) the two overlapping east-west; "next to"/"across from" and the plan's adjacency: the
  two boxes touching;
- *overlap*: the overlapping area of every pair of boxes;
- *inside*: the squared distance from the free region of sample points of each box (a box of a
  room on an L-shaped plan's notch stays in the notch, not across it).

The overlap weight grows over the iterations, so rooms first find their places through one
another and then settle apart. The hub (the largest room, which wraps around the others and is a
poor rectangle) takes part with a box of half its area; its seed is then the middle of what the
other boxes leave. Seeds are the boxes' centres moved to the nearest free cell. Pure numpy,
deterministic (no randomness).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

from mansion.exceptions import InvalidInputError
from mansion.planning.spatial_language import DIRECTIONS, Reading
from mansion.planning.spatial_seeds import FreeGrid, SeedRoom

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

__all__ = ["LayoutWeights", "RoomBox", "layout_rectangles", "rectangle_seeds"]


@dataclass(frozen=True)
class LayoutWeights:
    """Weights of :func:`layout_rectangles`' terms (costs in cells²)."""

    position: float = 2.0
    corner: float = 3.0
    centre: float = 0.3
    exterior: float = 0.3
    relation: float = 1.0
    #: how far apart a relation wants the two centres, in the sum of their half-sizes
    gap: float = 0.8
    touch: float = 0.5
    adjacency: float = 0.5
    overlap: float = 1.0
    inside: float = 4.0
    #: the pull of a box's shape toward the stated width : depth (log-aspect, squared)
    shape: float = 2.0
    #: the hub's box has this share of its area
    hub_area: float = 0.5
    iterations: int = 400
    step: float = 0.5


@dataclass(frozen=True)
class RoomBox:
    """A solved room box in cells of the free grid (x right, y up): centre and half sizes."""

    id: str
    cx: float
    cy: float
    hx: float
    hy: float


def _outside_distance(mask: npt.NDArray[np.bool_]) -> npt.NDArray[np.float64]:
    """Distance (cells) from each cell's centre to the nearest free cell's centre (0 on free)."""
    import numpy as np

    rr, cc = np.nonzero(mask)
    R, C = np.indices(mask.shape)
    d2 = np.full(mask.shape, np.inf)
    # chunks of free cells keep the memory small on a 64 × 64 grid
    for k in range(0, rr.size, 256):
        d2 = np.minimum(d2, ((R[..., None] - rr[k : k + 256]) ** 2 + (C[..., None] - cc[k : k + 256]) ** 2).min(axis=-1))
    return np.sqrt(d2)


def _walls(mask: npt.NDArray[np.bool_]) -> dict[tuple[int, int], npt.NDArray[np.float64]]:
    """The free region's outer walls: (axis, sign) → per row or column of the other axis, the
    coordinate of its last free cell's outer edge in that direction (NaN where none is free)."""
    import numpy as np

    H, W = mask.shape
    out: dict[tuple[int, int], npt.NDArray[np.float64]] = {}
    any_c, any_r = mask.any(axis=0), mask.any(axis=1)
    cols_lo = np.where(any_c, np.argmax(mask, axis=0), np.nan)
    cols_hi = np.where(any_c, H - np.argmax(mask[::-1], axis=0), np.nan)
    rows_lo = np.where(any_r, np.argmax(mask, axis=1), np.nan)
    rows_hi = np.where(any_r, W - np.argmax(mask[:, ::-1], axis=1), np.nan)
    out[(1, -1)], out[(1, 1)] = cols_lo.astype(float), cols_hi.astype(float)  # south/north per column
    out[(0, -1)], out[(0, 1)] = rows_lo.astype(float), rows_hi.astype(float)  # west/east per row
    return out


def _wall(
    walls: dict[tuple[int, int], npt.NDArray[np.float64]], axis: int, sign: int,
    centre: npt.NDArray[np.float64], half: npt.NDArray[np.float64], default: float,
) -> float:
    """Where a room's wall on side (axis, sign) meets the region's: the region's outer edge on
    that side along the room's span of the other axis, the innermost of it so the whole wall
    fits (a room "in the southwest corner" of an L-shaped plan sits in the notch's corner)."""
    import numpy as np

    line = walls[(axis, sign)]
    other = 1 - axis
    a = max(int(np.floor(centre[other] - half[other] + 0.5)), 0)
    b = min(int(np.ceil(centre[other] + half[other] - 0.5)), line.size - 1)
    span = line[a : b + 1] if b >= a else line[min(max(int(centre[other]), 0), line.size - 1)][None]
    span = span[~np.isnan(span)]
    if span.size == 0:
        return default
    return float(np.median(span))


def _stated_aspect(statements: Iterable) -> float:
    """log(width / depth) the text states for a room (0 when it states none)."""
    for s in statements:
        if s.kind == "size" and s.width and s.depth:
            return math.log(min(max(s.width / s.depth, 0.25), 4.0))
    return 0.0


def layout_rectangles(
    reading: Reading,
    rooms: Sequence[SeedRoom],
    free: FreeGrid,
    adjacency: Iterable[tuple[str, str]] = (),
    *,
    start: dict[str, tuple[float, float]] | None = None,
    weights: LayoutWeights | None = None,
) -> list[RoomBox]:
    """One box per room (in ``rooms`` order), in cells of ``free`` (x right, y up, origin at the
    grid's corner). ``start`` (room id → point in ``free``'s frame) is where the centres begin;
    without it each room begins where its compass words put it (the region's centre otherwise)."""
    import numpy as np

    if not rooms:
        raise InvalidInputError("no rooms to lay out")
    w = weights or LayoutWeights()
    mask = np.asarray(free.mask, dtype=bool)
    n = len(rooms)
    ids = [r.id for r in rooms]
    index = {rid: k for k, rid in enumerate(ids)}
    rr, cc = np.nonzero(mask)
    x0, x1 = float(cc.min()), float(cc.max() + 1)
    y0, y1 = float(rr.min()), float(rr.max() + 1)
    mid = np.array([(x0 + x1) / 2, (y0 + y1) / 2])
    lo = np.array([x0, y0])
    hi = np.array([x1, y1])
    outside = _outside_distance(mask)

    hub = max(range(n), key=lambda k: rooms[k].area)
    area = np.array([max(r.area / free.cell**2, 1.0) for r in rooms])
    area[hub] *= w.hub_area
    about = {rid: reading.about(rid) for rid in ids}
    aspect0 = np.array([_stated_aspect(about[rid]) for rid in ids])
    has_shape = np.array([any(s.kind == "size" and s.width and s.depth for s in about[rid]) for rid in ids])

    # unary targets: (room, axis, sign, weight); sign 0 = the centre on the region's middle
    unary: list[tuple[int, int, int, float]] = []
    for k, rid in enumerate(ids):
        for s in about[rid]:
            if s.kind not in ("position", "exterior") or not s.direction:
                continue
            dx, dy = DIRECTIONS[s.direction]
            if s.direction == "centre":
                unary += [(k, 0, 0, w.centre), (k, 1, 0, w.centre)]
                continue
            wt = w.exterior if s.kind == "exterior" else w.corner if dx and dy else w.position
            if dx:
                unary.append((k, 0, dx, wt))
            if dy:
                unary.append((k, 1, dy, wt))
    # pairwise: touch (i, j, weight) and order (i, j, ux, uy, weight)
    touch: list[tuple[int, int, float]] = []
    order: list[tuple[int, int, int, int, float]] = []
    for rid in ids:
        for s in about[rid]:
            if s.kind != "relation":
                continue
            js = [index[o] for o in (reading.resolved.get(m.key) for m in s.others) if o in index and o != rid]
            i = index[rid]
            if s.relation in ("next_to", "between", "across_from"):
                touch += [(i, j, w.touch) for j in js]
            elif s.relation and s.relation.endswith("_of") and s.relation[:-3] in DIRECTIONS:
                ux, uy = DIRECTIONS[s.relation[:-3]]
                order += [(i, j, ux, uy, w.relation) for j in js]
    for a, b in adjacency:
        if a in index and b in index and a != b:
            touch.append((index[a], index[b], w.adjacency))

    # start
    c = np.tile(mid, (n, 1))
    for k, t_axis, sign, _ in unary:
        if sign:
            c[k, t_axis] = (mid[t_axis] + (hi[t_axis] if sign > 0 else lo[t_axis])) / 2
    if start:
        for rid, (px, py) in start.items():
            if rid in index:
                c[index[rid]] = ((px - free.origin[0]) / free.cell, (py - free.origin[1]) / free.cell)
    s = np.where(has_shape, aspect0, 0.0) * 0.5
    s_lim = math.log(4.0)

    iu, ju = np.triu_indices(n, 1)
    t_i = np.array([t[0] for t in touch], dtype=int)
    t_j = np.array([t[1] for t in touch], dtype=int)
    t_w = np.array([t[2] for t in touch])
    o_i = np.array([o[0] for o in order], dtype=int)
    o_j = np.array([o[1] for o in order], dtype=int)
    o_u = np.array([(o[2], o[3]) for o in order], dtype=float).reshape(-1, 2)
    o_w = np.array([o[4] for o in order])
    u_k = np.array([u[0] for u in unary], dtype=int)
    u_a = np.array([u[1] for u in unary], dtype=int)
    u_s = np.array([u[2] for u in unary], dtype=float)
    u_w = np.array([u[3] for u in unary])
    grid = np.array([-0.75, -0.25, 0.25, 0.75])
    su = np.stack(np.meshgrid(grid, grid), -1).reshape(-1, 2)  # sample offsets in half-sizes
    gy_, gx_ = np.gradient(outside)
    walls = _walls(mask)
    H, W = mask.shape

    m1 = np.zeros(c.shape)
    v1 = np.zeros(c.shape)
    ms = np.zeros(n)
    vs = np.zeros(n)
    for it in range(w.iterations):
        half = np.stack([np.sqrt(area * np.exp(s)) / 2, np.sqrt(area * np.exp(-s)) / 2], 1)
        gc = np.zeros_like(c)
        gh = np.zeros_like(half)
        ramp = min(1.0, 0.1 + it / (0.6 * w.iterations))
        # positions: the named edge on the region's edge
        if u_k.size:
            cu = c[u_k, u_a]
            hu = half[u_k, u_a]
            edge = np.where(u_s > 0, cu + hu, np.where(u_s < 0, cu - hu, cu))
            target = np.where(u_s > 0, hi[u_a], np.where(u_s < 0, lo[u_a], mid[u_a]))
            for t in range(u_k.size):
                if u_s[t]:
                    target[t] = _wall(walls, u_a[t], int(u_s[t]), c[u_k[t]], half[u_k[t]], target[t])
            r = edge - target
            # moves the room only: its shape is the text's and the region's business
            np.add.at(gc, (u_k, u_a), 2 * u_w * r)
        # inside the bounding box of the free region
        over_hi = np.maximum(0.0, c + half - hi)
        over_lo = np.maximum(0.0, lo - (c - half))
        gc += 2 * w.inside * (over_hi - over_lo)
        gh += 2 * w.inside * (over_hi + over_lo)
        # inside the free region: sample points' distance to it
        px = c[:, None, 0] + half[:, None, 0] * su[None, :, 0]
        py = c[:, None, 1] + half[:, None, 1] * su[None, :, 1]
        ci = np.clip(np.floor(px).astype(int), 0, W - 1)
        ri = np.clip(np.floor(py).astype(int), 0, H - 1)
        d = outside[ri, ci]
        dgx, dgy = gx_[ri, ci], gy_[ri, ci]
        fx = 2 * w.inside * d * dgx / su.shape[0]
        fy = 2 * w.inside * d * dgy / su.shape[0]
        gc[:, 0] += fx.sum(1)
        gc[:, 1] += fy.sum(1)
        gh[:, 0] += (fx * su[None, :, 0]).sum(1)
        gh[:, 1] += (fy * su[None, :, 1]).sum(1)
        # overlap of every pair: area of the intersection
        if iu.size:
            dxy = c[iu] - c[ju]
            ov = half[iu] + half[ju] - np.abs(dxy)
            on = (ov[:, 0] > 0) & (ov[:, 1] > 0)
            if on.any():
                a, b, o, dd = iu[on], ju[on], ov[on], dxy[on]
                sg = np.sign(dd) + (dd == 0) * 1.0
                wo = w.overlap * ramp
                g_ax = wo * o[:, 1]  # d(area)/d(ov_x)
                g_ay = wo * o[:, 0]
                np.add.at(gc[:, 0], a, -g_ax * sg[:, 0])
                np.add.at(gc[:, 0], b, g_ax * sg[:, 0])
                np.add.at(gc[:, 1], a, -g_ay * sg[:, 1])
                np.add.at(gc[:, 1], b, g_ay * sg[:, 1])
                for m in (a, b):
                    np.add.at(gh[:, 0], m, g_ax)
                    np.add.at(gh[:, 1], m, g_ay)
        # touching: the gap between the two boxes on each axis
        if t_i.size:
            dxy = c[t_i] - c[t_j]
            gap = np.abs(dxy) - half[t_i] - half[t_j]
            r = np.maximum(0.0, gap)
            g = 2 * t_w[:, None] * r
            sg = np.sign(dxy)
            np.add.at(gc, t_i, g * sg)
            np.add.at(gc, t_j, -g * sg)
        # ordering: i's centre at least gap half-sizes beyond j's along the named direction
        if o_i.size:
            dxy = c[o_i] - c[o_j]
            need = w.gap * (half[o_i] + half[o_j])
            short = np.where(o_u != 0, np.maximum(0.0, need - o_u * dxy), 0.0)
            g = 2 * o_w[:, None] * short * -o_u
            # due north/south (east/west): overlapping on the other axis
            side = np.where(o_u == 0, np.maximum(0.0, np.abs(dxy) - half[o_i] - half[o_j]), 0.0)
            g2 = 0.5 * o_w[:, None] * side * np.sign(dxy)
            np.add.at(gc, o_i, g + g2)
            np.add.at(gc, o_j, -g - g2)
        # shape: d/ds of the half sizes, and the pull toward the stated aspect (or square)
        gs = gh[:, 0] * half[:, 0] / 2 - gh[:, 1] * half[:, 1] / 2
        gs += 2 * w.shape * (s - np.where(has_shape, aspect0, 0.0)) * np.where(has_shape, 1.0, 0.5)
        # Adam steps: scale-free in the terms' weights, the step in cells
        lr = w.step * (1.0 - 0.9 * it / w.iterations)
        m1 = 0.8 * m1 + 0.2 * gc
        v1 = 0.95 * v1 + 0.05 * gc * gc
        c = c - lr * m1 / (np.sqrt(v1) + 1e-6)
        ms = 0.8 * ms + 0.2 * gs
        vs = 0.95 * vs + 0.05 * gs * gs
        s = np.clip(s - 0.1 * lr * ms / (np.sqrt(vs) + 1e-6), -s_lim, s_lim)
        c = np.clip(c, lo, hi)
    half = np.stack([np.sqrt(area * np.exp(s)) / 2, np.sqrt(area * np.exp(-s)) / 2], 1)
    return [RoomBox(rid, float(c[k, 0]), float(c[k, 1]), float(half[k, 0]), float(half[k, 1])) for k, rid in enumerate(ids)]


def rectangle_seeds(
    reading: Reading,
    rooms: Sequence[SeedRoom],
    free: FreeGrid,
    adjacency: Iterable[tuple[str, str]] = (),
    *,
    start: dict[str, tuple[float, float]] | None = None,
    weights: LayoutWeights | None = None,
) -> dict[str, tuple[float, float]]:
    """Seeds (room id → point in ``free``'s frame, always on a free cell) from
    :func:`layout_rectangles`: each box's centre, the hub's the middle of what the others leave."""
    import numpy as np

    boxes = layout_rectangles(reading, rooms, free, adjacency, start=start, weights=weights)
    mask = np.asarray(free.mask, dtype=bool)
    rr, cc = np.nonzero(mask)
    X, Y = cc + 0.5, rr + 0.5
    hub = max(range(len(rooms)), key=lambda k: rooms[k].area)
    taken = np.zeros(X.size, dtype=bool)
    points: dict[str, int] = {}
    for k, b in enumerate(boxes):
        if k == hub:
            continue
        d2 = (X - b.cx) ** 2 + (Y - b.cy) ** 2 + np.where(taken, 1e6, 0.0)
        points[b.id] = int(np.argmin(d2))
        taken[points[b.id]] = True
    # the hub: the middle of the free cells outside every other (full-size) box
    covered = taken.copy()
    for k, b in enumerate(boxes):
        if k != hub:
            covered |= (np.abs(X - b.cx) < b.hx) & (np.abs(Y - b.cy) < b.hy)
    rest = ~covered if (~covered).any() else ~taken
    lx, ly = X[rest].mean(), Y[rest].mean()
    points[boxes[hub].id] = int(np.argmin((X - lx) ** 2 + (Y - ly) ** 2 + np.where(rest, 0.0, 1e6)))
    return {
        rid: (free.origin[0] + float(X[points[rid]]) * free.cell, free.origin[1] + float(Y[points[rid]]) * free.cell)
        for rid in (r.id for r in rooms)
    }
