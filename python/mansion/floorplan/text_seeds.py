"""Seeds that follow the position words of a building's description ("a pharmacy on the east side
next to the lobby", "the kitchen in the north-east corner").

:class:`TextSeedPlanner` reads the description once per floor with
:mod:`mansion.planning.spatial_language`, places a point for every room of the floor's graph with
:mod:`mansion.planning.spatial_seeds` (on the floor's outline rasterised at the solver's cell
size, cores kept where they are), and answers each cut round from those points, moved into the
round's region when a point lies outside it. Floors whose rooms the description does not place
keep the solver's own heuristic: :func:`text_seed_planner` returns None for them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from mansion.models.seeds import ChildSeed, SeedPlan, SeedRequest
from mansion.models import Footprint, RoomGraph
from mansion.planning.spatial_language import KnownRoom, Reading, Statement, read_description
from mansion.planning.spatial_seeds import FreeGrid, SeedReport, SeedRoom, _honoured, place_seeds

__all__ = ["PositionCheck", "TextSeedPlanner", "position_checks", "text_seed_planner"]


@dataclass(frozen=True)
class PositionCheck:
    """One statement of the description about a room of a floor, and whether the solved floor
    honours it."""

    room: str
    text: str
    honoured: bool


class TextSeedPlanner:
    """A seed planner that places each cut round's children by the description (see the module
    docstring): the round's region is the free grid, each child carries the statements about it
    and about the rooms later rounds cut out of it, and its area is its region's target area."""

    def __init__(self, reading: Reading, report: SeedReport, free: FreeGrid, adjacency: list[tuple[str, str]], cores: dict[str, tuple[float, float]]) -> None:
        self.reading = reading
        self.report = report
        self.free = free
        self.adjacency = adjacency
        self.cores = cores

    def plan(self, request: SeedRequest) -> SeedPlan:
        from shapely.geometry import Polygon

        region = Polygon(request.region.polygon, request.region.holes)
        grid = _region_grid(region, request.cell_size)
        owner = {c.id: c.id for c in request.children}
        for c in request.children:
            for d in c.descendants:
                owner[d.id] = c.id
        owner[request.parent] = request.parent
        # the round's reading: statements about a child or the rooms it will hold, re-keyed
        statements: dict[str, list[Statement]] = {}
        for rid, ss in self.reading.statements.items():
            if rid in owner:
                statements.setdefault(owner[rid], []).extend(ss)
        resolved = {k: owner.get(v, v) for k, v in self.reading.resolved.items()}
        reading = Reading(statements=statements, resolved=resolved)
        rooms = [SeedRoom(c.id, c.room_type, max(c.target_area, request.cell_size**2)) for c in request.children]
        parent_area = max(request.region.area - sum(c.target_area for c in request.children), request.cell_size**2)
        rooms.append(SeedRoom(request.parent, "hub", parent_area))
        adjacency = sorted({(owner[a], owner[b]) for a, b in self.adjacency if a in owner and b in owner and owner[a] != owner[b]})
        points, _ = place_seeds(reading, rooms, grid, adjacency)
        seeds = {c.id: ChildSeed(point=self.cores.get(c.id, points[c.id])) for c in request.children}
        return SeedPlan(seeds=seeds, parent_seed=points[request.parent])


def _region_grid(region: object, cell: float) -> FreeGrid:
    import numpy as np
    import shapely

    x0, y0, x1, y1 = region.bounds  # type: ignore[attr-defined]
    cols = max(1, math.ceil((x1 - x0) / cell - 1e-9))
    rows = max(1, math.ceil((y1 - y0) / cell - 1e-9))
    gx, gy = np.meshgrid(x0 + (np.arange(cols) + 0.5) * cell, y0 + (np.arange(rows) + 0.5) * cell)
    mask = np.asarray(shapely.contains_xy(region, gx, gy), dtype=bool)
    if not mask.any():
        mask[:] = True
    return FreeGrid(mask, (x0, y0), cell)


def _free_grid(footprint: Footprint, cell: float) -> FreeGrid:
    import numpy as np
    import shapely
    from shapely.geometry import Polygon

    poly = Polygon(footprint.polygon, footprint.holes)
    x0, y0, x1, y1 = poly.bounds
    cols = max(1, math.ceil((x1 - x0) / cell))
    rows = max(1, math.ceil((y1 - y0) / cell))
    xs = x0 + (np.arange(cols) + 0.5) * cell
    ys = y0 + (np.arange(rows) + 0.5) * cell
    gx, gy = np.meshgrid(xs, ys)
    mask = shapely.contains_xy(poly, gx, gy)
    for core in footprint.cores:
        mask &= ~((gx > core.x[0]) & (gx < core.x[1]) & (gy > core.y[0]) & (gy < core.y[1]))
    return FreeGrid(np.asarray(mask, dtype=bool), (x0, y0), cell)


def text_seed_planner(description: str, graph: RoomGraph, footprint: Footprint, cell: float = 0.5) -> TextSeedPlanner | None:
    """The planner for one floor, or None when the description places none of its rooms."""
    cores = {c.id: ((c.x[0] + c.x[1]) / 2, (c.y[0] + c.y[1]) / 2) for c in footprint.cores}
    nodes = [n for n in graph.nodes if n.id not in cores]
    known = [KnownRoom(n.id, n.room_type) for n in nodes]
    reading = read_description(description, known)
    placing = [s for _, s in reading.all() if s.kind in ("position", "relation", "exterior")]
    if not placing:
        return None
    free = _free_grid(footprint, cell)
    rooms = [SeedRoom(n.id, n.room_type, max(n.area, cell * cell)) for n in nodes]
    adjacency = [(e.source, e.target) for e in graph.edges if e.source not in cores and e.target not in cores]
    _, report = place_seeds(reading, rooms, free, adjacency)
    return TextSeedPlanner(reading, report, free, adjacency, cores)


def position_checks(planner: TextSeedPlanner, centroids: dict[str, tuple[float, float]]) -> list[PositionCheck]:
    """Whether the solved rooms (their centroids) honour each placing statement."""
    import numpy as np

    rr, cc = np.nonzero(planner.free.mask)
    ext = (float(cc.min()), float(cc.max() + 1), float(rr.min()), float(rr.max() + 1))
    out: list[PositionCheck] = []
    for rid, s in planner.reading.all():
        if s.kind not in ("position", "relation", "exterior") or rid not in centroids:
            continue
        ok = _honoured(s, rid, centroids, planner.reading, planner.free, ext)
        out.append(PositionCheck(rid, _describe(s), ok))
    return out


def _describe(s: Statement) -> str:
    if s.kind == "position":
        where = "the centre" if s.direction == "centre" else f"the {s.direction}"
        return f"{s.subject.words} in {where} ({s.text.strip()!r})"
    if s.kind == "exterior":
        return f"{s.subject.words} on the {s.direction} outside wall ({s.text.strip()!r})"
    others = " and ".join(o.words for o in s.others)
    rel = (s.relation or "").replace("_", " ")
    return f"{s.subject.words} {rel} {others} ({s.text.strip()!r})"
