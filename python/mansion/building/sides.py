"""Rooms widened from the side: a room below its clear width moves a wall out into the rooms
beside it, whole rows or columns at a time (issue 14).

A room that takes what its neighbours leave (the floor's hub, a kindergarten's play hall, a
library's reading hall, a supermarket's sales floor) or one grown between two others can come
out 3.5 m wide where it needs 4.5 m, beside group rooms 6.5 m deep that could each give a metre.
The solver's repair moves one row or column at a time and takes a move only when it lowers the
room's shortfall, and a room 3.5 m wide is as narrow at 4 m as at 3.5: it takes none. An
architect moves the wall the whole metre.

:func:`widen_sides` takes each room below its width (but cores) and, along each axis, pushes it
out on one side, or on both opposite sides about evenly, by up to its width in cells: every cell
of a neighbour within that reach of the room in that direction goes to the room, across the whole
side, so the walls it moves stay straight (a core or the outline stops it). A push on one side is
also tried with the rooms it takes from sliding over as far into the rooms beyond them
(:data:`SLIDES`: a group room at its width beside the hall moves a metre into the sleep room
beyond it rather than giving the metre). The donors are the rooms those cells belonged to (never
a core; on floors that carry walls, only rooms of the room's own first-round region). Of the
pushes that leave fewer of the room's cells outside its width's squares, those that leave fewest
(then take fewest cells) are judged, :data:`MAX_JUDGED` per axis (one that leaves a neighbour
below its minimum area, as most do on a tight floor, is passed over without counting); a
neighbour's cell the push leaves outside every 1 m square of the neighbour's goes to a room
beside it whose square it completes (a corridor's cell in the corner by a toilet, to the
toilet). They are judged under the rules of a family re-laid
(:func:`mansion.building.recut.judged_score`): no room of them gains a defect of ``mansion eval
realism`` it lacked, each stays in one piece at its minimum area with no new part one cell wide,
and every relation keeps its wall. The room need not come out at its width: what is left of its
strips (the arm of an L) goes to the mends after this one (a hall made of it,
:mod:`mansion.building.halls`). Of the pushes that pass, the one leaving fewest cells outside the
squares wins, then the fewest defects, then the rooms closest to their planned areas. Nothing of
the program changes, so nothing is recorded.

The same pushes serve a room below its minimum area (:func:`enlarge_rooms`): of those that bring
it to its minimum, the ones taking fewest cells are judged the same way. The floor's steps run it
before a room too small is merged into a neighbour or dropped, and again once the width mends
are done (a private office 7.5 m² of its 8 m² takes half a metre of the meeting room beside it
rather than becoming part of it).
"""

from __future__ import annotations

import numpy as np

from mansion.building.load_bearing import first_round_groups
from mansion import _core
from mansion.building.merge import block_side, mask_defects
from mansion.building.recut import _kept_walls, _least, _passable, _redrawn, _squares, _wide_rectangle, judged_score
from mansion.models.graph import RoomGraph, RoomNode
from mansion.models.layout import FloorLayout
from mansion.models.room_design import needed_width
from mansion.models.room_shape import EPS

__all__ = ["enlarge_rooms", "widen_sides"]

def widen_sides(
    layout: FloorLayout,
    graph: RoomGraph,
    building_type: str | None,
    min_contact: float = 1.0,
    same_region: bool = False,
) -> FloorLayout:
    """``layout`` with each room below its clear width widened by pushing its sides out into its
    neighbours where the module's rules allow, rooms in the order of their ids.
    ``same_region``: only into rooms of its own first-round region (floors that carry walls)."""
    nodes = {n.id: n for n in graph.nodes}
    group = first_round_groups(graph) if same_region else None
    cell = layout.grid.cell_size
    for room in sorted(r.id for r in layout.rooms):
        rooms = {r.id: r for r in layout.rooms}
        if room not in nodes or nodes[room].is_core or _wide_rectangle(rooms[room], building_type):
            continue
        labels = layout.grid.array()
        ids = list(layout.grid.ids)
        mask = labels == ids.index(room)
        if "narrow" not in mask_defects(mask, rooms[room].room_type, building_type, cell):
            continue
        found = _pushed(layout, graph, room, labels, ids, nodes, group, building_type, min_contact)
        if found is not None:
            layout = found
    return layout


def _uncovered(mask: np.ndarray, width: float, cell: float) -> int:
    """Cells of ``mask`` that no square ``width`` metres wide inside it covers (those
    :func:`~mansion.building.merge.square_cover` leaves, counted by the core)."""
    return int(mask.sum()) - int(_core.covered_cells(mask, block_side(width - 2 * EPS, cell)))


