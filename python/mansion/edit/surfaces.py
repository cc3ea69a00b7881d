"""What lies on a receptacle and what inside it, and where one more object fits.

Everything comes from the house JSON and the assets' axis-aligned bounding boxes: an object rests
*on* a receptacle when its bottom is at the receptacle's top (within a settling tolerance), *in*
it when its bottom is lower (a fridge's or a shelf's inside). A new object is packed in 2D on the
top (or on the floor of the inside box, inset by the container's walls): candidate spots on a
fine grid of the receptacle's own frame, nearest its centre first, in the receptacle's heading or
turned a quarter, keeping a gap to the boxes of what is already there. Its ``y`` follows from
the surface, so the box rests on it, as ``mansion validate`` checks.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from mansion.placement.check import footprint
from mansion.sim.world import ObjectInfo, Props

__all__ = ["Slot", "area_free", "contents", "fit", "on_top"]

#: An object whose bottom is this far below the top or less rests on it (m).
SETTLE = 0.02
#: Gap kept between packed objects, and from the top's edge (m).
GAP = 0.02
#: A container's walls: its inside is its box inset by this on every side (m).
WALL = 0.05
#: Grid step of the candidate spots (m).
STEP = 0.02


@dataclass(frozen=True)
class Slot:
    x: float
    y: float
    z: float
    yaw: float


def _top(rec: ObjectInfo) -> float:
    return rec.obj.position.y + rec.props.height / 2


def _bottom(info: ObjectInfo) -> float:
    return info.obj.position.y - info.props.height / 2


def on_top(rec: ObjectInfo, others: list[ObjectInfo]) -> list[ObjectInfo]:
    """What rests on the receptacle's top: its children whose bottom is at the top, and other
    objects of the floor standing on it by their boxes (a footprint over the top, the bottom at
    its height)."""
    top = _top(rec)
    fp = footprint(rec.centre, rec.props.width, rec.props.depth, rec.obj.rotation.y)
    out = []
    for o in others:
        if o.id == rec.id:
            continue
        b = _bottom(o)
        if o.parent == rec.id:
            if b >= top - SETTLE:
                out.append(o)
        elif o.parent is None and top - SETTLE <= b <= top + 0.05:
            if footprint(o.centre, o.props.width, o.props.depth, o.obj.rotation.y).intersects(fp):
                out.append(o)
    return sorted(out, key=lambda o: o.id)


def contents(rec: ObjectInfo, others: list[ObjectInfo]) -> list[ObjectInfo]:
    """What lies inside the receptacle: its children whose bottom is below its top."""
    top = _top(rec)
    return sorted((o for o in others if o.parent == rec.id and _bottom(o) < top - SETTLE), key=lambda o: o.id)


def _local_box(rec: ObjectInfo, o: ObjectInfo) -> tuple[float, float, float, float]:
    """``o``'s footprint in the receptacle's frame (u along its width, v along its depth), as
    the bounds of its turned box (the inverse of the turn ``footprint`` applies)."""
    t = math.radians(rec.obj.rotation.y)
    dx, dz = o.centre[0] - rec.centre[0], o.centre[1] - rec.centre[1]
    u = dx * math.cos(t) - dz * math.sin(t)
    v = dx * math.sin(t) + dz * math.cos(t)
    r = math.radians(o.obj.rotation.y - rec.obj.rotation.y)
    c, s = abs(math.cos(r)), abs(math.sin(r))
    hu = c * o.props.width / 2 + s * o.props.depth / 2
    hv = s * o.props.width / 2 + c * o.props.depth / 2
    return (u - hu, v - hv, u + hu, v + hv)


def fit(rec: ObjectInfo, item: Props, taken: list[ObjectInfo], inside: bool) -> Slot | None:
    """Where ``item`` fits on the receptacle's top (``inside``: on the floor of its inside box)
    without overlapping ``taken``: the free spot nearest the centre, or None."""
    p = rec.props
    inset = WALL if inside else GAP
    half_w, half_d = p.width / 2 - inset, p.depth / 2 - inset
    if inside and item.height > p.height - 2 * WALL:
        return None
    boxes = np.array([_local_box(rec, o) for o in taken]).reshape(-1, 4)
    best: tuple[float, float, float, float] | None = None
    for turn in (0.0, 90.0):
        w, d = (item.width, item.depth) if turn == 0.0 else (item.depth, item.width)
        if w / 2 > half_w or d / 2 > half_d:
            continue
        us = _axis(half_w - w / 2)
        vs = _axis(half_d - d / 2)
        u, v = np.meshgrid(us, vs, indexing="ij")
        u, v = u.ravel(), v.ravel()
        x0, z0, x1, z1 = (boxes[:, i][None, :] for i in range(4))
        hit = ((u[:, None] - w / 2 < x1 + GAP) & (u[:, None] + w / 2 > x0 - GAP)
               & (v[:, None] - d / 2 < z1 + GAP) & (v[:, None] + d / 2 > z0 - GAP))
        ok = ~hit.any(axis=1)
        if not ok.any():
            continue
        r = np.where(ok, np.hypot(u, v), np.inf)
        k = int(np.argmin(r))
        # the quarter turn only when it gets nearer the centre
        if best is None or r[k] < best[0] - 1e-9:
            best = (float(r[k]), float(u[k]), float(v[k]), turn)
    if best is None:
        return None
    _, u0, v0, turn = best
    t = math.radians(rec.obj.rotation.y)
    x = rec.centre[0] + u0 * math.cos(t) + v0 * math.sin(t)
    z = rec.centre[1] - u0 * math.sin(t) + v0 * math.cos(t)
    base = rec.obj.position.y - p.height / 2 + WALL if inside else _top(rec)
    return Slot(round(x, 4), round(base + item.height / 2 + 1e-3, 4), round(z, 4), (rec.obj.rotation.y + turn) % 360.0)


def _axis(half: float) -> np.ndarray:
    """Candidate offsets from -half to half, symmetric about 0 (so the centre is a candidate)."""
    n = int(math.floor(half / STEP + 1e-9))
    return np.arange(-n, n + 1) * STEP


def area_free(rec: ObjectInfo, taken: list[ObjectInfo]) -> float:
    """The top's area not under ``taken`` (m², an estimate from the boxes)."""
    used = sum(min(o.props.width * o.props.depth, rec.props.width * rec.props.depth) for o in taken)
    return max(rec.props.width * rec.props.depth - used, 0.0)

