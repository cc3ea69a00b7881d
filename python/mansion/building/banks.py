"""Banks: a floor laid out whole as a double-loaded corridor, rooms in banks along its two sides.

Hotels' guest-room floors are planned this way everywhere, and schools' classroom floors: a
corridor down the middle of the slab, guest rooms or classrooms in bays between it and the
facade on both sides, a guest room entered from the corridor past its bathroom, the cores and
the service rooms (housekeeping, linen, toilets) where the bays stop. Grown by the cut rounds (:mod:`mansion.floorplan.solve`) such a floor came out as wings of
rooms round ragged corridors: guest rooms wrapped round their ensuites, rooms 90 m² beside rooms
below their 3.3 m width, half a floor's rooms left out (issue 14).

The layout here is drawn on the solver's grid (0.5 m cells) in four steps, for each bay depth
``D`` from the deepest the floor allows (at most :data:`MAX_DEPTH`) down to :data:`MIN_DEPTH`:

1. **Corridor.** Every free cell gets its distance to the facade along the four axes (the nearest
   outside cell in a straight line; cores count as inside, so a bay runs behind a core). Cells
   farther than ``D`` from every facade are the corridor: on a slab a strip down the middle, on an
   L, T or U a strip that turns with the arms. Each core the corridor does not reach gets a stub
   as wide as the corridor: a square of its width slid from beside the core to the corridor, the
   fewest steps with a turn costing :data:`_TURN` (straight where it can be, else an L).
2. **Runs.** The cells within ``D`` of a facade are the banks. Each faces the facade whose line
   of such cells is longest, cores on it counted in (a corner square goes with the longer side,
   so the bays along it stay rectangles); a facade's cells, position by position along it, make
   *runs* of one depth (behind a core the cells are shallower, and have no window). A run no
   room fits faces its other facade where it can, else becomes corridor (the corridor then
   reaches the facade at a slab's end, a window at its end); so do the positions at a run's ends
   that the corridor does not touch, more than :data:`_CORNER` of them (a corner square whose
   room would have no door).
3. **Bays.** The rooms are packed into the runs: the rooms the floor must keep first, service
   rooms where they waste least (the shallow runs behind cores), rooms that want daylight in the
   facade runs with most width left. Each asks for the width its clear width, minimum area and
   proportions need at the run's depth, with its ensuite (a guest room 3.3 m and its ensuite
   1.5 m: a 5 m bay); a run's spare width goes to its guest rooms, in steps at which an ensuite
   still fits. A room no run holds is left out when the floor may do without it (``spare``), else
   the depth fails. Ensuites go at the corridor end of their bay, on alternate sides, so two
   bathrooms share a wall as hotels pair them.
4. **Checks** (:func:`_fault`). Every room one piece, at its minimum area, with no shape defect
   (:func:`~mansion.building.merge.mask_defects`: no part below its clear width, no sliver, not
   elongated), no larger than :data:`OVERSIZE` times its planned area and :data:`OVERSIZE_M2` m²
   over it, every door of the graph with a wall of ``min_contact`` metres, the corridor at most
   :data:`MAX_CORRIDOR_SHARE` of the free area. The first depth that passes is kept; when none
   does, the caller lays the floor out by the cut rounds.

**Racetracks.** A plate too deep for one corridor (a hospital's ward floor on a 21 m square)
leaves a slab's corridor a hall, or in pieces round its cores. Where its template allows
(``FloorTemplate.racetrack``), each depth is also tried as a racetrack, the banks along two
opposite facades only (those below and above, or left and right): a corridor runs along each
bank, the cells farther than the bank and its corridor from both facades are an *inner zone*,
and the corridors join at their ends along the other two facades (a window at each end). The
inner zone's runs face one corridor across the zone's depth, with no window, so the rooms that
need no daylight go there (a nurse station, a treatment room, the utilities, a toilet cluster)
and the wards to the facades. Of the slabs and racetracks that pass the checks, the one keeping
most rooms wins, then the one whose corridor takes least of the floor.

Only floors whose rooms hang off the hub (wing corridors are folded into it,
:func:`bank_graph`), whose rooms' only children are their ensuites and whose other sub-hubs are
clusters (a toilet lobby with its toilets, drawn in one bay: the lobby's strip from the corridor
to the facade, its rooms stacked beside it) are laid out here: a hotel's guest floors, a
school's classroom floors and a hospital's ward floors (``FloorTemplate.banks``; the hospital's
as racetracks too).
"""

from __future__ import annotations

import dataclasses
import heapq
import math
from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

from mansion import _core
from mansion._grid import row_runs
from mansion.building.merge import grid_adjacencies, mask_defects, rooms_from_grid
from mansion.building.recut import _pieces, _thin_parts, edge_grown
from mansion.models.graph import RoomEdge, RoomGraph
from mansion.models.building import Footprint
from mansion.models.layout import Diagnostics, FloorLayout, LabelGrid, LayoutRoom
from mansion.models.room_design import design_key, needed_width, room_design

__all__ = ["MAX_DEPTH", "MIN_DEPTH", "bank_layout", "bank_graph"]

#: The deepest bay (m, facade to corridor) a floor is given: a hotel room with its bathroom is
#: 7-9 m deep. On a deeper floor the corridor widens into a hall.
MAX_DEPTH = 9.0
#: The shallowest bay (m): a guest room 5 m wide and 5 m deep keeps 19.75 m² past its ensuite.
MIN_DEPTH = 5.0
#: The most of a floor's free area its corridor may take (else the cut rounds lay it out): the
#: hotels' programs hold back 26-38 % of a floor for circulation (``Typology.reserve``).
MAX_CORRIDOR_SHARE = 0.4
#: A room is not drawn larger than this many times its planned area and this many m² over it
#: (a housekeeping room that takes a corner square of the floor).
OVERSIZE = 2.0
OVERSIZE_M2 = 15.0
#: Proportions no room is drawn beyond (the realism measure's elongation bound is 3).
_ASPECT = 2.9
#: Proportions no ensuite is drawn beyond (the design table's for bathrooms).
_ENSUITE_ASPECT = 2.5
#: How far an ensuite's drawn area may stray from its planned area (a share of it).
_ENSUITE_AREA = 0.25

