"""A floor's navigation grid, built from its house JSON alone.

A cell (``cell`` metres, 0.1 by default) is free when its centre lies in a room that is not a
stair or elevator core, at least the agent's radius from every solid stretch of wall (walls minus
the holes of open doors; a closed door's hole is solid; empty walls are openings) and from every
floor object's footprint (the asset's bounding box turned by its rotation). Everything is
rasterised with numpy, segment by segment and object by object, so a 500 m² floor builds in a
few tens of milliseconds.

Shortest paths are breadth-first over the 8-connected free cells, frontier by frontier with
numpy (one BFS from the agent serves every target on the floor); the cell path is then pulled
taut along lines of sight, and its length in metres is what the skills count.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import shapely
from numpy.typing import NDArray
from shapely.geometry import Polygon

from mansion.scene.house import House

__all__ = ["CELL", "NavGrid", "Path"]

#: Grid cell size (m).
CELL = 0.1

Pt = tuple[float, float]
_OFFSETS_RC = ((0, 1), (0, -1), (1, 0), (-1, 0), (1, 1), (1, -1), (-1, 1), (-1, -1))


@dataclass(frozen=True)
class Path:
    """A walk on the floor: the taut polyline from start to goal and its length (m)."""

    points: tuple[Pt, ...]
    length: float


def _segment_distance(px: NDArray[np.float64], pz: NDArray[np.float64], a: Pt, b: Pt) -> NDArray[np.float64]:
    dx, dz = b[0] - a[0], b[1] - a[1]
    n2 = dx * dx + dz * dz
    if n2 <= 0.0:
        return np.hypot(px - a[0], pz - a[1])
    t = np.clip(((px - a[0]) * dx + (pz - a[1]) * dz) / n2, 0.0, 1.0)
    return np.hypot(px - (a[0] + t * dx), pz - (a[1] + t * dz))


def box_distance(px: NDArray[np.float64], pz: NDArray[np.float64], centre: Pt, width: float,
                 depth: float, yaw: float) -> NDArray[np.float64]:
    """Distance from points to an object's footprint: a ``width`` × ``depth`` box at ``centre``
    turned by AI2-THOR's yaw (degrees, 0 faces +z)."""
    t = math.radians(yaw)
    c, s = math.cos(t), math.sin(t)
    rx, rz = px - centre[0], pz - centre[1]
    # the box's local axes: width along (cos, -sin), depth along (sin, cos)
    lx = rx * c - rz * s
    lz = rx * s + rz * c
    ex = np.maximum(np.abs(lx) - width / 2, 0.0)
    ez = np.maximum(np.abs(lz) - depth / 2, 0.0)
    return np.hypot(ex, ez)


