"""Load-bearing walls: the walls of a floor's first cut round, carried up as fixed walls.

The solver does not report walls, so they are read off the winning label grid: every cell belongs
to the hub or to the subtree of one of the hub's children (the rooms that the first round cut out
and later rounds subdivided); the grid edges between two different such groups are the first
round's walls. Edges touching a core or the outside are not walls between rooms and are left
out. Collinear unit edges are merged into maximal segments in metres.

A copied floor repeats its original's layout, so it keeps every wall of it; what any floor passes
up is its first round's walls. The floor above keeps them where its outline (minus its cores)
contains them. For the floor above to respect them, its own first round must fall into the same
compartments, so :class:`SkeletonSeedPlanner` seeds each of its first-round children inside the
region the same child took on the floor below; areas are matched by :func:`retarget_first_round`.
"""

from __future__ import annotations

from collections import deque

import numpy as np
from shapely.geometry import LineString, MultiLineString, Polygon, box
from shapely.ops import linemerge, polylabel, unary_union

from mansion.models.seeds import ChildSeed, SeedPlan, SeedPlanner, SeedRequest
from mansion.models import FloorLayout, Footprint, RoomGraph
from mansion.models.graph import RoomNode
from mansion.models.footprint import Point

__all__ = [
    "SkeletonSeedPlanner",
    "carry_walls",
    "cut_parents",
    "first_round_groups",
    "first_round_regions",
    "first_round_walls",
    "retarget_first_round",
]

Segment = tuple[Point, Point]


def cut_parents(graph: RoomGraph) -> dict[str, str]:
    """Room id → the room whose region it is cut from, following the solver's cut rounds: a
    breadth-first search from the hub, cores never parents. The hub and the cores have none."""
    hub = graph.hub.id
    cores = {n.id for n in graph.nodes if n.is_core}
    ids = {n.id for n in graph.nodes}
    # each room's neighbours as RoomGraph.neighbours lists them (in edge order, each once), read
    # in one pass over the edges: the mends ask for the cut tree thousands of times
    beside: dict[str, list[str]] = {}
    for edge in graph.edges:
        for room, other in ((edge.source, edge.target), (edge.target, edge.source)):
            near = beside.setdefault(room, [])
            if other not in near:
                near.append(other)
    parent: dict[str, str] = {}
    seen = {hub}
    queue = deque([hub])
    while queue:
        room = queue.popleft()
        if room not in ids:
            graph.node(room)  # RoomGraph.neighbours' error for a room the graph lacks
        for child in beside.get(room, []):
            if child in seen or child in cores:
                continue
            seen.add(child)
            parent[child] = room
            queue.append(child)
    return parent


def first_round_groups(graph: RoomGraph) -> dict[str, str]:
    """Room id → the first-round room whose region it was cut from (the hub maps to itself),
    along :func:`cut_parents`."""
    hub = graph.hub.id
    group = {hub: hub}
    # cut_parents lists rooms in breadth-first order, so a parent's group is known first
    for child, parent in cut_parents(graph).items():
        group[child] = child if parent == hub else group[parent]
    return group


def _group_grid(layout: FloorLayout, graph: RoomGraph) -> tuple[np.ndarray, list[str]]:
    groups = first_round_groups(graph)
    names = sorted(set(groups.values()))
    index = {g: i for i, g in enumerate(names)}
    lut = np.array([index.get(groups.get(rid, ""), -1) for rid in layout.grid.ids] + [-1], dtype=np.int32)
    labels = layout.grid.array()
    return np.where(labels >= 0, lut[labels], -1), names


def first_round_walls(layout: FloorLayout, graph: RoomGraph) -> list[Segment]:
    """The walls between the first round's regions, as maximal axis-aligned segments."""
    g, _ = _group_grid(layout, graph)
    s = layout.grid.cell_size
    ox, oy = layout.grid.origin
    pieces: list[LineString] = []
    # Vertical walls: between columns c and c+1 of a row.
    diff = (g[:, :-1] != g[:, 1:]) & (g[:, :-1] >= 0) & (g[:, 1:] >= 0)
    for r, c in zip(*np.nonzero(diff)):
        x = ox + (c + 1) * s
        pieces.append(LineString([(x, oy + r * s), (x, oy + (r + 1) * s)]))
    diff = (g[:-1, :] != g[1:, :]) & (g[:-1, :] >= 0) & (g[1:, :] >= 0)
    for r, c in zip(*np.nonzero(diff)):
        y = oy + (r + 1) * s
        pieces.append(LineString([(ox + c * s, y), (ox + (c + 1) * s, y)]))
    return _segments(unary_union(pieces)) if pieces else []


