"""Synthesising orthogonal floor outlines sized to an area, and how they change with height.

Shapes: rectangle, L, U, T and courtyard (a ring around a open court). Every coordinate is a
whole metre, so outlines, cores and carried walls all lie on the solver's grid lines for any cell
size that divides 1 m. Stacks: ``uniform`` (every floor the same), ``setback`` (the top floors
lose a strip), ``podium`` (a tower on a wider base), ``garage`` (a ground floor with a protruding
garage). Upper outlines always lie inside the floor below.
"""

from __future__ import annotations

import math
import random

from shapely.geometry import Polygon, box
from shapely.geometry.polygon import orient

from mansion.exceptions import PlannerError
from mansion.models.footprint import Ring

__all__ = ["Outline", "shape_outline", "stack_outlines"]

#: (outer ring, holes): one floor's outline.
Outline = tuple[Ring, list[Ring]]


def _ring(poly: Polygon) -> Ring:
    # simplify(0) drops collinear vertices that unions and differences leave behind.
    coords = list(orient(poly.simplify(0), sign=1.0).exterior.coords)[:-1]
    return [(float(round(x)), float(round(y))) for x, y in coords]


def _transform(poly: Polygon, rng: random.Random) -> Polygon:
    """A random mirror / quarter turn, moved back to the origin: same shape, other orientation."""
    from shapely import affinity

    if rng.random() < 0.5:
        poly = affinity.scale(poly, -1, 1, origin=(0, 0))
    if rng.random() < 0.5:
        poly = affinity.scale(poly, 1, -1, origin=(0, 0))
    if rng.random() < 0.5:
        poly = affinity.rotate(poly, 90, origin=(0, 0))
    x0, y0, _, _ = poly.bounds
    return affinity.translate(poly, -x0, -y0)


def _rect(area: float, rng: random.Random, min_side: float) -> Polygon:
    aspect = rng.uniform(1.0, 1.8)
    w = max(min_side, round(math.sqrt(area * aspect)))
    h = max(min_side, round(area / w))
    return box(0, 0, w, h)


