"""Mesh primitives in metres, y up: boxes and prisms (a plane polygon with holes, extruded).

A polygon is triangulated with shapely's constrained Delaunay triangulation (GEOS), so slabs
with openings and walls with door and window holes need no extra triangulation library. Faces
wind counter-clockwise seen from outside, so normals point out of the solid.
"""

from __future__ import annotations

import numpy as np
import shapely
from shapely.geometry import MultiPolygon, Polygon
from shapely.geometry.polygon import orient

__all__ = ["Mesh", "box", "merge", "prism", "transformed"]

#: vertices (n × 3 float) and triangles (m × 3 int).
Mesh = tuple[np.ndarray, np.ndarray]

# The 8 corners of the unit cube and its 12 outward-wound triangles.
_CUBE_V = np.array(
    [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], float
)
_CUBE_F = np.array(
    [[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4],
     [3, 7, 6], [3, 6, 2], [0, 4, 7], [0, 7, 3], [1, 2, 6], [1, 6, 5]], np.int64
)


def box(lo: tuple[float, float, float], hi: tuple[float, float, float]) -> Mesh:
    """An axis-aligned box from corner ``lo`` to corner ``hi``."""
    lo_a, hi_a = np.asarray(lo, float), np.asarray(hi, float)
    return lo_a + _CUBE_V * (hi_a - lo_a), _CUBE_F.copy()


def transformed(mesh: Mesh, matrix: np.ndarray) -> Mesh:
    """``mesh`` under a 4 × 4 affine ``matrix``; a mirroring matrix flips the winding back."""
    v, f = mesh
    out = v @ matrix[:3, :3].T + matrix[:3, 3]
    if np.linalg.det(matrix[:3, :3]) < 0:
        f = f[:, ::-1]
    return out, f


def merge(meshes: list[Mesh]) -> Mesh:
    """One mesh of several (vertex indices shifted)."""
    vs, fs, n = [], [], 0
    for v, f in meshes:
        vs.append(v)
        fs.append(f + n)
        n += len(v)
    if not vs:
        return np.zeros((0, 3)), np.zeros((0, 3), np.int64)
    return np.vstack(vs), np.vstack(fs)


def _cross2(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
    return (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])


def _prism_one(poly: Polygon, t0: float, t1: float) -> Mesh:
    poly = orient(poly, sign=1.0)  # exterior counter-clockwise, holes clockwise
    tris = shapely.get_parts(shapely.constrained_delaunay_triangles(poly))
    # Each triangle's first three ring points, as (m, 3, 2).
    corners = np.array([np.asarray(t.exterior.coords)[:3] for t in tris], float).reshape(-1, 3, 2)
    ccw = _cross2(corners[:, 0], corners[:, 1], corners[:, 2]) > 0
    corners[ccw] = corners[ccw][:, ::-1]  # now clockwise in (a, b)
    m = len(corners)
    flat = corners.reshape(-1, 2)

    def lift(ab: np.ndarray, t: float) -> np.ndarray:
        # Plane coordinates (a, b) → (a, t, b): the prism rises along the second axis.
        return np.column_stack([ab[:, 0], np.full(len(ab), t), ab[:, 1]])

    # In (a, t, b) space a triangle clockwise in (a, b) faces +t; so the top cap keeps the
    # clockwise order and the bottom cap reverses it.
    top_v, top_f = lift(flat, t1), np.arange(3 * m).reshape(-1, 3)
    bot_v, bot_f = lift(flat, t0), np.arange(3 * m).reshape(-1, 3)[:, ::-1]
    sides = []
    for ring in [poly.exterior, *poly.interiors]:
        pts = np.asarray(ring.coords)[:-1]
        q = np.roll(pts, -1, axis=0)
        k = len(pts)
        v = np.vstack([lift(pts, t0), lift(q, t0), lift(q, t1), lift(pts, t1)])
        i = np.arange(k)
        # Quad p0 q0 q1 p1: (p0, q1, q0) and (p0, p1, q1) face the right of p→q, i.e. outward
        # for a counter-clockwise exterior and into the hole for a clockwise hole ring.
        f = np.vstack([np.column_stack([i, 2 * k + i, k + i]), np.column_stack([i, 3 * k + i, 2 * k + i])])
        sides.append((v, f))
    return merge([(top_v, top_f), (bot_v, bot_f), *sides])


def prism(shape: Polygon | MultiPolygon, t0: float, t1: float) -> Mesh:
    """``shape`` in the (a, b) plane extruded from t0 to t1, as points (a, t, b).

    So a floor polygon in (x, z) extrudes straight to a slab in (x, y, z); walls map (a, t, b)
    to their own frame with :func:`transformed`.
    """
    parts = [p for p in getattr(shape, "geoms", [shape]) if isinstance(p, Polygon) and not p.is_empty and p.area > 1e-9]
    return merge([_prism_one(p, t0, t1) for p in parts])