_DIRS = ("down", "up", "left", "right")
#: Sub-hubs folded into the banks' corridor (a toilet lobby, also circulation, is not one).
_WINGS = frozenset({"corridor", "ward_corridor"})
#: Cell edges a core shares with the corridor at least (its door).
_CORE_CONTACT = 2
#: Positions at a run's end without the corridor beside them that its end bay takes (more go
#: to the corridor).
_CORNER = 4
#: Times the cells of runs too short for any room are turned to face another facade.
_REFACINGS = 3
#: What a turn of a core's corridor stub costs, in cells of its length.
_TURN = 4


# -- the graph ---------------------------------------------------------------------------------


def bank_graph(graph: RoomGraph) -> RoomGraph | None:
    """``graph`` with its wing corridors folded into the hub (their rooms hang off the hub, their
    area is the hub's), or None when the floor is not one for banks: a sub-hub that is not a
    corridor nor a cluster (a toilet lobby with its toilets: rooms without children that need no
    daylight), a room with children other than its ensuite, a room cut from a room that is not
    off the hub."""
    hub = graph.hub.id
    nodes = {n.id: n for n in graph.nodes}
    wings = {
        n.id for n in graph.nodes
        if n.id != hub and n.type == "area" and design_key(n.room_type) in _WINGS
    }
    parent: dict[str, str] = {}
    for e in graph.edges:
        if e.kind != "access" or nodes[e.target].is_core:
            continue
        if e.target in parent:
            return None
        parent[e.target] = hub if e.source in wings else e.source
    below: dict[str, list[str]] = {}
    for room, up in parent.items():
        below.setdefault(up, []).append(room)
    clusters = {n.id for n in graph.nodes if n.id != hub and n.type == "area" and n.id not in wings}
    for c in clusters:
        # a cluster: a sub-hub off the hub whose rooms are leaves that need no daylight (a
        # toilet lobby and its toilets), drawn together in one bay
        if parent.get(c) != hub or not below.get(c) or any(
            r in below or room_design(nodes[r].room_type).daylight for r in below[c]
        ):
            return None
    for room, up in parent.items():
        if room in wings or up == hub or up in clusters:
            continue
        if parent.get(up) != hub or not room_design(nodes[up].room_type).own_bathroom:
            return None
    if any(e.kind != "access" for e in graph.edges):
        return None
    extra = sum(nodes[w].area for w in wings)
    kept = [
        n.model_copy(update={"area": n.area + extra}) if n.id == hub else n
        for n in graph.nodes if n.id not in wings
    ]
    edges: list[RoomEdge] = []
    for e in graph.edges:
        if e.target in wings:
            continue
        source = hub if e.source in wings else e.source
        edges.append(RoomEdge(source=source, target=e.target, kind="access"))
    return RoomGraph(nodes=kept, edges=edges)


# -- the grid ----------------------------------------------------------------------------------


def _rays(inside: np.ndarray) -> dict[str, np.ndarray]:
    """For each cell, how many cells (itself included) lie between it and the outside in each
    direction: 1 for a cell on the facade (the grid's edge counts as outside)."""
    h, w = inside.shape
    out = {d: np.zeros((h, w), dtype=np.int32) for d in _DIRS}
    ins = inside.astype(np.int32)
    for r in range(h):
        prev = out["down"][r - 1] if r else np.zeros(w, np.int32)
        out["down"][r] = (prev + 1) * ins[r]
    for r in range(h - 1, -1, -1):
        prev = out["up"][r + 1] if r < h - 1 else np.zeros(w, np.int32)
        out["up"][r] = (prev + 1) * ins[r]
    for c in range(w):
        prev = out["left"][:, c - 1] if c else np.zeros(h, np.int32)
        out["left"][:, c] = (prev + 1) * ins[:, c]
    for c in range(w - 1, -1, -1):
        prev = out["right"][:, c + 1] if c < w - 1 else np.zeros(h, np.int32)
        out["right"][:, c] = (prev + 1) * ins[:, c]
    return out


def _run_lengths(mask: np.ndarray, axis: int) -> np.ndarray:
    """Each True cell's run length of True cells along ``axis`` (1: along rows, 0: along
    columns); 0 elsewhere."""
    ids, count = row_runs(mask if axis == 1 else mask.T)
    counts = np.bincount(ids.ravel(), minlength=count + 1)
    counts[0] = 0
    out = counts[ids].astype(np.int32)
    return out if axis == 1 else out.T


def _contact(a: np.ndarray, b: np.ndarray) -> int:
    """Cell edges shared by the cells of ``a`` and of ``b``."""
    return int(
        (a[1:, :] & b[:-1, :]).sum() + (a[:-1, :] & b[1:, :]).sum()
        + (a[:, 1:] & b[:, :-1]).sum() + (a[:, :-1] & b[:, 1:]).sum()
    )


def _block_sums(mask: np.ndarray, width: int) -> np.ndarray:
    """For each cell, how many cells of ``mask`` the ``width`` x ``width`` square with its
    lower-left cell there holds (0 where the square leaves the grid)."""
    h, w = mask.shape
    acc = np.zeros((h + 1, w + 1), dtype=np.int32)
    acc[1:, 1:] = mask.astype(np.int32).cumsum(0).cumsum(1)
    out = np.zeros((h, w), dtype=np.int32)
    if h >= width and w >= width:
        out[: h - width + 1, : w - width + 1] = (
            acc[width:, width:] - acc[:-width, width:] - acc[width:, :-width] + acc[:-width, :-width]
        )
    return out


