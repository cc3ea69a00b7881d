"""Two rooms cut again together: a room below its clear width and a room beside it share their
cells anew by one straight cut or one corner cut (issue 14).

The other width mends move one room's walls at a time: a rectangle of about the room's area
(:mod:`mansion.building.recut`), a wall pushed out (:mod:`mansion.building.sides`), a family laid
out again as a row (:mod:`mansion.building.families`). A room left an L round a neighbour that
is itself oddly shaped (a hotel lounge wrapped round a conference room, a ward round the nurse
station, a guest room round its ensuite) needs both redrawn: an architect draws the wall between
the two again, straight or with one corner, and each room takes a side. The rectangle of
:func:`mansion.building.recut.recut_narrow_rooms` is one such side, at about the room's own area
and with the rest one piece; here the room may keep a notch or an arm at its width, and take or
give what the other can spare down to its minimum.

:func:`recut_pairs` takes each room below its clear width (not the hub, nor a core, nor
circulation) and each room beside it sharing a door's width of wall (no core, no circulation: a
corridor is planned, not what is left over; in the same first-round region on floors that carry
walls; with corridors and the hub among them the same rooms are mended on the offline hundreds,
for more time). The cells the two hold are split by
every straight line of the grid across them and every corner (a quarter of the plane at each
grid point, each of the four ways), and the room takes either side. A split is kept only when

- the room comes out with no defect of ``mansion eval realism``'s (below its width, elongated, a
  sliver, no usable square) and at its minimum area;
- the room beside it is one piece, at its minimum area (or what it had, if less), with no defect
  it lacked, no part one cell wide it lacked nor its 1 m squares split into more pieces
  (:func:`mansion.building.recut._passable`);
- every relation of either room in the room graph keeps its wall, and the two keep a door's
  width of wall between them (:func:`mansion.building.recut.walls_hold`).

Of those, the one keeping most of the room's cells wins, then the one closest to the two rooms'
planned areas. The rooms cut from either (an ensuite of a guest room) keep their cells. Nothing of
the program changes, so nothing is recorded.

A mend of ``steps.NARROW_MENDS``, after the families are laid out again. Measured on the offline
hundreds (``mansion eval realism --generate 100 --seed 0``, ``--seed 100``): below width 45 / 27
-> 41 / 26, rooms 4,371 / 4,326 -> 4,377 / 4,332 (rooms the merges and the dissolve no longer
take), below area, elongated, slivers and rooms without a usable square unchanged (5 / 1, 16 /
11, 0 / 0, 0 / 0): hotel 166's and hotel 68's lounges, hospital 90's ward beside the nurse
station and hotel 96's two guest rooms round their ensuites. With the libraries' and
supermarkets' corridor hubs (``typologies``): below width 36 / 20 -> 32 / 19, rooms 4,353 /
4,325 -> 4,359 / 4,331, the rest unchanged. The mend takes 0.34 s of the hundred's 30 s. Tried and left: the splits closest to
the planned areas first (43 / 26); the room beside kept at 70 % of its planned area (43 / 26);
the mend before the families (the same) or once more before the dissolve (the same counts); the
hub mended so too (the same counts, 4,374 / 4,325 rooms).
"""

from __future__ import annotations

import functools

import numpy as np

from mansion.building.load_bearing import first_round_groups
from mansion.building.merge import DOOR_WIDTH, block_side, mask_defects, square_cover
from mansion.building.recut import (
    _box_round, _connected, _kept_walls, _least, _passable, _redrawn, below_width, held_walls, walls_hold,
)
from mansion.models.graph import RoomGraph
from mansion.models.layout import FloorLayout
from mansion.models.room_design import needed_width, room_design
from mansion.models.room_shape import EPS, SHARE_EPS, TOLERANCE

__all__ = ["MAX_PAIR_TRIED", "recut_pairs"]

#: Splits tried per pair of rooms at most, keeping most of the room's cells first (each judged
#: in full has its pieces and shared walls measured; the areas of all are counted at once).
#: 30 leave 43 / 26 rooms below their width on the offline hundreds, 60 41 / 26; 200 also 41 /
#: 26, with a sliver and 4 / 3 rooms fewer (what the later mends make of the rooms it moves).
MAX_PAIR_TRIED = 60


