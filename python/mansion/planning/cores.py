"""Placing vertical cores: boxes in corners bounded by two exterior walls, the same on every floor.

The paper's building planner puts each stair and elevator in a corner of the outline bounded by two
exterior walls, with whole-metre coordinates, and keeps the box identical on every floor the core
serves. A core serving several floors must therefore lie inside every one of their outlines: the
corners are taken from the smallest (topmost) served outline and checked against all the others.
A box is accepted only if every served floor's free region stays one piece with no sliver
narrower than 2 m beside it, which keeps the floors solvable. When the corners run out (more
cores than corners), a core goes beside an already placed one along the same exterior wall.
"""

from __future__ import annotations

import math
import random
from collections.abc import Sequence

from shapely.geometry import Polygon, box
from shapely.geometry.base import BaseGeometry

from mansion.exceptions import PlannerError
from mansion.models.building import BuildingCore
from mansion.planning.footprints import Outline

__all__ = ["CoreRequest", "place_cores"]

CoreRequest = tuple[str, str, tuple[int, int]]  # (id, type, (width, depth)) in whole metres


def _convex_corners(ring: Sequence[tuple[float, float]]) -> list[tuple[tuple[float, float], tuple[int, int], tuple[int, int]]]:
    """Convex vertices of a counter-clockwise orthogonal ring with the unit directions of the two
    walls leaving them (into the building along each wall)."""
    n = len(ring)
    out = []
    for i in range(n):
        p, a, b = ring[i], ring[i - 1], ring[(i + 1) % n]
        d_in = (p[0] - a[0], p[1] - a[1])
        d_out = (b[0] - p[0], b[1] - p[1])
        cross = d_in[0] * d_out[1] - d_in[1] * d_out[0]
        if cross > 0:  # a left turn on a counter-clockwise ring: convex
            u = (int(math.copysign(1, d_out[0])) if d_out[0] else 0, int(math.copysign(1, d_out[1])) if d_out[1] else 0)
            v = (-int(math.copysign(1, d_in[0])) if d_in[0] else 0, -int(math.copysign(1, d_in[1])) if d_in[1] else 0)
            out.append((p, u, v))
    return out


def _box_at(p: tuple[float, float], u: tuple[int, int], v: tuple[int, int], a: int, b: int) -> Polygon:
    qx = p[0] + u[0] * a + v[0] * b
    qy = p[1] + u[1] * a + v[1] * b
    return box(min(p[0], qx), min(p[1], qy), max(p[0], qx), max(p[1], qy))


def _fits(candidate: Polygon, floors: list[Polygon], placed: list[Polygon]) -> bool:
    for fl in floors:
        if not candidate.within(fl):
            return False
        free: BaseGeometry = fl.difference(candidate)
        for other in placed:
            if other.intersection(candidate).area > 1e-9:
                return False
            free = free.difference(other)
        if free.geom_type != "Polygon":
            return False
        # Slivers narrower than 2 m beside the core would leave rooms no solver can draw.
        if free.buffer(-1.0, join_style="mitre").buffer(1.0, join_style="mitre").area < free.area - 1e-6:
            return False
    return True


def place_cores(
    outlines: Sequence[Outline],
    requests: Sequence[CoreRequest],
    floors_served: Sequence[int],
    rng: random.Random,
) -> list[BuildingCore]:
    """Place each requested core (in order) so that it serves ``floors_served``.

    Stairs after the first go to the corner farthest from the cores placed so far (escape routes
    apart); elevators to the nearest free corner (a lift beside the main stair). Raises
    :class:`PlannerError` naming the core when no position fits.
    """
    served = [Polygon(outlines[f][0], outlines[f][1]) for f in floors_served]
    smallest = min(floors_served, key=lambda f: Polygon(outlines[f][0], outlines[f][1]).area)
    corners = _convex_corners(outlines[smallest][0])
    rng.shuffle(corners)
    placed: list[Polygon] = []
    cores: list[BuildingCore] = []
    for cid, kind, (w, d) in requests:
        options = []
        for p, u, v in corners:
            for a, b in ((w, d), (d, w)):
                options.append(_box_at(p, u, v, a, b))
        if placed:
            centre = [(g.centroid.x, g.centroid.y) for g in placed]

            def dist(g: Polygon) -> float:
                return min(math.dist((g.centroid.x, g.centroid.y), c) for c in centre)

            options.sort(key=dist, reverse=(kind == "stair"))
            # Beside a placed core along an exterior wall, for when the corners are used up.
            for g in placed:
                x0, y0, x1, y1 = (int(t) for t in g.bounds)
                for a, b in ((w, d), (d, w)):
                    options += [
                        box(x1, y0, x1 + a, y0 + b), box(x0 - a, y0, x0, y0 + b),
                        box(x0, y1, x0 + a, y1 + b), box(x0, y0 - b, x0 + a, y0),
                        box(x1, y1 - b, x1 + a, y1), box(x0 - a, y1 - b, x0, y1),
                        box(x1 - a, y1, x1, y1 + b), box(x1 - a, y0 - b, x1, y0),
                    ]
        chosen = next((c for c in options if _fits(c, served, placed)), None)
        if chosen is None:
            raise PlannerError(
                f"cannot place {kind} core {cid!r} ({w} × {d} m) in a corner of the outline "
                f"serving floors {list(floors_served)}; the outline is too small or too narrow"
            )
        placed.append(chosen)
        x0, y0, x1, y1 = chosen.bounds
        cores.append(
            BuildingCore(
                id=cid, type=kind,  # type: ignore[arg-type]
                x=(float(x0), float(x1)), y=(float(y0), float(y1)), floors=list(floors_served),
            )
        )
    return cores