def _stub(core: np.ndarray, corridor: np.ndarray, free: np.ndarray, width: int) -> np.ndarray | None:
    """The cells of a corridor ``width`` cells wide from a side of ``core`` to ``corridor``
    through ``free`` cells: a square of ``width`` cells slid from beside the core until it
    meets the corridor, the fewest steps with a turn costing :data:`_TURN` steps (straight
    stubs, an L where none is straight). None when no such path exists."""
    h, w = free.shape
    fits = (_block_sums(free, width) == width * width).tolist()
    start = (_block_sums(edge_grown(core), width) >= width) & np.asarray(fits)
    goal = (
        (_block_sums(edge_grown(corridor), width) >= min(width, _CORE_CONTACT))
        | (_block_sums(corridor, width) > 0)
    ).tolist()
    queue: list[tuple[int, int, int, int]] = []
    best: dict[tuple[int, int, int], int] = {}
    prev: dict[tuple[int, int, int], tuple[int, int, int] | None] = {}
    for r, c in zip(*np.nonzero(start)):
        for d in range(4):
            key = (int(r), int(c), d)
            best[key] = 0
            prev[key] = None
            heapq.heappush(queue, (0, *key))
    steps = ((1, 0), (-1, 0), (0, 1), (0, -1))
    while queue:
        cost, r, c, d = heapq.heappop(queue)
        if cost > best[(r, c, d)]:
            continue
        if goal[r][c]:
            out = np.zeros_like(free)
            key: tuple[int, int, int] | None = (r, c, d)
            while key is not None:
                out[key[0]: key[0] + width, key[1]: key[1] + width] = True
                key = prev[key]
            return out & ~corridor
        for nd, (dr, dc) in enumerate(steps):
            rr, cc = r + dr, c + dc
            if not (0 <= rr < h and 0 <= cc < w) or not fits[rr][cc]:
                continue
            step = cost + 1 + (_TURN if nd != d and cost > 0 else 0)
            key2 = (rr, cc, nd)
            if step < best.get(key2, 1 << 30):
                best[key2] = step
                prev[key2] = (r, c, d)
                heapq.heappush(queue, (step, rr, cc, nd))
    return None


@dataclass
class _Run:
    """Cells along one facade at one depth, in order along it: ``columns[t]`` the cells (row,
    col) of the t-th position, innermost (nearest the corridor) last."""

    columns: list[list[tuple[int, int]]]
    #: the facade it faces, an index of :data:`_DIRS`
    facing: int
    #: whether its outermost cells are on the facade (not behind a core): a room here has a window
    lit: bool = True

    def __len__(self) -> int:
        return len(self.columns)

    @property
    def depth(self) -> int:
        return len(self.columns[0])


@dataclass
class _Item:
    """A room off the hub to be given a bay, with what its width depends on."""

    id: str
    need: int  # its clear width, cells
    least: float  # its minimum area, cells
    target: float  # its planned area, cells
    bank: bool  # a room that wants daylight (takes its run's spare width)
    spare: bool  # may be left out
    room_type: str = ""
    building_type: str | None = None
    ensuite: str | None = None
    ensuite_width: int = 0
    ensuite_cells: int = 0
    ensuite_least: int = 0  # its minimum area, cells
    #: the rooms of a cluster drawn in its bay beside it: (id, room type, clear width, minimum
    #: area, planned area), widths in cells, areas in cells
    cluster: tuple[tuple[str, str, int, float, float], ...] = ()
    columns: tuple[int, int] = (0, 0)
    run: int = -1
    _widths: dict[int, int] = field(default_factory=dict)

    def width(self, depth: int) -> int:
        """The fewest positions it can have in a run ``depth`` cells deep (0: none will do)."""
        found = self._widths.get(depth)
        if found is None:
            found = self._widths[depth] = self._width(depth)
        return found

    def _width(self, depth: int) -> int:
        if depth < self.need:
            return 0
        if self.cluster:
            side = next(
                (w for w in range(max(r[2] for r in self.cluster), depth + 1) if _stack(self.cluster, w, depth)),
                0,
            )
            return self.need + side if side else 0
        least = max(
            self.need, math.ceil(depth / _ASPECT - 1e-6),
            math.ceil((self.least + self.ensuite_cells * self.ensuite_width) / depth - 1e-6),
        )
        return next((w for w in range(least, 3 * depth + 1) if self.fits(w, depth)), 0)

    def fits(self, wide: int, depth: int) -> bool:
        """Whether a bay ``wide`` positions by ``depth`` cells holds it and its ensuite (a
        cluster: its rooms)."""
        if self.cluster:
            return _stack(self.cluster, wide - self.need, depth) is not None
        return self.ensuite is None or any(
            _bay_fits(wide, depth, a, b, self.room_type, self.building_type) for a, b in _ensuite_shapes(self)
        )

    def want(self, depth: int) -> int:
        """The positions its planned area asks for at ``depth``."""
        return max(self.width(depth), round((self.target + self.ensuite_cells * self.ensuite_width) / depth))


@dataclass
class _Plan:
    labels: np.ndarray
    #: the rooms its labels number, in order (the graph's, then the rooms added)
    ids: list[str]
    dropped: list[str] = field(default_factory=list)
    #: (room, its ensuite or None, the room it repeats, that room's ensuite or None)
    added: list[tuple[str, str | None, str, str | None]] = field(default_factory=list)