def recut_pairs(
    layout: FloorLayout,
    graph: RoomGraph,
    building_type: str | None = None,
    min_contact: float = 1.0,
    same_region: bool = False,
    tried: int | None = MAX_PAIR_TRIED,
    clean: bool = False,
) -> FloorLayout:
    """``layout`` with each room below its clear width and a room beside it cut again together by
    one straight or corner cut, where the module's rules allow; rooms in the order of their ids,
    their neighbours too, the first neighbour that mends the room taking it.
    ``same_region``: only within one first-round region (floors that carry walls). ``tried``:
    the splits judged in full per pair at most (None: every split, as
    :data:`mansion.building.steps.LAST_PAIRS` asks). ``clean``: the room beside comes out with no defect at all, not merely none it lacked (a
    bedroom already below its width never takes a flat's 1.5 m arm off its living room)."""
    nodes = {n.id: n for n in graph.nodes}
    hub = graph.hub.id
    group = first_round_groups(graph) if same_region else None
    for room in sorted(r.id for r in layout.rooms):
        node = nodes.get(room)
        if node is None or node.is_core or room == hub or room_design(node.room_type).circulation:
            continue
        if not below_width(layout.room(room), building_type):
            continue
        beside = sorted(
            other for a in layout.adjacencies if room in (a.a, a.b) and a.longest + EPS >= DOOR_WIDTH
            for other in [a.b if a.a == room else a.a]
            if other in nodes and not nodes[other].is_core
            and not room_design(nodes[other].room_type).circulation
            and (group is None or group.get(other) == group.get(room))
        )
        for other in beside:
            found = _best_pair(layout, graph, room, other, building_type, min_contact, tried, clean)
            if found is not None:
                layout = found
                break
    return layout


@functools.lru_cache(maxsize=256)
def _cuts(shape: tuple[int, int]) -> np.ndarray:
    """Every part one cut takes off a grid of ``shape``, one (way, k1, k2) row each
    (:func:`_part`): the cells below each row line and left of each column line, and each of the
    four quarters at each inner grid point (the rest of the grid is the other side of the cut).
    Cached by the shape, read only: the pairs of a floor's mends share a few shapes."""
    h, w = shape
    rows, cols = np.meshgrid(np.arange(1, h), np.arange(1, w), indexing="ij")
    k1, k2 = rows.ravel(), cols.ravel()
    parts = np.concatenate([
        np.stack([np.full(h - 1, 0), np.arange(1, h), np.zeros(h - 1, dtype=np.int64)], axis=1),
        np.stack([np.full(w - 1, 1), np.zeros(w - 1, dtype=np.int64), np.arange(1, w)], axis=1),
    ] + [np.stack([np.full(len(k1), 2 + q), k1, k2], axis=1) for q in range(4)])
    parts.flags.writeable = False
    return parts


def _counts(mask: np.ndarray, parts: np.ndarray) -> np.ndarray:
    """The cells of ``mask`` each of ``parts`` (:func:`_cuts` of its shape) holds, counted from
    prefix sums: a pair weighs thousands of parts."""
    h, w = mask.shape
    p = np.zeros((h + 1, w + 1), dtype=np.int64)
    p[1:, 1:] = mask.cumsum(axis=0).cumsum(axis=1)
    way, k1, k2 = parts.T
    ll = p[k1, k2]
    below, left = p[k1, w], p[h, k2]
    # by way: the rows below, the columns left, then the four quarters
    return np.select(
        [way == 0, way == 1, way == 2, way == 3, way == 4],
        [below, left, ll, below - ll, left - ll],
        p[h, w] - below - left + ll,
    )


def _covered(cells: np.ndarray, width: float, cell: float) -> tuple[np.ndarray, int]:
    """(the cells of each side of each cut of ``cells`` (:func:`_cuts`' parts, then their
    rests) that the squares of ``width`` lying in ``cells`` cover, those squares' cells in all).
    A side's own squares lie in ``cells``, so it is below that width (a tenth of it outside every
    such square) whenever it is so by these counts."""
    cover = square_cover(cells, width - 2 * EPS, cell)
    part = _counts(cover, _cuts(cells.shape))
    every = int(cover.sum())
    return np.concatenate([part, every - part]), every


def _thick(parts: np.ndarray, cells: np.ndarray, rest: bool) -> np.ndarray:
    """The short side, in cells, of the box each of ``parts`` (:func:`_cuts`) of ``cells`` lies
    in (``rest``: the other side of its cut), at most: the cut's lines clipped to the cells' box."""
    rr, cc = np.nonzero(cells)
    r0, r1, c0, c1 = int(rr.min()), int(rr.max()) + 1, int(cc.min()), int(cc.max()) + 1
    way, k1, k2 = parts.T
    none = np.zeros(len(way), dtype=bool)
    if rest:
        # the rest of a straight cut: the other side of its line; of a corner cut, the whole box
        below, above, left, right = none, way == 0, none, way == 1
    else:
        below, above = np.isin(way, (0, 2, 3)), np.isin(way, (4, 5))
        left, right = np.isin(way, (1, 2, 4)), np.isin(way, (3, 5))
    lo_r = np.where(above, np.maximum(k1, r0), r0)
    hi_r = np.where(below, np.minimum(k1, r1), r1)
    lo_c = np.where(right, np.maximum(k2, c0), c0)
    hi_c = np.where(left, np.minimum(k2, c1), c1)
    return np.minimum(hi_r - lo_r, hi_c - lo_c)


