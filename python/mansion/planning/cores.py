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
from collections.abc import Mapping, Sequence

from shapely.geometry import Polygon, box
from shapely.geometry.base import BaseGeometry

from mansion.exceptions import PlannerError
from mansion.models.building import BuildingCore
from mansion.planning.footprints import Outline

__all__ = ["CoreRequest", "core_problem", "place_cores"]

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


def _served(outlines: Sequence[Outline], floors_served: Sequence[int]) -> tuple[list[Polygon], int]:
    served = [Polygon(outlines[f][0], outlines[f][1]) for f in floors_served]
    smallest = min(floors_served, key=lambda f: Polygon(outlines[f][0], outlines[f][1]).area)
    return served, smallest


def _core_box(core: BuildingCore) -> Polygon:
    return box(core.x[0], core.y[0], core.x[1], core.y[1])


def core_problem(
    core: BuildingCore,
    size: tuple[int, int],
    outlines: Sequence[Outline],
    placed: Sequence[BuildingCore] = (),
) -> str | None:
    """Why ``core`` (proposed by someone else, e.g. an LLM) cannot stand where it is, or None.

    The same rules :func:`place_cores` follows: whole-metre coordinates, the size asked for (either
    way round), a corner of the smallest served outline bounded by two exterior walls, inside every
    floor it serves, clear of the ``placed`` cores, and leaving each free region one piece with no
    sliver narrower than 2 m.
    """
    where = f"{core.type} core {core.id!r} at x={list(core.x)}, y={list(core.y)}"
    if any(t != round(t) for t in (*core.x, *core.y)):
        return f"{where}: coordinates must be whole metres"
    w, d = core.x[1] - core.x[0], core.y[1] - core.y[0]
    if {round(w), round(d)} != set(size) or w * d != size[0] * size[1]:
        return f"{where}: the box is {w:g} x {d:g} m, it must be {size[0]} x {size[1]} m"
    served, smallest = _served(outlines, core.floors)
    candidate = _core_box(core)
    corners = {
        _box_at(p, u, v, a, b).bounds
        for p, u, v in _convex_corners(outlines[smallest][0])
        for a, b in (size, size[::-1])
    }
    if candidate.bounds not in corners:
        return f"{where}: not in a corner of floor {smallest}'s outline bounded by two exterior walls"
    if not _fits(candidate, served, [_core_box(c) for c in placed]):
        return (
            f"{where}: outside a floor it serves, overlapping another core, or cutting the free "
            "area into pieces or slivers narrower than 2 m"
        )
    return None


def place_cores(
    outlines: Sequence[Outline],
    requests: Sequence[CoreRequest],
    floors_served: Sequence[int],
    rng: random.Random,
    *,
    placed_cores: Sequence[BuildingCore] = (),
    near: Mapping[str, tuple[float, float]] | None = None,
) -> list[BuildingCore]:
    """Place each requested core (in order) so that it serves ``floors_served``.

    Stairs after the first go to the corner farthest from the cores placed so far (escape routes
    apart); elevators to the nearest free corner (a lift beside the main stair). A core with a
    point in ``near`` goes to the fitting position closest to it instead (where an LLM wanted it).
    ``placed_cores`` are already standing and must be kept clear of. Raises
    :class:`PlannerError` naming the core when no position fits.
    """
    served, smallest = _served(outlines, floors_served)
    corners = _convex_corners(outlines[smallest][0])
    rng.shuffle(corners)
    placed: list[Polygon] = [_core_box(c) for c in placed_cores]
    cores: list[BuildingCore] = []
    for cid, kind, (w, d) in requests:
        options = []
        for p, u, v in corners:
            for a, b in ((w, d), (d, w)):
                options.append(_box_at(p, u, v, a, b))
        if near is not None and cid in near:
            target = near[cid]
            options.sort(key=lambda g: math.dist((g.centroid.x, g.centroid.y), target))
        elif placed:
            centre = [(g.centroid.x, g.centroid.y) for g in placed]

            def dist(g: Polygon) -> float:
                return min(math.dist((g.centroid.x, g.centroid.y), c) for c in centre)

            options.sort(key=dist, reverse=(kind == "stair"))
        if placed:
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