def _runs(
    band: np.ndarray, rays: dict[str, np.ndarray], depth: int, banned: np.ndarray, cores: np.ndarray,
) -> list[_Run]:
    """The banks' cells by the facade they face, split into runs of consecutive positions of one
    depth (behind a core a facade's cells are shallower). A cell faces the facade within
    ``depth`` whose line of such cells, cores on it counted in, is longest: a corner square goes
    with the longer facade, even when a core stands on it (``banned[k]``: cells that may not
    face the k-th of :data:`_DIRS`)."""
    near = {d: band & (rays[d] <= depth) & ~banned[k] for k, d in enumerate(_DIRS)}
    length = {
        d: _run_lengths(near[d] | (cores & (rays[d] <= depth)), 1 if d in ("down", "up") else 0)
        for d in _DIRS
    }
    choice = np.full(band.shape, -1, dtype=np.int32)
    best_len = np.full(band.shape, -1, dtype=np.int32)
    best_ray = np.full(band.shape, 1 << 20, dtype=np.int32)
    for k, d in enumerate(_DIRS):
        better = near[d] & ((length[d] > best_len) | ((length[d] == best_len) & (rays[d] < best_ray)))
        choice[better] = k
        best_len[better] = length[d][better]
        best_ray[better] = rays[d][better]
    runs: list[_Run] = []
    for k, d in enumerate(_DIRS):
        rows, cols = np.nonzero(choice == k)
        if rows.size == 0:
            continue
        ray = rays[d][rows, cols]
        if d in ("down", "up"):
            wall, t = (rows - ray if d == "down" else rows + ray), cols
        else:
            wall, t = (cols - ray if d == "left" else cols + ray), rows
        # by facade line, then position along it, then from the facade inwards
        order = np.lexsort((ray, t, wall))
        rows, cols, wall, t = rows[order], cols[order], wall[order], t[order]
        starts = np.flatnonzero(np.r_[True, (wall[1:] != wall[:-1]) | (t[1:] != t[:-1])])
        ends = np.r_[starts[1:], rows.size]
        cells = list(zip(rows.tolist(), cols.tolist()))
        columns = [cells[i:j] for i, j in zip(starts.tolist(), ends.tolist())]
        size = ends - starts
        cw, ct = wall[starts], t[starts]
        # a run breaks where the facade line changes, a position is skipped or the depth changes
        breaks = np.flatnonzero(
            np.r_[True, (cw[1:] != cw[:-1]) | (ct[1:] != ct[:-1] + 1) | (size[1:] != size[:-1])]
        ).tolist() + [len(columns)]
        facade = rays[d]
        for i, j in zip(breaks[:-1], breaks[1:]):
            run = columns[i:j]
            runs.append(_Run(run, k, all(facade[col[0]] == 1 for col in run)))
    return runs


def _trimmed(runs: list[_Run], corridor: np.ndarray, items: list[_Item]) -> list[_Run]:
    """``runs`` without the positions at their ends whose cells do not reach ``corridor`` (a
    corner square, where two facades' banks meet: a room there would have no door), those
    cells given to the corridor (a corner lobby), when they are more than :data:`_CORNER`
    positions; fewer widen the run's end bay. Runs left too short for any room go to the
    corridor too."""
    out = list(runs)
    for _ in range(4):
        changed = False
        kept: list[_Run] = []
        for run in out:
            touch = [bool(_reaches(col, corridor)) for col in run.columns]
            lo, hi = 0, len(run)
            while lo < hi and not touch[lo]:
                lo += 1
            while hi > lo and not touch[hi - 1]:
                hi -= 1
            lo = 0 if lo <= _CORNER else lo
            hi = len(run) if len(run) - hi <= _CORNER else hi
            cut = run.columns[:lo] + run.columns[hi:]
            rest = _Run(run.columns[lo:hi], run.facing, run.lit) if hi > lo else None
            if rest is None or not any(0 < it.width(rest.depth) <= len(rest) for it in items):
                cut = run.columns
                rest = None
            for col in cut:
                for r, c in col:
                    corridor[r, c] = True
            changed |= bool(cut)
            if rest is not None:
                kept.append(rest)
        out = kept
        if not changed:
            break
    return out


def _reaches(col: list[tuple[int, int]], corridor: np.ndarray) -> bool:
    """Whether the innermost cell of a run's position has the corridor beside it."""
    r, c = col[-1]
    h, w = corridor.shape
    return any(
        0 <= rr < h and 0 <= cc < w and corridor[rr, cc]
        for rr, cc in ((r - 1, c), (r + 1, c), (r, c - 1), (r, c + 1))
    )


def _items(graph: RoomGraph, cell: float, building_type: str | None, spare: set[str]) -> list[_Item]:
    """The rooms off the hub with what their bays need."""
    hub = graph.hub.id
    nodes = {n.id: n for n in graph.nodes}
    below: dict[str, list[str]] = {}
    off_hub: list[str] = []
    for e in graph.edges:
        if nodes[e.target].is_core:
            continue
        if e.source == hub:
            off_hub.append(e.target)
        else:
            below.setdefault(e.source, []).append(e.target)
    ensuite = {up: rooms[0] for up, rooms in below.items() if nodes[up].type != "area"}
    items: list[_Item] = []
    sq = cell * cell

    def cells(width: float) -> int:
        return math.ceil(width / cell - 1e-6)

    for rid in off_hub:
        n = nodes[rid]
        d = room_design(n.room_type)
        item = _Item(
            rid, cells(needed_width(n.room_type, building_type)), d.min_area / sq, n.area / sq,
            bool(d.daylight), rid in spare, n.room_type, building_type,
        )
        if n.type == "area":
            item.cluster = tuple(
                (r, nodes[r].room_type, cells(needed_width(nodes[r].room_type, building_type)),
                 room_design(nodes[r].room_type).min_area / sq, nodes[r].area / sq)
                for r in below[rid]
            )
        if rid in ensuite:
            e = nodes[ensuite[rid]]
            item.ensuite = e.id
            item.ensuite_width = max(cells(needed_width(e.room_type, building_type)), 2)
            item.ensuite_least = math.ceil(room_design(e.room_type).min_area / sq - 1e-6)
            item.ensuite_cells = max(
                math.ceil(room_design(e.room_type).min_area / (item.ensuite_width * sq) - 1e-6),
                round(e.area / (item.ensuite_width * sq)),
                item.ensuite_width,
            )
        items.append(item)
    return items


def _pack(items: list[_Item], runs: list[_Run]) -> list[_Item] | None:
    """Give each item a run: the rooms that must stay first, each where it leaves the least
    width unused among the runs it fits (service rooms fill the short runs behind cores), the
    rooms with daylight in the run with the most width left. Items without a run are dropped
    when they may be, else None. Returns the items placed."""
    free = [len(r) for r in runs]
    placed: list[_Item] = []
    order = sorted(items, key=lambda it: (it.spare, it.bank, -it.width(runs[0].depth if runs else 1)))
    for item in order:
        fits = [
            j for j in range(len(runs))
            if 0 < item.width(runs[j].depth) <= free[j] and (runs[j].lit or not item.bank)
        ]
        if not fits:
            if item.spare:
                continue
            return None
        if item.bank:
            best = max(fits, key=lambda j: (runs[j].depth, free[j]))
        else:
            best = min(fits, key=lambda j: (runs[j].lit, free[j] - item.width(runs[j].depth), -runs[j].depth))
        item.run = best
        free[best] -= item.width(runs[best].depth)
        placed.append(item)
    return placed