def _segments(geom: object) -> list[Segment]:
    merged = linemerge(geom) if not isinstance(geom, LineString) else geom
    lines = [merged] if isinstance(merged, LineString) else list(getattr(merged, "geoms", []))
    out: list[Segment] = []
    for line in lines:
        coords = list(line.coords)
        # Split merged polylines at their corners: fixed walls are straight segments.
        start = coords[0]
        for i in range(1, len(coords)):
            a, b = coords[i - 1], coords[i]
            nxt = coords[i + 1] if i + 1 < len(coords) else None
            straight = nxt is not None and (
                (a[0] == b[0] == nxt[0]) or (a[1] == b[1] == nxt[1])
            )
            if not straight:
                out.append(((float(start[0]), float(start[1])), (float(b[0]), float(b[1]))))
                start = b
    return sorted(out)


def carry_walls(walls: list[Segment], footprint: Footprint) -> list[Segment]:
    """The part of ``walls`` inside the floor's free region (outline minus holes and cores),
    not on its boundary."""
    region = Polygon(footprint.polygon, footprint.holes)
    for core in footprint.cores:
        region = region.difference(box(core.x[0], core.y[0], core.x[1], core.y[1]))
    kept = []
    for a, b in walls:
        inside = LineString([a, b]).intersection(region).difference(region.boundary)
        if inside.is_empty:
            continue
        kept += _segments(inside if isinstance(inside, (LineString, MultiLineString)) else unary_union(
            [g for g in getattr(inside, "geoms", []) if isinstance(g, LineString)]
        ))
    return [(a, b) for a, b in kept if a != b]


def first_round_regions(layout: FloorLayout, graph: RoomGraph) -> dict[str, tuple[float, Point]]:
    """First-round room id → (area of its region in m², a point well inside it)."""
    g, names = _group_grid(layout, graph)
    s = layout.grid.cell_size
    ox, oy = layout.grid.origin
    out: dict[str, tuple[float, Point]] = {}
    for i, name in enumerate(names):
        rows, cols = np.nonzero(g == i)
        if rows.size == 0:
            continue
        cells = unary_union(_row_runs(g == i, ox, oy, s))
        poly = cells if isinstance(cells, Polygon) else max(cells.geoms, key=lambda p: p.area)
        pole = polylabel(poly, tolerance=s / 2)
        out[name] = (float(rows.size * s * s), (float(pole.x), float(pole.y)))
    return out


def _row_runs(mask: np.ndarray, ox: float, oy: float, s: float) -> list[Polygon]:
    """The cells of ``mask`` as one box per run of cells along a row: the same region as a box
    per cell from a tenth of the boxes (74 → 8 ms a floor: with a box per cell, the regions took
    most of the time outside the solver). The union may start its boundary elsewhere, which can
    move the pole of inaccessibility when two candidates tie (one floor in thirty)."""
    out = []
    h, w = mask.shape
    padded = np.zeros((h, w + 2), dtype=np.int8)
    padded[:, 1:-1] = mask
    edges = np.diff(padded, axis=1)
    for r, c0 in zip(*np.nonzero(edges == 1)):
        c1 = c0 + int(np.argmax(edges[r, c0 + 1:] == -1)) + 1
        out.append(box(ox + c0 * s, oy + r * s, ox + c1 * s, oy + (r + 1) * s))
    return out