def enlarge_rooms(
    layout: FloorLayout,
    graph: RoomGraph,
    building_type: str | None,
    min_contact: float = 1.0,
    same_region: bool = False,
) -> FloorLayout:
    """``layout`` with each room still below its minimum area pushed out into its neighbours,
    on one side or two opposite sides, as far as its minimum needs and no farther, where the
    module's rules allow (a staff office 7.5 m² of its 9 m² taking half a metre of the rooms
    beside it), rooms in the order of their ids. ``same_region`` as for :func:`widen_sides`."""
    nodes = {n.id: n for n in graph.nodes}
    group = first_round_groups(graph) if same_region else None
    for room in sorted(r.id for r in layout.rooms):
        node = nodes.get(room)
        if node is None or node.is_core or layout.room(room).area + EPS >= _least(node):
            continue
        found = _pushed(
            layout, graph, room, layout.grid.array(), list(layout.grid.ids), nodes, group, building_type,
            min_contact, area=_least(node),
        )
        if found is not None:
            layout = found
    return layout


def _pushes(mask: np.ndarray, givers: np.ndarray, dy: int, dx: int, reach: int) -> list[np.ndarray]:
    """The cells ``mask`` gains pushed out 1, 2, … up to ``reach`` cells in direction (``dy``,
    ``dx``), through its own cells and those of ``givers`` only (a core or the outline stops it):
    one entry per depth that gains a cell."""
    out: list[np.ndarray] = []
    grown = mask.copy()
    step = mask.copy()
    h, w = mask.shape
    for _ in range(reach):
        moved = np.zeros_like(step)
        moved[max(dy, 0):h + min(dy, 0), max(dx, 0):w + min(dx, 0)] = step[
            max(-dy, 0):h + min(-dy, 0), max(-dx, 0):w + min(-dx, 0)
        ]
        step = moved & (grown | givers)
        added = step & ~grown
        if not added.any():
            break
        grown |= added
        out.append(grown & ~mask)
    return out


def _take_nubs(new: np.ndarray, labels: np.ndarray, key: int, donors: list[int], may_take: np.ndarray) -> set[int]:
    """Give each cell of ``donors`` that the push left outside every 1 m square of theirs (in
    ``new``, in place) to a room beside it whose 1 m square it then completes, the pushed room
    (``key``) first, only rooms ``may_take`` allows by label (no core; on floors that carry walls
    none of another first-round region): a corridor's cell left in the corner between a toilet
    and the wall the push moved, which no agent passes, goes to the toilet. The rooms given
    cells, besides ``key``."""
    given: set[int] = set()
    h, w = new.shape
    for donor in donors:
        _, covered = _squares(new == donor)
        _, covered_before = _squares(labels == donor)
        for r, c in zip(*np.nonzero((new == donor) & ~covered & covered_before)):
            around = {int(new[y, x]) for y, x in ((r - 1, c), (r + 1, c), (r, c - 1), (r, c + 1)) if 0 <= y < h and 0 <= x < w}
            for taker in sorted(around - {donor, -1}, key=lambda k: (k != key, k)):
                # the taker's three cells of a 2 × 2 block round this one
                if may_take[taker] and any(
                    0 <= r + dy < h and 0 <= c + dx < w
                    and new[r + dy, c + dx] == new[r + dy, c] == new[r, c + dx] == taker
                    for dy in (-1, 1) for dx in (-1, 1)
                ):
                    new[r, c] = taker
                    if taker != key:
                        given.add(taker)
                    break
    return given


#: Whether a one-sided push is also tried with the rooms it takes from sliding over as far into
#: the rooms beyond them (a room pushed into a row of rooms at their width moves the whole row).
SLIDES = True

#: Pushes judged in full per axis, at most (the fewest cells left outside the width's squares
#: first, then the fewest taken).
MAX_JUDGED = 3