def _bays(placed: list[_Item], runs: list[_Run]) -> None:
    """Lay each run's items side by side along it, the run's spare width shared by its banks:
    first towards the width each one's planned area asks for, then in turn, each bay only to a
    width its ensuite still fits (a bay one position wider may hold none: the strip beside the
    ensuite falls below the room's width). What no bay can take is left to the corridor (a
    window at its end)."""
    by_run: dict[int, list[_Item]] = {}
    for it in placed:
        by_run.setdefault(it.run, []).append(it)
    for j, members in by_run.items():
        n, depth = len(runs[j]), runs[j].depth
        # service rooms at the run's ends, the banks between
        service = [it for it in members if not it.bank]
        banks = [it for it in members if it.bank]
        order = service[: len(service) // 2] + banks + service[len(service) // 2:]
        widths = [it.width(depth) for it in order]
        spare = n - sum(widths)
        takers = [i for i, it in enumerate(order) if it.bank]
        # a run of service rooms alone leaves what they do not ask for to the corridor
        for i in takers or range(len(order)):
            fits = [w for w in range(widths[i], min(order[i].want(depth), widths[i] + spare) + 1) if order[i].fits(w, depth)]
            if fits:
                spare -= fits[-1] - widths[i]
                widths[i] = fits[-1]
        moved = bool(takers)
        while spare > 0 and moved:
            moved = False
            for i in takers:
                wider = next((w for w in range(widths[i] + 1, widths[i] + spare + 1) if order[i].fits(w, depth)), None)
                if wider is not None:
                    spare -= wider - widths[i]
                    widths[i] = wider
                    moved = True
                if spare == 0:
                    break
        t = 0
        for it, wd in zip(order, widths):
            it.columns = (t, t + wd)
            t += wd


def _stack(rooms: tuple[tuple[str, str, int, float, float], ...], side: int, depth: int) -> list[int] | None:
    """Depths (cells) of a cluster's rooms stacked from the facade in a strip ``side`` positions
    wide and ``depth`` deep: each at least its clear width and minimum area and within the
    proportions no room is drawn beyond, the rest shared as their planned areas ask; None when
    they do not fit."""
    if side < max(r[2] for r in rooms):
        return None
    least = [max(need, math.ceil(area / side - 1e-6), math.ceil(side / _ASPECT - 1e-6)) for _, _, need, area, _ in rooms]
    if sum(least) > depth:
        return None
    out = list(least)
    spare = depth - sum(least)
    total = sum(r[4] for r in rooms) or 1.0
    for i, r in enumerate(rooms):
        out[i] += int(spare * r[4] / total)
    out[-1] += depth - sum(out)
    if any(d > _ASPECT * side for d in out):
        return None
    return out


@lru_cache(maxsize=4096)
def _bay_fits(wide: int, deep: int, a: int, b: int, room_type: str, building_type: str | None) -> bool:
    """Whether a bay ``wide`` x ``deep`` cells with an ensuite ``a`` positions by ``b`` cells
    cut from a corner at its corridor end leaves its room sound (:func:`mask_defects`, 0.5 m
    cells) and on the corridor for a door."""
    if a >= wide - 1 or b >= deep:
        return False
    room = np.ones((deep, wide), dtype=bool)
    room[deep - b:, :a] = False
    return not mask_defects(room, room_type, building_type, 0.5)


def _ensuite_shapes(item: _Item) -> list[tuple[int, int]]:
    """(positions along the run, cells deep) an ensuite of ``item`` may take: its clear width at
    least, within :data:`_ENSUITE_AREA` of its planned area (never below its minimum) and no
    longer than :data:`_ENSUITE_ASPECT` to one; the narrowest first, then the nearest its planned
    area, each also turned."""
    cells = item.ensuite_cells * item.ensuite_width
    w = item.ensuite_width
    lo = max(item.ensuite_least, math.ceil(cells * (1 - _ENSUITE_AREA) - 1e-6))
    hi = max(lo, math.floor(cells * (1 + _ENSUITE_AREA) + 1e-6))
    found: list[tuple[int, int, tuple[int, int]]] = []
    for a in range(w, w + 5):
        for b in range(max(w, math.ceil(lo / a - 1e-6)), hi // a + 1):
            if max(a, b) <= _ENSUITE_ASPECT * min(a, b):
                found.append((a, abs(a * b - cells), (a, b)))
    out: list[tuple[int, int]] = []
    for _, _, (a, b) in sorted(found):
        for shape in ((a, b), (b, a)):
            if shape not in out:
                out.append(shape)
    return out


def _draw(
    placed: list[_Item], runs: list[_Run], labels: np.ndarray, index: dict[str, int],
    building_type: str | None, room_types: dict[str, str], cell: float, corridor: np.ndarray,
) -> str | None:
    """Label each item's bay and its ensuite at the corridor end of the bay: the first of its
    shapes, at either end of the bay (the end alternating along the run, so bathrooms pair),
    that leaves the room sound and at a door's width on the corridor. Returns the first room
    whose bay holds no such ensuite, if any."""
    # the n-th room with an ensuite along its run puts it at the bay's far end when n is even,
    # its near end when odd: the two bathrooms of each pair of bays share a wall
    along: dict[int, int] = {}
    for it in sorted(placed, key=lambda x: (x.run, x.columns)):
        run = runs[it.run]
        a, b = it.columns
        bay = np.zeros(labels.shape, dtype=bool)
        for t in range(a, b):
            for r, c in run.columns[t]:
                bay[r, c] = True
        labels[bay] = index[it.id]
        if it.cluster:
            if not _draw_cluster(it, run, labels, index, building_type, room_types, cell):
                return it.id
            continue
        if it.ensuite is None:
            continue
        n = along[it.run] = along.get(it.run, -1) + 1
        done = False
        for wide, deep in _ensuite_shapes(it):
            if wide >= b - a or deep >= run.depth:
                continue
            ends = ((b - wide, b), (a, a + wide))
            for lo, hi in ends[::-1] if n % 2 else ends:
                ens = np.zeros_like(bay)
                for t in range(lo, hi):
                    for r, c in run.columns[t][-deep:]:
                        ens[r, c] = True
                room = bay & ~ens
                if (
                    _contact(room, corridor) >= _CORE_CONTACT
                    and not mask_defects(room, room_types[it.id], building_type, cell)
                    and _core.mask_passable(room) == (0, 1)
                ):
                    labels[ens] = index[it.ensuite]
                    done = True
                    break
            if done:
                break
        if not done:
            return it.id
    return None


def _draw_cluster(
    it: _Item, run: _Run, labels: np.ndarray, index: dict[str, int], building_type: str | None,
    room_types: dict[str, str], cell: float,
) -> bool:
    """A cluster's rooms stacked from the facade to the corridor beside its sub-hub's strip, at
    either end of the bay: False when neither leaves every room sound and passable."""
    a, b = it.columns
    side = b - a - it.need
    depths = _stack(it.cluster, side, run.depth)
    if depths is None:
        return False
    for lo, hi in ((a + it.need, b), (a, a + side)):
        trial = labels.copy()
        start = 0
        for (rid, *_), d in zip(it.cluster, depths):
            for t in range(lo, hi):
                for r, c in run.columns[t][start: start + d]:
                    trial[r, c] = index[rid]
            start += d
        masks = [(rid, trial == index[rid]) for rid, *_ in it.cluster] + [(it.id, trial == index[it.id])]
        if all(
            not mask_defects(m, room_types[rid], building_type, cell) and _core.mask_passable(m) == (0, 1)
            for rid, m in masks
        ):
            labels[:] = trial
            return True
    return False


def _absorb(labels: np.ndarray, hub: int, keep: set[int], building_type: str | None, room_types: list[str], cell: float) -> None:
    """Pieces of the hub cut off from its largest piece (a short run by a core) go to the room
    beside them that shares most wall with them and stays sound (not a core or an ensuite)."""
    if _core.mask_pieces(labels == hub) < 2:
        return
    comps = _masks(_pieces(labels == hub), labels.shape)
    comps.sort(key=lambda m: -int(m.sum()))
    _hand_off(labels, comps[1:], hub, keep, building_type, room_types, cell)


def _hand_off(
    labels: np.ndarray, comps: list[np.ndarray], hub: int, keep: set[int], building_type: str | None,
    room_types: list[str], cell: float,
) -> None:
    """Give each of ``comps`` (cells of the hub) to the room beside it that shares most wall
    with it and stays sound and passable; a piece no room takes stays the hub's."""
    for comp in comps:
        best: tuple[int, int] | None = None
        for k in set(np.unique(labels[edge_grown(comp) & ~comp]).tolist()):
            if k < 0 or k == hub or k not in keep:
                continue
            touch = _contact(comp, labels == k)
            if touch and (best is None or touch > best[0]):
                grown = (labels == k) | comp
                if not mask_defects(grown, room_types[k], building_type, cell) and _core.mask_passable(grown) == (0, 1):
                    best = (touch, k)
        if best is not None:
            labels[comp] = best[1]


def _masks(parts: list[list[tuple[int, int]]], shape: tuple[int, ...]) -> list[np.ndarray]:
    """Each of ``parts`` (its (row, column) cells, as :func:`~mansion.building.recut._pieces`
    gives them) as a mask of a grid of ``shape``."""
    out: list[np.ndarray] = []
    for part in parts:
        mask = np.zeros(shape, dtype=bool)
        rows, cols = zip(*part)
        mask[list(rows), list(cols)] = True
        out.append(mask)
    return out


def _fault(
    labels: np.ndarray, graph: RoomGraph, ids: list[str], building_type: str | None, cell: float,
    min_contact: float,
) -> str | None:
    """What keeps the layout from being sound, if anything: a room missing or in pieces, below
    its minimum area, with a shape defect (:func:`mask_defects`), a door without its wall."""
    nodes = {n.id: n for n in graph.nodes}
    for k, rid in enumerate(ids):
        mask = labels == k
        node = nodes[rid]
        if not mask.any():
            return f"{rid} has no floor"
        if _core.mask_pieces(mask) != 1:
            return f"{rid} is in pieces"
        if node.is_core:
            continue
        uncovered, pieces = _core.mask_passable(mask)
        if uncovered or pieces != 1:
            # a part 0.5 m wide, or parts joined by one: no agent passes (mansion validate)
            return f"{rid} has a passage narrower than 1 m"
        if mask.sum() * cell * cell < room_design(node.room_type).min_area - 1e-6:
            return f"{rid} is below its minimum area"
        defects = mask_defects(mask, node.room_type, building_type, cell)
        if defects:
            return f"{rid} is {', '.join(sorted(defects))}"
    free = int((labels >= 0).sum() - sum(int((labels == k).sum()) for k, rid in enumerate(ids) if nodes[rid].is_core))
    for k, rid in enumerate(ids):
        node = nodes[rid]
        area = float((labels == k).sum()) * cell * cell
        if k == 0:
            if area > MAX_CORRIDOR_SHARE * free * cell * cell:
                return f"{rid} takes {area / (free * cell * cell):.0%} of the floor"
        elif not node.is_core and area > OVERSIZE * node.area and area > node.area + OVERSIZE_M2:
            return f"{rid} is {area:.0f} m² for {node.area:.0f} m² planned"
    adj = {frozenset((a.a, a.b)): a for a in grid_adjacencies(labels, ids, cell)}
    for e in graph.edges:
        found = adj.get(frozenset((e.source, e.target)))
        if found is None or found.contact + 1e-9 < min_contact or found.longest + 1e-9 < min(min_contact, 1.0):
            return f"no door's wall between {e.source} and {e.target}"
    return None


def _attempt(
    graph: RoomGraph, raster: np.ndarray, rays: dict[str, np.ndarray], depth: int, corridor_cells: int,
    building_type: str | None, cell: float, spare: set[str], core_index: dict[str, int], fill: str | None,
    ring: int = 0,
) -> _Plan | str:
    """The floor at one bay depth (cells), or why there is none. ``ring`` 1 or 2: the banks
    only along the facades below and above (1) or left and right (2), a corridor along each and
    an inner zone between them of rooms that need no daylight, the corridors joined at their
    ends along the other two facades (a racetrack)."""
    ids = [n.id for n in graph.nodes]
    index = {rid: k for k, rid in enumerate(ids)}
    hub = index[graph.hub.id]
    free = raster == -2
    inner = np.zeros_like(free)
    # cells that may not face a facade: in a racetrack the banks face their two facades only
    facing = np.zeros((len(_DIRS), *free.shape), dtype=bool)
    if ring:
        mine, other = ((0, 1), (2, 3)) if ring == 1 else ((2, 3), (0, 1))
        reach = np.minimum(rays[_DIRS[mine[0]]], rays[_DIRS[mine[1]]])
        ends = np.minimum(rays[_DIRS[other[0]]], rays[_DIRS[other[1]]])
        inner = free & (reach > depth + corridor_cells) & (ends > corridor_cells)
        if not inner.any():
            return "no inner zone"
        corridor = free & (reach > depth) & ~inner
        for k in other:
            facing[k] = free & (reach <= depth)
        rays_in = _rays(inner)
        span = int(max(int(rays_in[d][inner].max()) for d in _DIRS))
        # the inner rooms span the zone, from one corridor to the other
        for k in range(len(_DIRS)):
            if k != mine[0]:
                facing[k] |= inner
    else:
        corridor = free & (np.minimum.reduce([rays[d] for d in _DIRS]) > depth)
    if not corridor.any():
        return "no corridor"
    if corridor.sum() > MAX_CORRIDOR_SHARE * free.sum():
        # the corridor only grows from here (runs no room fits, stubs): no need to draw it
        return f"corridor takes {corridor.sum() / free.sum():.0%} of the floor before the runs"
    items = _items(graph, cell, building_type, spare)

    def runs_of(corridor: np.ndarray) -> list[_Run]:
        # a run no room fits faces another facade where it can (the cells beside a core that
        # cuts a long facade short face the next one), and else becomes corridor (the corridor
        # reaches the facade at a slab's end)
        banned = np.zeros((len(_DIRS), *free.shape), dtype=bool)
        for _ in range(_REFACINGS + 1):
            runs = _runs(free & ~corridor & ~inner, rays, depth, banned | facing, raster >= 0)
            if ring:
                # the inner zone's rooms face a corridor, across the zone, with no window
                runs += [
                    dataclasses.replace(run, lit=False)
                    for run in _runs(inner & ~corridor, rays_in, span, banned | facing, raster >= 0)
                ]
            short = [run for run in runs if not any(0 < it.width(run.depth) <= len(run) for it in items)]
            if not short:
                break
            for run in short:
                for col in run.columns:
                    for r, c in col:
                        banned[run.facing, r, c] = True
        kept = [run for run in runs if run not in short]
        taken = np.zeros_like(free)
        for run in kept:
            for col in run.columns:
                for r, c in col:
                    taken[r, c] = True
        corridor |= free & ~taken
        return kept

    runs_of(corridor)
    # cores the corridor does not reach get a stub to it
    for cid, k in core_index.items():
        if cid not in index:
            continue
        core = raster == k
        if _contact(core, corridor) >= _CORE_CONTACT:
            continue
        stub = _stub(core, corridor, free & ~(raster >= 0), corridor_cells)
        if stub is None:
            return f"no corridor reaches {cid}"
        corridor |= stub
    kept_runs = _trimmed(runs_of(corridor), corridor, items)
    placed = _pack(items, kept_runs)
    if placed is None:
        return "the rooms that must stay do not fit"
    added = _filled(placed, items, kept_runs, fill, {n.id for n in graph.nodes})
    for room, bath, _, _ in added:
        for rid in (room, bath):
            if rid is not None:
                index[rid] = len(ids)
                ids.append(rid)
    _bays(placed, kept_runs)
    labels = np.full(raster.shape, -1, dtype=np.int32)
    labels[free] = hub
    for cid, k in core_index.items():
        if cid in index:
            labels[raster == k] = index[cid]
    room_types = {n.id: n.room_type for n in graph.nodes}
    for room, bath, model, model_bath in added:
        room_types[room] = room_types[model]
        if bath is not None and model_bath is not None:
            room_types[bath] = room_types[model_bath]
    failed = _draw(placed, kept_runs, labels, index, building_type, room_types, cell, corridor)
    if failed:
        return f"no ensuite fits the bay of {failed}"
    keep = {index[it.id] for it in placed}
    types = [room_types[rid] for rid in ids]
    _absorb(labels, hub, keep, building_type, types, cell)
    # strips 0.5 m wide (a core's side left to the corridor), which no agent walks
    _hand_off(labels, _masks(_thin_parts(labels == hub), labels.shape), hub, keep, building_type, types, cell)
    # runs no room took stay the corridor's (checked below like every room)
    names = {it.id for it in placed}
    dropped = [it.id for it in items if it.id not in names]
    return _Plan(labels, ids, dropped, added)


def _filled(
    placed: list[_Item], items: list[_Item], runs: list[_Run], fill: str | None, taken: set[str],
) -> list[tuple[str, str | None, str, str | None]]:
    """More rooms of the floor's ``fill`` type (its guest rooms) in the width the facade runs
    have left once every room is placed, as the program repeats them until the floor's area is
    used; each a copy of the first such room, with its ensuite. Adds them to ``placed`` and
    returns (room, ensuite, the room copied, its ensuite)."""
    model = next((it for it in items if it.room_type == fill), None) if fill else None
    if model is None:
        return []
    used = [0] * len(runs)
    for it in placed:
        used[it.run] += it.width(runs[it.run].depth)
    prefix = model.id.rstrip("0123456789")
    n = 1
    out: list[tuple[str, str | None, str, str | None]] = []
    for j, run in enumerate(runs):
        wide = model.width(run.depth) if run.lit else 0
        while wide and len(run) - used[j] >= wide:
            while f"{prefix}{n}" in taken:
                n += 1
            room = f"{prefix}{n}"
            bath = f"{room}_ensuite" if model.ensuite is not None else None
            taken.update(r for r in (room, bath) if r is not None)
            placed.append(dataclasses.replace(model, id=room, ensuite=bath, run=j, _widths=dict(model._widths)))
            out.append((room, bath, model.id, model.ensuite))
            used[j] += wide
    return out


def bank_layout(
    graph: RoomGraph,
    footprint: Footprint,
    building_type: str | None,
    *,
    cell: float = 0.5,
    min_contact: float = 1.0,
    spare: set[str] | frozenset[str] = frozenset(),
    fill: str | None = None,
    why: list[str] | None = None,
    ring: bool = False,
) -> tuple[FloorLayout, RoomGraph, list[str], list[str]] | None:
    """The floor of ``graph`` (already :func:`bank_graph`'s) on ``footprint`` as a double-loaded
    corridor, or None when no depth gives a sound layout. Returns the layout, the graph without
    the rooms left out (each of them in ``spare``, with its ensuite) and with the rooms added,
    the ids of those left out and of those added. ``fill``: the room type repeated in the width
    the bays leave (a hotel's guest rooms; None: none added). ``why``, when given, collects what
    failed at each depth tried. ``ring``: each depth tried as a racetrack too, both ways round,
    and of all that pass the one keeping most rooms, then with the least corridor, kept (else
    the deepest slab that passes)."""
    raster, origin = _core.rasterise(footprint.model_dump_json(), cell)
    raster = np.asarray(raster, dtype=np.int32)
    rays = _rays(raster != -1)
    core_index = {core.id: k for k, core in enumerate(footprint.cores)}
    corridor_cells = math.ceil(needed_width(graph.hub.room_type, building_type) / cell - 1e-6)
    free = raster == -2
    if not free.any():
        return None
    dist = np.minimum.reduce([rays[d] for d in _DIRS])
    deepest = int(dist[free].max())
    hi = min(int(MAX_DEPTH / cell + 1e-6), deepest - math.ceil(corridor_cells / 2))
    lo = int(MIN_DEPTH / cell + 1e-6)
    tries = [(depth, 0) for depth in range(hi, lo - 1, -1)]
    if ring:
        tries += [(depth, way) for depth in range(int(MAX_DEPTH / cell + 1e-6), lo - 1, -1) for way in (1, 2)]
    best: tuple[tuple[int, int], tuple[FloorLayout, RoomGraph, list[str], list[str]]] | None = None
    for depth, around in tries:
        plan = _attempt(
            graph, raster, rays, depth, corridor_cells, building_type, cell, set(spare), core_index, fill,
            ring=around,
        )
        if isinstance(plan, str):
            if why is not None:
                why.append(f"at {depth * cell:g} m{f' (ring {around})' if around else ''}: {plan}")
            continue
        g = _planned_graph(graph, plan)
        ids = [n.id for n in g.nodes]
        where = {rid: k for k, rid in enumerate(ids)}
        remap = np.array([where.get(rid, -1) for rid in plan.ids] + [-1], dtype=np.int32)
        labels = np.where(plan.labels >= 0, remap[plan.labels], plan.labels)
        fault = _fault(labels, g, ids, building_type, cell, min_contact)
        if fault is not None:
            if why is not None:
                why.append(f"at {depth * cell:g} m{f' (ring {around})' if around else ''}: {fault}")
            continue
        found = (_layout(labels, g, ids, origin, cell), g, plan.dropped, [a[0] for a in plan.added])
        if not ring:
            return found
        # of the slabs and racetracks that pass, the one keeping most rooms, then the one whose
        # corridor takes least of the floor (a slab on a deep plate leaves a hall, not a corridor)
        key = (len(plan.dropped) - len(plan.added), int((labels == ids.index(graph.hub.id)).sum()))
        if best is None or key < best[0]:
            best = (key, found)
    return None if best is None else best[1]


def _planned_graph(graph: RoomGraph, plan: _Plan) -> RoomGraph:
    """``graph`` without the rooms ``plan`` left out (with their ensuites) and with the rooms it
    added, each a copy of the room it repeats (and of its ensuite), off the hub."""
    gone = set(plan.dropped)
    for e in graph.edges:
        if e.source in gone:
            gone.add(e.target)
    nodes = [n for n in graph.nodes if n.id not in gone]
    edges = [e for e in graph.edges if e.source not in gone and e.target not in gone]
    by_id = {n.id: n for n in graph.nodes}
    hub = graph.hub.id
    for room, bath, model, model_bath in plan.added:
        nodes.append(by_id[model].model_copy(update={"id": room}))
        edges.append(RoomEdge(source=hub, target=room, kind="access"))
        if bath is not None and model_bath is not None:
            nodes.append(by_id[model_bath].model_copy(update={"id": bath}))
            edges.append(RoomEdge(source=room, target=bath, kind="access"))
    return RoomGraph(nodes=nodes, edges=edges)


def _layout(labels: np.ndarray, graph: RoomGraph, ids: list[str], origin: tuple[float, float], cell: float) -> FloorLayout:
    """The floor's layout drawn from its labels as the solver draws one (its rooms by
    :func:`~mansion.building.merge.rooms_from_grid`, their walls by
    :func:`~mansion.building.merge.grid_adjacencies`), with no cut rounds to report."""
    rows, cols = labels.shape
    grid = LabelGrid(origin=origin, cell_size=cell, cols=cols, rows=rows, ids=ids, labels=labels.tolist())
    placeholders = {
        n.id: LayoutRoom(
            id=n.id, room_type=n.room_type, type=n.type, polygon=[(0.0, 0.0)] * 4, area=0.0,
            target_area=n.area, centroid=(0.0, 0.0),
        )
        for n in graph.nodes
    }
    rooms = rooms_from_grid(labels, grid, placeholders, {})
    return FloorLayout(
        rooms=rooms, grid=grid, adjacencies=grid_adjacencies(labels, ids, cell),
        diagnostics=Diagnostics(rounds=[], fallback_used=False),
    )