@dataclass
class NavGrid:
    """The free cells of one floor and the room of every cell."""

    origin: Pt
    cell: float
    shape: tuple[int, int]  # rows (z), columns (x)
    room_ids: list[str]
    label: NDArray[np.int16]  # room index per cell, -1 outside every room
    walls_ok: NDArray[np.bool_]  # inside a walkable room and clear of solid walls
    free: NDArray[np.bool_]  # and clear of every floor object
    radius: float
    _dist_cache: dict[tuple[int, int], NDArray[np.int32]] = field(default_factory=dict, repr=False)

    # -- building -------------------------------------------------------------------------------
    @classmethod
    def build(
        cls, house: House, radius: float, *, objects: list[tuple[Pt, float, float, float]],
        closed_doors: set[str], cores: set[str], cell: float = CELL,
    ) -> NavGrid:
        """``objects``: floor footprints as (centre, width, depth, yaw); ``closed_doors``: ids of
        doors whose hole is shut; ``cores``: rooms the agent does not walk into."""
        polys = {r.id: [(p.x, p.z) for p in r.floor_polygon] for r in house.rooms}
        xs = [x for ring in polys.values() for x, _ in ring]
        zs = [z for ring in polys.values() for _, z in ring]
        x0, z0 = min(xs) - 2 * cell, min(zs) - 2 * cell
        w = max(1, math.ceil((max(xs) - x0) / cell) + 2)
        h = max(1, math.ceil((max(zs) - z0) / cell) + 2)
        gx = x0 + (np.arange(w) + 0.5) * cell
        gz = z0 + (np.arange(h) + 0.5) * cell
        label = np.full((h, w), -1, dtype=np.int16)
        room_ids = list(polys)
        for k, rid in enumerate(room_ids):
            ring = polys[rid]
            rx = [p[0] for p in ring]
            rz = [p[1] for p in ring]
            c0, c1 = np.searchsorted(gx, min(rx)), np.searchsorted(gx, max(rx))
            r0, r1 = np.searchsorted(gz, min(rz)), np.searchsorted(gz, max(rz))
            if c1 <= c0 or r1 <= r0:
                continue
            mx, mz = np.meshgrid(gx[c0:c1], gz[r0:r1])
            inside = shapely.contains_xy(Polygon(ring), mx, mz)
            sub = label[r0:r1, c0:c1]
            sub[inside] = k
        walk = np.zeros((h, w), dtype=bool)
        for k, rid in enumerate(room_ids):
            if rid not in cores:
                walk |= label == k
        walls_ok = walk.copy()
        for a, b in _solid_segments(house, closed_doors):
            _clear_near(walls_ok, gx, gz, radius, lambda px, pz, a=a, b=b: _segment_distance(px, pz, a, b),
                        (min(a[0], b[0]), min(a[1], b[1]), max(a[0], b[0]), max(a[1], b[1])))
        free = walls_ok.copy()
        for centre, width, depth, yaw in objects:
            half = math.hypot(width, depth) / 2
            bbox = (centre[0] - half, centre[1] - half, centre[0] + half, centre[1] + half)
            _clear_near(free, gx, gz, radius,
                        lambda px, pz, c=centre, wd=width, dp=depth, y=yaw: box_distance(px, pz, c, wd, dp, y), bbox)
        return cls((x0, z0), cell, (h, w), room_ids, label, walls_ok, free, radius)

    # -- coordinates ----------------------------------------------------------------------------
    def cell_of(self, x: float, z: float) -> tuple[int, int]:
        c = int(math.floor((x - self.origin[0]) / self.cell))
        r = int(math.floor((z - self.origin[1]) / self.cell))
        return (min(max(r, 0), self.shape[0] - 1), min(max(c, 0), self.shape[1] - 1))

    def centre(self, rc: tuple[int, int]) -> Pt:
        return (self.origin[0] + (rc[1] + 0.5) * self.cell, self.origin[1] + (rc[0] + 0.5) * self.cell)

    def centres(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """x and z of every cell centre, as (rows, columns) arrays."""
        gx = self.origin[0] + (np.arange(self.shape[1]) + 0.5) * self.cell
        gz = self.origin[1] + (np.arange(self.shape[0]) + 0.5) * self.cell
        return np.broadcast_to(gx, self.shape), np.broadcast_to(gz[:, None], self.shape)

    def room_at(self, x: float, z: float) -> str | None:
        k = int(self.label[self.cell_of(x, z)])
        return self.room_ids[k] if k >= 0 else None

    def snap(self, x: float, z: float, within: float = 0.5) -> tuple[int, int] | None:
        """The free cell nearest (x, z), if one lies within ``within`` metres."""
        rc = self.cell_of(x, z)
        if self.free[rc]:
            return rc
        n = int(math.ceil(within / self.cell))
        r0, c0 = max(rc[0] - n, 0), max(rc[1] - n, 0)
        sub = self.free[r0:rc[0] + n + 1, c0:rc[1] + n + 1]
        rr, cc = np.nonzero(sub)
        if rr.size == 0:
            return None
        px = self.origin[0] + (cc + c0 + 0.5) * self.cell
        pz = self.origin[1] + (rr + r0 + 0.5) * self.cell
        d = np.hypot(px - x, pz - z)
        k = int(np.argmin(d))
        if d[k] > within:
            return None
        return (int(rr[k] + r0), int(cc[k] + c0))

    # -- search ---------------------------------------------------------------------------------
    def distances(self, start: tuple[int, int]) -> NDArray[np.int32]:
        """BFS steps from ``start`` to every free cell (-1: not reached), cached per start."""
        hit = self._dist_cache.get(start)
        if hit is not None:
            return hit
        h, w = self.shape
        wp = w + 2
        padded = np.zeros((h + 2, wp), dtype=bool)
        padded[1:-1, 1:-1] = self.free
        flat = padded.ravel()
        dist = np.full(flat.size, -1, dtype=np.int32)
        s = (start[0] + 1) * wp + start[1] + 1
        if flat[s]:
            dist[s] = 0
            offsets = np.array([dr * wp + dc for dr, dc in _OFFSETS_RC], dtype=np.int64)
            frontier = np.array([s], dtype=np.int64)
            d = 0
            while frontier.size:
                d += 1
                nb = (frontier[:, None] + offsets).ravel()
                nb = nb[flat[nb] & (dist[nb] < 0)]
                nb = np.unique(nb)
                dist[nb] = d
                frontier = nb
        out = dist.reshape(h + 2, wp)[1:-1, 1:-1].copy()
        if len(self._dist_cache) > 16:
            self._dist_cache.clear()
        self._dist_cache[start] = out
        return out

    def path(self, start: tuple[int, int], goal: tuple[int, int]) -> Path | None:
        """The shortest walk from ``start`` to ``goal`` (free cells), pulled taut; None when
        the goal is not reached."""
        dist = self.distances(start)
        if dist[goal] < 0:
            return None
        cells = [goal]
        r, c = goal
        h, w = self.shape
        while dist[r, c] > 0:
            want = dist[r, c] - 1
            for dr, dc in _OFFSETS_RC:  # straight moves first: fewer kinks to pull taut
                rr, cc = r + dr, c + dc
                if 0 <= rr < h and 0 <= cc < w and dist[rr, cc] == want:
                    r, c = rr, cc
                    break
            cells.append((r, c))
        cells.reverse()
        pts = self._taut(cells)
        length = sum(math.dist(a, b) for a, b in zip(pts, pts[1:]))
        return Path(tuple(pts), length)

    def visible(self, a: Pt, b: Pt, mask: NDArray[np.bool_] | None = None) -> bool:
        """Whether the straight line a→b stays on ``mask`` (the free cells by default)."""
        m = self.free if mask is None else mask
        n = max(2, int(math.dist(a, b) / (self.cell * 0.5)) + 2)
        t = np.linspace(0.0, 1.0, n)
        xs = a[0] + (b[0] - a[0]) * t
        zs = a[1] + (b[1] - a[1]) * t
        c = np.clip(np.floor((xs - self.origin[0]) / self.cell).astype(np.int64), 0, self.shape[1] - 1)
        r = np.clip(np.floor((zs - self.origin[1]) / self.cell).astype(np.int64), 0, self.shape[0] - 1)
        return bool(m[r, c].all())

    def _taut(self, cells: list[tuple[int, int]]) -> list[Pt]:
        pts = [self.centre(rc) for rc in cells]
        if len(pts) <= 2:
            return pts
        out = [pts[0]]
        i = 0
        while i < len(pts) - 1:
            # the farthest point still in sight, found by doubling then bisecting
            step, j = 1, i + 1
            while i + step * 2 < len(pts) and self.visible(pts[i], pts[i + step * 2]):
                step *= 2
            lo, hi = i + step, min(i + step * 2, len(pts) - 1)
            j = lo
            while lo <= hi:
                mid = (lo + hi) // 2
                if self.visible(pts[i], pts[mid]):
                    j, lo = mid, mid + 1
                else:
                    hi = mid - 1
            out.append(pts[j])
            i = j
        return out


def _clear_near(mask: NDArray[np.bool_], gx: NDArray[Any], gz: NDArray[Any], radius: float,
                distance: object, bbox: tuple[float, float, float, float]) -> None:
    """Mark cells of ``mask`` closer than ``radius`` to a shape (given by its distance function
    and bounding box) as blocked."""
    x0, z0, x1, z1 = bbox
    c0, c1 = np.searchsorted(gx, x0 - radius), np.searchsorted(gx, x1 + radius)
    r0, r1 = np.searchsorted(gz, z0 - radius), np.searchsorted(gz, z1 + radius)
    if c1 <= c0 or r1 <= r0:
        return
    px, pz = np.meshgrid(gx[c0:c1], gz[r0:r1])
    near = distance(px, pz) < radius  # type: ignore[operator]
    mask[r0:r1, c0:c1] &= ~near


def _solid_segments(house: House, closed_doors: set[str]) -> list[tuple[Pt, Pt]]:
    """Every stretch of solid wall: each wall pair once, minus the holes of open doors."""
    holes: dict[str, list[tuple[float, float]]] = {}
    walls = {w.id: w for w in house.walls}
    for door in house.doors:
        if door.id in closed_doors:
            continue
        lo, hi = door.hole_polygon[0].x, door.hole_polygon[1].x
        holes.setdefault(door.wall0, []).append((lo, hi))
        w1 = walls.get(door.wall1)
        if w1 is not None:
            (a, b) = w1.segment()
            n = math.dist(a, b)
            holes.setdefault(door.wall1, []).append((n - hi, n - lo))
    out: list[tuple[Pt, Pt]] = []
    seen: set[tuple[Pt, Pt]] = set()
    for wall in house.walls:
        if wall.empty:
            continue
        a, b = wall.segment()
        n = math.dist(a, b)
        if n <= 1e-9:
            continue
        spans = [(0.0, n)]
        for lo, hi in holes.get(wall.id, []):
            nxt = []
            for s0, s1 in spans:
                if hi <= s0 or lo >= s1:
                    nxt.append((s0, s1))
                    continue
                if lo > s0:
                    nxt.append((s0, lo))
                if hi < s1:
                    nxt.append((hi, s1))
            spans = nxt
        ux, uz = (b[0] - a[0]) / n, (b[1] - a[1]) / n
        for s0, s1 in spans:
            p = (round(a[0] + ux * s0, 4), round(a[1] + uz * s0, 4))
            q = (round(a[0] + ux * s1, 4), round(a[1] + uz * s1, 4))
            key = (min(p, q), max(p, q))
            if key not in seen:
                seen.add(key)
                out.append((p, q))
    return out