def shape_outline(shape: str, area: float, rng: random.Random, *, min_arm: float) -> Outline:
    """An outline of ``shape`` whose area is close to ``area`` m² (whole metres)."""
    if shape == "rectangle":
        poly = _rect(area, rng, 4)
        holes: list[Ring] = []
    elif shape in ("l_shape", "u_shape", "t_shape"):
        fx, fy = rng.uniform(0.35, 0.5), rng.uniform(0.35, 0.5)
        kept = 1.0 - fx * fy
        aspect = rng.uniform(1.1, 1.7)
        w = math.sqrt(area / kept * aspect)
        h = area / kept / w
        w, h = round(w), round(h)
        cw, ch = round(w * fx), round(h * fy)
        if shape == "l_shape":
            poly = box(0, 0, w, h).difference(box(w - cw, h - ch, w, h))
            arms: tuple[int, ...] = (w - cw, h - ch)
        elif shape == "u_shape":
            x0 = (w - cw) // 2
            poly = box(0, 0, w, h).difference(box(x0, h - ch, x0 + cw, h))
            arms = (x0, w - x0 - cw, h - ch)
        else:
            side = max(1, cw // 2)  # each cut corner is half the notch width
            poly = box(0, 0, w, h).difference(box(0, 0, side, ch)).difference(box(w - side, 0, w, ch))
            arms = (w - 2 * side, h - ch)
        if min(arms) < min_arm:
            return shape_outline("rectangle", area, rng, min_arm=min_arm)
        holes = []
    elif shape == "courtyard":
        depth = rng.randint(8, 10)
        aspect = rng.uniform(1.0, 1.5)
        # area = w·h − (w − 2d)(h − 2d) = 2d(w + h) − 4d², with h = w / aspect: linear in w.
        w = (area + 4 * depth * depth) / (2 * depth * (1 + 1 / aspect))
        h = w / aspect
        w, h = round(w), round(h)
        if w - 2 * depth < 4 or h - 2 * depth < 4:
            return shape_outline("rectangle", area, rng, min_arm=min_arm)
        poly = box(0, 0, w, h)
        holes = [_ring(box(depth, depth, w - depth, h - depth))]
    else:
        raise PlannerError(f"unknown footprint shape {shape!r}")
    outer = _transform(Polygon(_ring(poly), holes), rng)
    return _ring(Polygon(outer.exterior)), [_ring(Polygon(r)) for r in outer.interiors]


def _setback(outline: Outline, rng: random.Random) -> Outline | None:
    outer, holes = outline
    poly = Polygon(outer, holes)
    x0, y0, x1, y1 = poly.bounds
    depth = rng.randint(3, 5)
    side = rng.choice(["left", "right", "bottom", "top"])
    cut = {
        "left": box(x0 + depth, y0, x1, y1), "right": box(x0, y0, x1 - depth, y1),
        "bottom": box(x0, y0 + depth, x1, y1), "top": box(x0, y0, x1, y1 - depth),
    }[side]
    kept = poly.intersection(cut)
    if kept.geom_type != "Polygon" or kept.area < 0.6 * poly.area or kept.interiors:
        return None
    return _ring(kept), []


def stack_outlines(
    shape: str, stack: str, floors: int, area: float, rng: random.Random, *, min_arm: float
) -> list[Outline]:
    """The outline of every floor, ground first, for one of the stacks named in the module doc."""
    if stack == "podium" and floors >= 3:
        base = shape_outline("rectangle", area, rng, min_arm=min_arm)
        bx = Polygon(base[0])
        x0, y0, x1, y1 = bx.bounds
        share = rng.uniform(0.55, 0.75)
        tw, th = max(min_arm * 2, round((x1 - x0) * math.sqrt(share))), max(
            min_arm * 2, round((y1 - y0) * math.sqrt(share))
        )
        tw, th = min(tw, x1 - x0), min(th, y1 - y0)
        ox = rng.choice([x0, x1 - tw])
        oy = rng.choice([y0, y1 - th])
        tower: Outline = (_ring(box(ox, oy, ox + tw, oy + th)), [])
        podium_floors = 1 if floors < 5 else 2
        return [base] * podium_floors + [tower] * (floors - podium_floors)
    if stack == "garage":
        main = shape_outline(shape, area, rng, min_arm=min_arm)
        poly = Polygon(main[0])
        x0, y0, x1, y1 = poly.bounds
        gw, gd = 6, 6
        # The garage sticks out of the left or right wall, flush with the front or the back,
        # wherever that wall is long enough to carry it.
        options = [
            box(x0 - gd, y0, x0, y0 + gw), box(x0 - gd, y1 - gw, x0, y1),
            box(x1, y0, x1 + gd, y0 + gw), box(x1, y1 - gw, x1 + gd, y1),
        ]
        rng.shuffle(options)
        ground = poly
        for garage in options:
            joined = poly.union(garage)
            if joined.geom_type == "Polygon" and poly.intersection(garage).length >= gw:
                ground = joined
                break
        gx0, gy0 = ground.bounds[0], ground.bounds[1]
        from shapely import affinity

        ground = affinity.translate(ground, -gx0, -gy0)
        poly = affinity.translate(poly, -gx0, -gy0)
        no_holes: list[Ring] = []
        return [(_ring(ground), no_holes)] + [(_ring(poly), no_holes)] * (floors - 1)
    base = shape_outline(shape, area, rng, min_arm=min_arm)
    outlines = [base] * floors
    if stack == "setback" and floors >= 2:
        stepped = _setback(base, rng)
        if stepped is not None:
            n = 1 if floors < 4 else rng.randint(1, 2)
            outlines = [base] * (floors - n) + [stepped] * n
    return outlines