def _pushed(
    layout: FloorLayout,
    graph: RoomGraph,
    room: str,
    labels: np.ndarray,
    ids: list[str],
    nodes: dict[str, RoomNode],
    group: dict[str, str] | None,
    building_type: str | None,
    min_contact: float,
    area: float | None = None,
) -> FloorLayout | None:
    """The best push of ``room``'s sides that passes, or None: one side, or two opposite sides
    each pushed part of the way (a hall 3.5 m wide between two rows of rooms that can each give
    half a metre). With ``area``, the pushes that bring the room to that many m², fewest cells
    first, instead of those that leave fewer of its cells outside its width's squares."""
    cell = layout.grid.cell_size
    rooms = {r.id: r for r in layout.rooms}
    key = ids.index(room)
    mask = labels == key
    # the labels a push may take cells from: rooms of the graph, no core, and on floors that
    # carry walls only those of the room's own first-round region
    may_give = np.zeros(len(ids), dtype=bool)
    for i, rid in enumerate(ids):
        node = nodes.get(rid)
        may_give[i] = (
            i != key and node is not None and not node.is_core
            and (group is None or group.get(rid) == group.get(room))
        )
    inside = labels >= 0
    givers = np.zeros_like(mask)
    givers[inside] = may_give[labels[inside]]
    # the rooms a neighbour's stranded cell may go to: the room, or one that may give
    may_take = may_give.copy()
    may_take[key] = True
    width = needed_width(rooms[room].room_type, building_type)
    reach = int(np.ceil(width / cell - 1e-6))
    # what a push must improve on: the cells outside the width's squares (pushing for area, none)
    was = _uncovered(mask, width, cell) if area is None else 0
    before: dict[str, set[str]] = {}
    passable: dict[str, tuple[int, int]] = {}
    best: tuple[tuple[int, float], np.ndarray] | None = None
    for axis in (((1, 0), (-1, 0)), ((0, 1), (0, -1))):
        ahead, back = (_pushes(mask, givers, dy, dx, reach) for dy, dx in axis)
        none = np.zeros_like(mask)
        # (cells left outside the squares, cells taken, slid, the cells, the one side's
        # direction and depth when one side only)
        tried: list[tuple[int, int, bool, np.ndarray, tuple[int, int] | None, int]] = []
        for a in range(len(ahead) + 1):
            for b in range(len(back) + 1):
                # one side, or both about evenly
                if not 0 < a + b <= reach or (a and b and abs(a - b) > 1):
                    continue
                taken = (ahead[a - 1] if a else none) | (back[b - 1] if b else none)
                if area is not None:
                    if float((mask | taken).sum()) * cell * cell + EPS >= area:
                        left = 0
                    else:
                        continue
                else:
                    left = _uncovered(mask | taken, width, cell)
                    if left >= was:
                        continue
                side = axis[0] if not b else axis[1] if not a else None
                tried.append((left, int(taken.sum()), False, taken, side, a or b))
                if side is not None and SLIDES:
                    # or the rooms it takes from slide over as far into the rooms beyond them
                    tried.append((left, int(taken.sum()), True, taken, side, a or b))
        tried.sort(key=lambda t: t[:3])
        judged = 0
        for left, _, slid, taken, side, depth in tried:
            if judged == MAX_JUDGED:
                break
            new = labels.copy()
            new[taken] = key
            donors = {int(k) for k in np.unique(labels[taken])}
            if slid and side is not None:
                for d in sorted(donors):
                    own = labels == d
                    gains = _pushes(own, givers & ~mask & ~own & ~taken, side[0], side[1], depth)
                    if gains:
                        new[gains[-1]] = d
            # every room the push changed, and a push that leaves one of them below its minimum
            # area (most are) refused before it counts among the judged: a shallower one may
            # leave it enough
            changed = sorted({int(k) for k in np.unique(labels[new != labels])} - {key})
            if any(
                not (new == d).any() or float((new == d).sum()) * cell * cell + EPS < _least(nodes[ids[d]])
                for d in changed
            ):
                continue  # (or a room would be taken whole)
            judged += 1
            takers = _take_nubs(new, labels, key, changed, may_take)
            cluster = [room, *sorted({ids[d] for d in changed} | {ids[t] for t in takers})]
            for rid in cluster:
                if rid not in before:
                    own = labels == ids.index(rid)
                    before[rid] = mask_defects(own, rooms[rid].room_type, building_type, cell)
                    passable[rid] = _passable(own)
            least = {rid: _least(nodes[rid]) for rid in cluster}
            if area is not None:
                least[room] = area
            targets = {rid: max(rooms[rid].target_area, least[rid]) for rid in cluster}
            score = judged_score(
                layout, new.astype(np.int32), cluster, _kept_walls(layout, graph, set(cluster)),
                {rid: before[rid] for rid in cluster}, least, targets,
                {rid: passable[rid] for rid in cluster}, building_type, min_contact, own=True, as_many=True,
            )
            if score is not None:
                if best is None or (left, score) < best[0]:
                    best = ((left, score), new.astype(np.int32))
                break  # the best of this axis
    # only the kept push is drawn
    return None if best is None else _redrawn(layout, best[1])