def _part(shape: tuple[int, int], way: int, k1: int, k2: int) -> np.ndarray:
    """The cells of a grid of ``shape`` one cut takes off (:func:`_cuts`): ``way`` 0, the rows
    below line ``k1``; 1, the columns left of line ``k2``; 2-5, the quarter at grid point
    (``k1``, ``k2``) below and left, below and right, above and left, above and right."""
    out = np.zeros(shape, dtype=bool)
    rows = slice(0, k1) if way in (0, 2, 3) else slice(k1, None) if way in (4, 5) else slice(None)
    cols = slice(0, k2) if way in (1, 2, 4) else slice(k2, None) if way in (3, 5) else slice(None)
    out[rows, cols] = True
    return out


def _best_pair(
    layout: FloorLayout,
    graph: RoomGraph,
    room: str,
    other: str,
    building_type: str | None,
    min_contact: float,
    tried: int | None = MAX_PAIR_TRIED,
    clean: bool = False,
) -> FloorLayout | None:
    """The layout with ``room`` and ``other`` cut again by the best split of their cells, or
    None when no split passes the module's rules; at most ``tried`` splits judged in full
    (None: all); ``clean``: ``other`` with no defect at all after."""
    grid = layout.grid
    labels = grid.array()
    ids = list(grid.ids)
    cell = grid.cell_size
    k_room, k_other = ids.index(room), ids.index(other)
    both = (labels == k_room) | (labels == k_other)
    # the two rooms' box and the cells round it (every wall of the two lies there)
    box = _box_round(both)
    sub = labels[box].astype(np.int32)
    cells = both[box]
    own, theirs = sub == k_room, sub == k_other
    nodes = {n.id: n for n in graph.nodes}
    r_room, r_other = layout.room(room), layout.room(other)
    unit = cell * cell
    least = _least(nodes[room]) / unit
    other_least = min(_least(nodes[other]), r_other.area) / unit
    targets = np.array([max(r_room.target_area, _least(nodes[room])), r_other.target_area]) / unit
    total, total_own = int(cells.sum()), int(own.sum())
    covered, every = _covered(cells, needed_width(r_room.room_type, building_type), cell)
    if total + EPS < least + other_least or every + EPS < (1 - TOLERANCE - SHARE_EPS) * least:
        return None  # the two cannot hold both minimums, or their cells no room at its width
    # each side of each cut for the room (the part a cut takes off, then the rest): its cells,
    # those it keeps of its own, the other's
    parts = _cuts(cells.shape)
    part_cells, part_own = _counts(cells, parts), _counts(own, parts)
    area = np.concatenate([part_cells, total - part_cells])
    kept = np.concatenate([part_own, total_own - part_own])
    rest = total - area
    # the room's side must hold its width's square: the box a side lies in (a cut's part, a
    # straight cut's rest; the rest of a corner cut is an L in the two rooms' box) wide enough
    wide = np.concatenate([_thick(parts, cells, False), _thick(parts, cells, True)]) >= block_side(
        needed_width(r_room.room_type, building_type) - 2 * EPS, cell,
    )
    # and, as the squares of a side lie in the two rooms' cells, no more than a tenth of it
    # outside every square of its width those cells hold (the same of the other room's side
    # where it was not below its width): counted for every cut at once, the splits judged in
    # full fall to a third
    sound = area - covered <= (TOLERANCE + SHARE_EPS) * area
    other_defects = set() if clean else mask_defects(theirs, r_other.room_type, building_type, cell)
    if "narrow" not in other_defects:
        # the other room's side is the rest of each cut
        covered, every = _covered(cells, needed_width(r_other.room_type, building_type), cell)
        sound &= rest - (every - covered) <= (TOLERANCE + SHARE_EPS) * rest
    fits = wide & (area + EPS >= least) & (rest + EPS >= other_least) & (area > 0) & (rest > 0) & (kept > 0)
    miss = np.abs(area - targets[0]) + np.abs(rest - targets[1])
    (found,) = np.nonzero(fits)
    order = found[np.lexsort((miss[found], -kept[found]))].tolist()
    if not order:
        return None
    other_passable = _passable(theirs)
    held = held_walls(ids, _kept_walls(layout, graph, {room, other}), room, other)
    seen: set[bytes] = set()
    judged = 0
    for i in order:
        way, k1, k2 = parts[i % len(parts)].tolist()
        side = _part(cells.shape, way, k1, k2)
        side = cells & (side if i < len(parts) else ~side)
        key = side.tobytes()
        if key in seen:
            continue  # the same cells from another cut
        seen.add(key)
        judged += 1
        if tried is not None and judged > tried:
            break
        if not sound[i]:
            continue  # a side below its width by the counts above
        # the room's shape first (one count by the core rules most splits out), then the pieces
        if mask_defects(side, r_room.room_type, building_type, cell):
            continue
        left = cells & ~side
        if not (_connected(side) and _connected(left)):
            continue
        if not mask_defects(left, r_other.room_type, building_type, cell) <= other_defects:
            continue
        if any(a > b for a, b in zip(_passable(left), other_passable)):
            continue
        new = np.where(cells, k_other, sub).astype(np.int32)
        new[side] = k_room
        if not walls_hold(new, held, cell, min_contact):
            continue
        whole = labels.astype(np.int32)
        whole[box] = new
        return _redrawn(layout, whole)
    return None