def retarget_first_round(graph: RoomGraph, areas: dict[str, float]) -> tuple[RoomGraph, list[str]]:
    """Fit each first-round subtree of ``graph`` (and the hub) to the area the same room's region
    had on the floor below, never below a room's ``min_area``: each room keeps its minimum and
    the rest of the region is shared in proportion to what the room was planned above it. A
    region too small for its rooms' minimums loses rooms first, repeated ones (a room type the
    floor has more of) before single ones, smaller before larger, each a leaf of the graph so the
    rest stays connected. Returns the graph and a relaxation note per region that lost rooms."""
    notes: list[str] = []
    while True:
        groups = first_round_groups(graph)
        members: dict[str, list[RoomNode]] = {}
        for node in graph.nodes:
            if node.id in groups:
                members.setdefault(groups[node.id], []).append(node)
        short = [
            grp for grp, nodes in members.items()
            if grp in areas and sum(n.min_area or 0.0 for n in nodes) > areas[grp] + 1e-9
        ]
        if not short:
            break
        dropped = []
        for grp in sorted(short):
            leaf = _droppable(graph, members[grp], grp)
            if leaf is not None:
                dropped.append(leaf.id)
                notes.append(
                    f"{leaf.id} left out: {grp}'s region on the floor below holds {areas[grp]:.1f} m², "
                    f"less than its rooms' minimums"
                )
        if not dropped:
            break  # nothing left to drop: the rooms share the region as planned
        graph = RoomGraph(
            nodes=[n for n in graph.nodes if n.id not in dropped],
            edges=[e for e in graph.edges if e.source not in dropped and e.target not in dropped],
        )
    groups = first_round_groups(graph)
    totals: dict[str, tuple[float, float]] = {}
    for node in graph.nodes:
        if node.id in groups:
            area, floor = totals.get(groups[node.id], (0.0, 0.0))
            totals[groups[node.id]] = (area + node.area, floor + _floor_of(node))
    nodes = []
    for node in graph.nodes:
        grp = groups.get(node.id)
        if grp is not None and grp in areas and totals[grp][0] > 0:
            area, floor = totals[grp]
            if grp == node.id and node.id == graph.hub.id:
                new_area = areas[grp]
            elif areas[grp] >= floor and area > floor:
                # the minimums first, the rest in proportion to what each was planned above its own
                new_area = _floor_of(node) + (node.area - _floor_of(node)) * (areas[grp] - floor) / (area - floor)
            else:
                new_area = node.area * areas[grp] / area
            node = node.model_copy(update={"area": new_area})
        nodes.append(node)
    return RoomGraph(nodes=nodes, edges=graph.edges), notes


def _floor_of(node: RoomNode) -> float:
    """The part of a node's planned area it must keep: its minimum, at most its plan."""
    return min(node.min_area or 0.0, node.area)


def _droppable(graph: RoomGraph, nodes: list[RoomNode], root: str) -> RoomNode | None:
    """The room of a first-round subtree to leave out first, or None: a leaf of the graph (one
    neighbour, no core), not the subtree's root; repeated types first, then the smallest."""
    cores = {n.id for n in graph.nodes if n.is_core}
    kinds: dict[str, int] = {}
    for n in graph.nodes:
        kinds[n.room_type or n.id] = kinds.get(n.room_type or n.id, 0) + 1
    leaves = [
        n for n in nodes
        if n.id != root and not n.is_core and len(set(graph.neighbours(n.id))) == 1
        and not set(graph.neighbours(n.id)) & cores
    ]
    if not leaves:
        return None
    return min(leaves, key=lambda n: (kinds[n.room_type or n.id] == 1, n.area, n.id))


class SkeletonSeedPlanner:
    """Seeds the first round at the regions of the floor below; every other round goes to
    ``rest`` when given (an LLM seed planner), else spreads its children over the parent region
    (farthest-point sampling, larger rooms first)."""

    def __init__(self, hub: str, points: dict[str, Point], rest: SeedPlanner | None = None) -> None:
        self.hub = hub
        self.points = points
        self.rest = rest

    def plan(self, request: SeedRequest) -> SeedPlan:
        if self.rest is not None and request.parent != self.hub:
            return self.rest.plan(request)
        seeds: dict[str, ChildSeed] = {}
        pending = []
        for child in request.children:
            if request.parent == self.hub and child.id in self.points:
                seeds[child.id] = ChildSeed(point=self.points[child.id])
            else:
                pending.append(child)
        if pending:
            region = Polygon(request.region.polygon, request.region.holes)
            x0, y0, x1, y1 = region.bounds
            step = request.cell_size
            xs, ys = np.meshgrid(np.arange(x0 + step / 2, x1, step), np.arange(y0 + step / 2, y1, step))
            import shapely

            inside = shapely.contains_xy(region, xs.ravel(), ys.ravel())
            cands = np.column_stack([xs.ravel()[inside], ys.ravel()[inside]])
            if cands.size == 0:
                c = region.representative_point()
                cands = np.array([[c.x, c.y]])
            chosen = [np.asarray(p) for p in seeds.values() if p.point is not None]
            dist = np.full(len(cands), np.inf)
            for p in chosen:
                dist = np.minimum(dist, np.hypot(*(cands - p).T))
            if not chosen:
                centre = np.array([region.centroid.x, region.centroid.y])
                dist = np.hypot(*(cands - centre).T)
            for child in sorted(pending, key=lambda c: -c.target_area):
                k = int(np.argmax(dist))
                p = cands[k]
                seeds[child.id] = ChildSeed(point=(float(p[0]), float(p[1])))
                dist = np.minimum(dist, np.hypot(*(cands - p).T))
        return SeedPlan(seeds=seeds)
