"""Rooms cut again from the region they were cut from: a floor's first mend for a room the
layout left too small or without a usable square (issue 14).

A room cut from a region (an ensuite from its guest room, a kitchen from its flat, an accessible
toilet from its toilet lobby) shares that region with the room that keeps the rest. When the
layout leaves the room unfit (below its minimum area, or with no usable square: a 2.5 m² ensuite,
an accessible toilet 1 m wide), an architect draws it again inside the same region as a rectangle
of its size, and the room it was cut from keeps the rest; or takes the floor from a sibling
beside it, cut from the same region, that can give it; or, last, from any other room beside it
(a head office of an admin suite from the canteen next door). Nothing of the program is lost, so
this is tried before a merge or a drop (:mod:`mansion.building.merge`).

The new room is a rectangle of the region's cells, at least its minimum area and its clear width
on each side (the design table's), as close to its planned area as the region allows. A recut is
kept only when

- the room is no longer unfit, and neither it nor the room it was cut from has a defect of
  ``mansion eval realism`` (elongated, a sliver, below its width, no usable square) it lacked;
  the room it was cut from stays at its minimum area if it was;
- the room it was cut from stays in one piece, and every relation of either room in the room graph
  keeps its shared wall: a door's (``min_contact``) where it had one, else what it had;
- the room it was cut from gains no part that no 1 m square covers (a passage 0.5 m wide the
  agent cannot take), nor has such squares split into more pieces, two joined only where they
  overlap by a 1 m side (:func:`_passable`);
- the room is no core; a room with rooms cut from it (a guest room and its ensuite) moves only
  its own cells, theirs staying where they are, their walls with it held like every relation's;
  on a floor whose walls carry the floor above both rooms sit in one first-round region, so no
  carried wall moves.

A room of a cluster that no rectangle mends (an accessible toilet 1 m wide between two WCs and
their lobby), or a cluster's head itself (a toilet lobby without a usable square), has the whole
cluster laid out again in the cells it holds: the head (the lobby) a strip along one side, a table
width deep, the rooms cut from it side by side along the strip, each a run of whole columns with
its minimum area and a share of the rest by its planned area; every side and every order of the
rooms is tried. A re-layout is kept only when every room of the cluster is in one piece, at its
minimum area and with a usable square, no room gains a part one cell wide, every relation keeps
its wall as above, and the cluster has fewer of ``mansion eval realism``'s defects in total than
before (a lobby narrower than a mall's 2.4 m corridors for an accessible toilet that holds its
square), or as many where one of its rooms had no usable square before (three WCs a little
narrow for one 1 m wide); of those, the fewest defects, then the rooms closest to their planned areas. Only a head
that is not the hub, with two to :data:`MAX_CLUSTER` rooms none of which has rooms of its own.

A room below its clear width (``mansion eval realism``'s "narrow": an arm 1 m wide along its
neighbour, a classroom notched by the corridor) is cut again the same way once the floor's unfit
rooms are mended (:func:`recut_narrow_rooms`): a rectangle of about its own area (its area
times :data:`NARROW_SPAN`) in the region it shares with the room it was cut from, a sibling or
another room beside it, keeping as many of its cells as it can, under the same rules; it must
come out of the cut no longer narrow. A room with the one room cut from it (a ward and its
ensuite) is cut again with it as a suite (:func:`_best_suite`). What is still below its width
keeps the cells its width's squares cover and hands each strip they leave to a room beside it
that can take it (:func:`hand_off_strips`). Nothing of the program changes, so these mends are
not recorded. Last, a part of a room one cell wide is widened from a neighbour
(:func:`widen_passages`).

Of the rectangles that pass, the one closest to the room's planned area wins, then the one whose
remainder is most compact (the most of its box filled), then the region it was cut from over a
sibling, then the lowest, leftmost one; another room beside it gives only where neither the
region nor a sibling can. Each recut is recorded in the floor's ``relaxations`` ("bathroom_2
cut again from bay_3 at 5.2 m² (bathroom_2 laid out at 2.2 m², below its 3.5 m² minimum; it
was 2.2 m²)").
"""

from __future__ import annotations

import itertools
from collections.abc import Callable
from typing import overload

import numpy as np

from mansion import _core
from mansion.building.load_bearing import cut_parents, first_round_groups
from mansion.building.outlines import outline, shape_measure
from mansion.building.merge import (
    DOOR_WIDTH, USABLE_SIDE, grid_adjacencies, mask_defects, rooms_from_grid, shape_defects, square_cover,
)
from mansion.models.graph import RoomGraph, RoomNode
from mansion.models.layout import FloorLayout, LayoutRoom
from mansion.models.room_design import ELONGATED_ASPECT, needed_width, room_design
from mansion.models.room_shape import EPS, SHARE_EPS, TOLERANCE

__all__ = ["hand_off_strips", "recut_narrow_rooms", "recut_unfit_rooms", "widen_passages"]

#: A rectangle is tried up to this many times its room's planned area (or minimum, the larger).
MAX_GROWTH = 1.6
#: A room below its clear width is cut again at this span of its area (it keeps about its size;
#: the floor it takes or gives is the neighbour's). Measured on the two hundreds: 0.9-1.15 left
#: 416 and 425 rooms below their width, 0.8-1.3 leaves 398 and 411 with the rooms' mean miss from
#: their planned areas unchanged (20.0 %, 23.0 %); 0.7-1.45 leaves 373 on the first but misses
#: more (20.4 %, 20 more rooms off by over 30 %).
NARROW_SPAN = (0.8, 1.3)
#: Rectangles judged per unfit room at most, closest to its planned area first (each has its
#: shared walls measured).
MAX_TRIED = 200
#: Rectangles judged per room below its clear width at most, keeping most of its cells first.
MAX_NARROW_TRIED = 200
#: The realism defects a widened passage (:func:`widen_passages`) may leave either room with.
WIDENING_DEFECTS = frozenset({"narrow", "sliver", "elongated"})
#: Rectangles judged per suite (a room below its clear width and the one room cut from it: a ward
#: and its ensuite) at most, keeping most of the suite's cells first; and places of the room cut
#: from it judged in full per rectangle (its corners and sizes, closest to its cells first).
MAX_SUITE_TRIED = 60
MAX_INNER_TRIED = 4
#: The room cut from a suite's room is drawn up to this many times its area (or its minimum).
INNER_GROWTH = 1.5


def recut_unfit_rooms(
    layout: FloorLayout,
    graph: RoomGraph,
    unfit: Callable[[FloorLayout, RoomGraph], dict[str, str]],
    building_type: str | None = None,
    min_contact: float = 1.0,
    same_region: bool = False,
) -> tuple[FloorLayout, list[str]]:
    """Cut each room ``unfit`` names (id → why) again inside the region it shares with the room
    it was cut from (or with a sibling or another room beside it), where the module's rules
    allow; the smallest unfit room first. ``same_region``: only within one first-round region
    (floors that carry walls). Returns the layout and a relaxation note per recut."""
    notes: list[str] = []
    tried: set[str] = set()
    parent = cut_parents(graph)
    group = first_round_groups(graph) if same_region else None
    has_children = set(parent.values())
    nodes = {n.id: n for n in graph.nodes}
    while True:
        bad = {r: why for r, why in unfit(layout, graph).items() if r not in tried}
        if not bad:
            return layout, notes
        rooms = {r.id: r for r in layout.rooms}
        room = min(bad, key=lambda r: (rooms[r].area, r))
        tried.add(room)
        up = parent.get(room)
        if up is None or nodes[room].is_core:
            continue
        # a room with rooms cut from it (a guest room and its ensuite) moves its own cells only:
        # theirs stay, and their walls with it must hold (_best_recut keeps every relation's)
        best = _best_over_donors(
            layout, graph, room, up, parent, nodes, group, building_type, min_contact,
        )
        if best is None:
            # the cluster laid out again, its head a strip with its rooms along it: the room's own
            # (a toilet lobby too small or without a square), or the one it is part of when no
            # rectangle mends it (an accessible toilet 1 m wide beside two WCs)
            head = room if room in has_children else up
            found_cluster = _cluster(layout, graph, head, parent, building_type, min_contact)
            if found_cluster is not None:
                layout, note = found_cluster
                notes.append(f"{note} ({room} {bad[room]})")
            continue
        donor, layout = best
        before = rooms[room].area
        after = next(r for r in layout.rooms if r.id == room).area
        where = f"from {donor}" if donor == up else f"with floor from {donor}"
        notes.append(f"{room} cut again {where} at {after:.1f} m² ({room} {bad[room]}; it was {before:.1f} m²)")


def recut_narrow_rooms(
    layout: FloorLayout,
    graph: RoomGraph,
    building_type: str | None = None,
    min_contact: float = 1.0,
    same_region: bool = False,
) -> FloorLayout:
    """``layout`` with each room below its clear width (``mansion eval realism``'s "narrow": an L
    whose arm is narrower than a ward, a classroom notched by a corridor) cut again as a
    rectangle of about its area in the region it shares with the room it was cut from, a sibling
    or another room beside it, under the rules of a recut; a room with the one room cut from it
    (a ward and its ensuite) together with it as a suite; a room with several rooms cut from it
    laid out again with them, its strip as deep as it takes (:data:`DEEP_CLUSTERS`); circulation
    and cores are left. The rectangle that keeps most of the room's cells wins.
    Nothing of the program changes, so nothing is recorded."""
    parent = cut_parents(graph)
    group = first_round_groups(graph) if same_region else None
    has_children = set(parent.values())
    nodes = {n.id: n for n in graph.nodes}
    children: dict[str, list[str]] = {}
    for child, head in sorted(parent.items()):
        children.setdefault(head, []).append(child)
    start = {r.id: r for r in layout.rooms}
    for room in sorted(start):
        rooms = {r.id: r for r in layout.rooms}
        up = parent.get(room)
        if (
            up is None or nodes[room].is_core
            or room_design(rooms[room].room_type).circulation or not below_width(rooms[room], building_type)
        ):
            continue
        own = children.get(room, [])
        if len(own) > 1:
            # a room with several rooms cut from it (an office bay's open office with a private
            # office, a print room and a phone booth) laid out again with them, its rooms in a
            # row along one end (DEEP_CLUSTERS)
            if DEEP_CLUSTERS:
                found = _cluster(layout, graph, room, parent, building_type, min_contact, deep=True)
                if found is not None:
                    layout = found[0]
            continue
        if own and (
            own[0] in has_children or own[0] not in rooms or nodes[own[0]].is_core
            or room_design(rooms[own[0]].room_type).circulation
        ):
            continue
        best = _best_over_donors(
            layout, graph, room, up, parent, nodes, group, building_type, min_contact, narrow=True,
            inner=own[0] if own else None,
        )
        if best is not None:
            layout = best[1]
    return layout


def relay_narrow_clusters(
    layout: FloorLayout, graph: RoomGraph, building_type: str | None = None, min_contact: float = 1.0,
) -> FloorLayout:
    """``layout`` with each room below its clear width that has two to :data:`MAX_CLUSTER` rooms
    cut from it laid out again with them, its strip as deep as it takes (as
    :func:`recut_narrow_rooms` does, :data:`DEEP_CLUSTERS`): for the rooms the floor's later
    mends left so (an office bay that took a meeting room's floor). The cluster's cells stay its
    own, so no first-round region changes. Nothing of the program changes."""
    parent = cut_parents(graph)
    for room in sorted(set(parent.values())):
        rooms = {r.id: r for r in layout.rooms}
        if room in rooms and below_width(rooms[room], building_type):
            found = _cluster(layout, graph, room, parent, building_type, min_contact, deep=True)
            if found is not None:
                layout = found[0]
    return layout


def hand_off_strips(
    layout: FloorLayout,
    graph: RoomGraph,
    building_type: str | None = None,
    min_contact: float = 1.0,
    same_region: bool = False,
) -> FloorLayout:
    """``layout`` with the strips of each room below its clear width (``mansion eval realism``'s
    "narrow") handed to the rooms beside them: the room keeps the cells its width's squares cover
    (one piece, at its minimum area or what it had), and each strip the squares leave (an arm
    1.5 m wide along a guest room's ensuite, the end of an office past a meeting room) goes to one
    neighbour, the smallest that can take it, a room before circulation (a corridor is planned,
    not what is left over): no core, one piece after, at most :data:`MAX_GROWTH` times its
    planned area (or minimum), with no realism defect it lacked, no part one cell wide or split of
    its 1 m squares it lacked, and every relation of either room keeping its wall. A strip no
    neighbour takes stays (the one that holds the room's door); the room must come out no longer
    narrow and with no defect it lacked, else nothing moves.
    ``same_region``: only within one first-round region (floors that carry walls). Nothing of the
    program changes, so nothing is recorded."""
    cell = layout.grid.cell_size
    return _mend_rooms(
        layout, graph, same_region,
        lambda lay, room, nodes, group: _handed_off(lay, graph, room, nodes, group, building_type, min_contact, cell),
    )


def below_width(room: LayoutRoom, building_type: str | None) -> bool:
    """Whether ``room`` is below its clear width (``mansion eval realism``'s "narrow"), a
    rectangle at least that wide each way told without drawing its outline."""
    if _wide_rectangle(room, building_type):
        return False
    return bool(shape_measure(room, ("narrow", needed_width(room.room_type, building_type))))


def _wide_rectangle(room: LayoutRoom, building_type: str | None) -> bool:
    """Whether ``room`` is a rectangle at least its clear width each way, so not narrow: most
    rooms, told without drawing an opening or reading the grid."""
    xs, ys = zip(*room.polygon)
    w, h = max(xs) - min(xs), max(ys) - min(ys)
    return (
        not room.holes and abs(w * h - room.area) < EPS
        and min(w, h) + EPS >= needed_width(room.room_type, building_type)
    )


def _mend_rooms(
    layout: FloorLayout,
    graph: RoomGraph,
    same_region: bool,
    mend: Callable[[FloorLayout, str, dict[str, RoomNode], dict[str, str] | None], FloorLayout | None],
) -> FloorLayout:
    """``layout`` with ``mend`` (the layout, a room, the graph's nodes by id, each room's
    first-round region where floors carry walls (``same_region``) else None → the mended layout,
    or None) applied to each room of the graph but the cores, in the order of their ids."""
    nodes = {n.id: n for n in graph.nodes}
    group = first_round_groups(graph) if same_region else None
    for room in sorted(r.id for r in layout.rooms):
        if room in nodes and not nodes[room].is_core:
            layout = mend(layout, room, nodes, group) or layout
    return layout


def width_squares(
    layout: FloorLayout, room: str, nodes: dict[str, RoomNode], building_type: str | None,
) -> tuple[np.ndarray, list[str], np.ndarray, set[str], np.ndarray] | None:
    """For ``room`` below its clear width: (the layout's labels, their ids, the room's cells, its
    realism defects, the cells its width's squares cover), or None when it is not below its width
    or those cells are not one piece at its minimum area (or what it has, if less)."""
    rooms = {r.id: r for r in layout.rooms}
    kind = rooms[room].room_type
    cell = layout.grid.cell_size
    labels = layout.grid.array().astype(np.int32)
    ids = list(layout.grid.ids)
    mask = labels == ids.index(room)
    before = mask_defects(mask, kind, building_type, cell)
    if "narrow" not in before:
        return None
    keep = square_cover(mask, needed_width(kind, building_type) - 2 * EPS, cell)
    if (
        not keep.any() or not _connected(keep)
        or keep.sum() * cell * cell + EPS < min(_least(nodes[room]), rooms[room].area)
    ):
        return None
    return labels, ids, mask, before, keep


def sound_body(
    layout: FloorLayout, room: str, nodes: dict[str, RoomNode], building_type: str | None,
) -> tuple[np.ndarray, list[str], np.ndarray, np.ndarray] | None:
    """For ``room`` below its clear width whose width's squares make a sound room (one piece, at
    its minimum area or what it has, no longer below its width and with no realism defect the
    room lacks): (the layout's labels, their ids, the room's cells, the cells those squares
    cover); else None. What the squares leave is what a mend gives away or makes a room of."""
    found = width_squares(layout, room, nodes, building_type)
    if found is None:
        return None
    labels, ids, mask, before, keep = found
    after = mask_defects(keep, layout.room(room).room_type, building_type, layout.grid.cell_size)
    if "narrow" in after or not after <= before:
        return None
    return labels, ids, mask, keep


def _handed_off(
    layout: FloorLayout,
    graph: RoomGraph,
    room: str,
    nodes: dict[str, RoomNode],
    group: dict[str, str] | None,
    building_type: str | None,
    min_contact: float,
    cell: float,
) -> FloorLayout | None:
    """The layout with ``room``'s strips handed to its neighbours (:func:`hand_off_strips`), or
    None when the room is not narrow or comes out narrow still."""
    rooms = {r.id: r for r in layout.rooms}
    if _wide_rectangle(rooms[room], building_type):
        return None
    kind = rooms[room].room_type
    found = width_squares(layout, room, nodes, building_type)
    if found is None:
        return None
    labels, ids, mask, before, keep = found
    k = ids.index(room)
    new = labels
    # the largest strip first: it decides most of the room's share below its width
    for strip in sorted(_pieces(mask & ~keep), key=lambda p: (-len(p), p)):
        rows, cols = zip(*strip)
        beside = {
            int(new[r, c]) for r0, c0 in strip for r, c in ((r0 + 1, c0), (r0 - 1, c0), (r0, c0 + 1), (r0, c0 - 1))
            if 0 <= r < new.shape[0] and 0 <= c < new.shape[1] and new[r, c] >= 0 and new[r, c] != k
        }
        best: tuple[tuple[bool, int, str], np.ndarray] | None = None
        for kx in sorted(beside):
            other = ids[kx]
            if other not in nodes or nodes[other].is_core or (
                group is not None and group.get(other) != group.get(room)
            ):
                continue
            trial = new.copy()
            trial[rows, cols] = kx
            was, now = new == kx, trial == kx
            cap = max(rooms[other].target_area, _least(nodes[other])) * MAX_GROWTH
            if now.sum() * cell * cell > cap + EPS or not _connected(now) or not _connected(trial == k):
                continue
            held = rooms[other].room_type
            if not mask_defects(now, held, building_type, cell) <= mask_defects(was, held, building_type, cell):
                continue
            if any(a > b for a, b in zip(_passable(now), _passable(was))):
                continue
            if _walls(trial, ids, cell, _kept_walls(layout, graph, {room, other}), min_contact) is None:
                continue
            # a room before circulation (a corridor is planned, not what is left over), then the
            # smallest
            key = (room_design(held).circulation and not room_design(kind).circulation, int(now.sum()), other)
            if best is None or key < best[0]:
                best = (key, trial)
        if best is not None:
            new = best[1]
    if new is labels:
        return None
    after = mask_defects(new == k, kind, building_type, cell)
    if "narrow" in after or not after <= before:
        return None
    return _redrawn(layout, new)


def widen_passages(
    layout: FloorLayout,
    graph: RoomGraph,
    building_type: str | None = None,
    min_contact: float = 1.0,
    same_region: bool = False,
) -> FloorLayout:
    """``layout`` with each part of a room one cell (0.5 m) wide, which no 1 m square covers (a
    hub's strip past a neighbour to a stair), made two cells wide with the row of cells beside it
    from one neighbour, where that neighbour can give them: it is no core, stays one piece at its
    minimum area (or what it had), gains no part one cell wide and no split of its 1 m squares,
    and every relation of either room in the graph keeps its wall. The room must come out with
    fewer such cells and its squares in no more pieces. Either room may come out narrow, a sliver
    or elongated (:data:`WIDENING_DEFECTS`: a passage the agent cannot take is worse), never
    without a usable square it had. ``same_region``: only within one first-round region (floors
    that carry walls). Such strips come from rounds whose width rules were lowered to 1 m to lay
    them out at all; the agent cannot pass them."""
    cell = layout.grid.cell_size
    ids = list(layout.grid.ids)

    def widen(lay: FloorLayout, room: str, nodes: dict[str, RoomNode], group: dict[str, str] | None) -> FloorLayout:
        for strip in _thin_parts(lay.grid.array() == ids.index(room)):
            lay = _widened(lay, graph, room, strip, nodes, group, building_type, min_contact, cell) or lay
        return lay

    return _mend_rooms(layout, graph, same_region, widen)


def _thin_parts(mask: np.ndarray) -> list[list[tuple[int, int]]]:
    """The 4-connected groups of the cells of ``mask`` that no 2 × 2 block of it covers, each as
    its (row, column) cells in order."""
    _, covered = _squares(mask)
    return _pieces(mask & ~covered)


def _pieces(mask: np.ndarray) -> list[list[tuple[int, int]]]:
    """The 4-connected pieces of the True cells of ``mask``, each as its (row, column) cells in
    order, by their first cell."""
    left = {(int(r), int(c)) for r, c in zip(*np.nonzero(mask))}
    parts: list[list[tuple[int, int]]] = []
    while left:
        start = min(left)
        left.discard(start)
        part, todo = [start], [start]
        while todo:
            r, c = todo.pop()
            for n in ((r + 1, c), (r - 1, c), (r, c + 1), (r, c - 1)):
                if n in left:
                    left.discard(n)
                    part.append(n)
                    todo.append(n)
        parts.append(sorted(part))
    return parts


def _widened(
    layout: FloorLayout,
    graph: RoomGraph,
    room: str,
    strip: list[tuple[int, int]],
    nodes: dict[str, RoomNode],
    group: dict[str, str] | None,
    building_type: str | None,
    min_contact: float,
    cell: float,
) -> FloorLayout | None:
    """The layout with ``strip`` (cells of ``room`` one cell wide) widened by the cells beside it
    on one side, all of one neighbour that can give them (:func:`widen_passages`), or None."""
    labels = layout.grid.array()
    ids = list(layout.grid.ids)
    rows, cols = labels.shape
    k = ids.index(room)
    rooms = {r.id: r for r in layout.rooms}
    before = _passable(labels == k)
    unusable_before = "unusable" in mask_defects(labels == k, rooms[room].room_type, building_type, cell)
    inside = set(strip)
    for dr, dc in ((0, 1), (0, -1), (1, 0), (-1, 0)):
        # the strip and the room's cells up to two beyond its ends, along the strip (the widened
        # passage must overlap the room's squares there by a 1 m side), moved one cell aside
        ends = {
            (r + dc * e * d, c + dr * e * d) for r, c in strip for e in (1, -1) for d in (1, 2)
            if all(
                0 <= r + dc * e * j < rows and 0 <= c + dr * e * j < cols
                and labels[r + dc * e * j, c + dr * e * j] == k for j in range(1, d + 1)
            )
        }
        side = sorted(
            (r + dr, c + dc) for r, c in inside | ends
            if not (0 <= r + dr < rows and 0 <= c + dc < cols) or labels[r + dr, c + dc] != k
        )
        if not side or not all(0 <= r < rows and 0 <= c < cols for r, c in side):
            continue
        owners = {int(labels[r, c]) for r, c in side}
        if len(owners) != 1:
            continue
        (kx,) = owners
        if kx < 0 or kx == k:
            continue
        other = ids[kx]
        if other not in nodes or nodes[other].is_core or (
            group is not None and group.get(other) != group.get(room)
        ):
            continue
        new = labels.astype(np.int32)
        for r, c in side:
            new[r, c] = k
        # what that leaves of the neighbour one cell wide beside the room goes with it (the end
        # of a column the passage took)
        stubs = [cell_ for strip_ in _thin_parts(new == kx) for cell_ in strip_]
        if len(stubs) <= len(side):
            for r, c in stubs:
                if any(0 <= r + a < rows and 0 <= c + b < cols and new[r + a, c + b] == k
                       for a, b in ((0, 1), (0, -1), (1, 0), (-1, 0))):
                    new[r, c] = k
        own, rest = new == k, new == kx
        now = _passable(own)
        if now[0] >= before[0] or now[1] > before[1] or not rest.any():
            continue
        if rest.sum() * cell * cell + EPS < min(_least(nodes[other]), rooms[other].area):
            continue
        # a passage the agent cannot take is worse than a room narrower than its table asks:
        # either room may come out narrow, a sliver or elongated, never without a usable square
        other_before = labels == kx
        if not _rest_holds(
            rest, cell, rooms[other].room_type, WIDENING_DEFECTS, _passable(other_before), building_type,
        ):
            continue
        if not unusable_before and "unusable" in mask_defects(own, rooms[room].room_type, building_type, cell):
            continue
        if _walls(new, ids, cell, _kept_walls(layout, graph, {room, other}), min_contact) is None:
            continue
        return _redrawn(layout, new)
    return None


def _least(node: RoomNode) -> float:
    """A room's minimum area, m²: its own (the program's), else its type's in the design table."""
    return node.min_area if node.min_area is not None else room_design(node.room_type).min_area


def _best_over_donors(
    layout: FloorLayout,
    graph: RoomGraph,
    room: str,
    up: str,
    parent: dict[str, str],
    nodes: dict[str, RoomNode],
    group: dict[str, str] | None,
    building_type: str | None,
    min_contact: float,
    narrow: bool = False,
    inner: str | None = None,
) -> tuple[str, FloorLayout] | None:
    """(the room that gives, the layout) of the best recut of ``room`` over :func:`_donors`, the
    region it was cut from winning ties (then the siblings in order), the other rooms beside it
    only where neither gives; ``group``: each room's first-round region where floors carry walls
    (no floor crosses between two), else None.
    ``inner``: the one room cut from ``room``, recut with it as a suite (:func:`_best_suite`)."""
    rooms = {r.id for r in layout.rooms}
    best: tuple[tuple[float, float], str, FloorLayout] | None = None
    for tier in _donors(layout, room, up, parent, nodes):
        for donor in tier:
            if donor not in rooms or (group is not None and group.get(donor) != group.get(room)):
                continue
            found = (
                _best_recut(layout, graph, room, donor, building_type, min_contact, narrow=narrow)
                if inner is None else _best_suite(layout, graph, room, inner, donor, building_type, min_contact)
            )
            if found is not None and (best is None or found[0] < best[0]):
                best = (found[0], donor, found[1])
        if best is not None:
            break  # the other rooms beside give only where the room's own region cannot
    return None if best is None else (best[1], best[2])


def _kept_walls(layout: FloorLayout, graph: RoomGraph, among: set[str]) -> list[tuple[str, str, float, float]]:
    """The relations of the room graph touching a room of ``among`` that have a wall in
    ``layout``: (its rooms, the longest wall, the contact), which :func:`_walls` holds them to."""
    adj = {frozenset((a.a, a.b)): a for a in layout.adjacencies}
    return [
        (e.source, e.target, a.longest, a.contact)
        for e in graph.edges if {e.source, e.target} & among
        for a in [adj.get(frozenset((e.source, e.target)))] if a is not None
    ]


def _donors(
    layout: FloorLayout, room: str, up: str, parent: dict[str, str], nodes: dict[str, RoomNode]
) -> tuple[list[str], list[str]]:
    """The rooms ``room`` may take floor from: the region it was cut from, then each sibling
    beside it (cut from the same region), then any other room beside it (a canteen beside the
    head office of an admin suite) but one cut from ``room`` itself, each sharing a door's width
    of wall and no core; as two tiers, the region and the siblings first. The other rooms give
    only where the first tier finds no recut at all: the wall between two branches of the cut
    tree moves only where their own regions cannot mend the room (seeds 0-99: 352 -> 338 rooms
    below their width, the one room without a usable square mended; seeds 100-199: 384 -> 371;
    about 1 in 10 of the second tier's searches finds a recut)."""
    beside = sorted(
        other for a in layout.adjacencies if room in (a.a, a.b) and a.longest + EPS >= DOOR_WIDTH
        for other in [a.b if a.a == room else a.a]
        if other in nodes and not nodes[other].is_core and other != up and parent.get(other) != room
    )
    return [up] + [o for o in beside if parent.get(o) == up], [o for o in beside if parent.get(o) != up]


def _best_recut(
    layout: FloorLayout,
    graph: RoomGraph,
    room: str,
    up: str,
    building_type: str | None,
    min_contact: float,
    narrow: bool = False,
) -> tuple[tuple[float, float], FloorLayout] | None:
    """((the miss from the room's planned area, minus the remainder's fill of its box), the
    layout) of the best rectangle for ``room`` in the region it shares with ``up``, or None.
    ``narrow``: the room is below its clear width, not unfit: a rectangle of about its area
    (:data:`NARROW_SPAN`), the one keeping most of its cells first (key: (minus the cells kept,
    the miss from its area))."""
    grid = layout.grid
    labels = grid.array()
    ids = list(grid.ids)
    k_room, k_up = ids.index(room), ids.index(up)
    region = (labels == k_room) | (labels == k_up)
    rr, cc = np.nonzero(region)
    r0, r1, c0, c1 = rr.min(), rr.max() + 1, cc.min(), cc.max() + 1
    cell = grid.cell_size
    rooms = {r.id: r for r in layout.rooms}
    node = next(n for n in graph.nodes if n.id == room)
    design = room_design(node.room_type)
    least = _least(node)
    target = max(rooms[room].target_area, least)
    # at least its clear width each way (room_design.needed_width, as realism judges)
    width = needed_width(node.room_type, building_type)
    side = max(3, int(np.ceil(width / cell - 1e-6)))
    lo, hi = int(np.ceil(least / (cell * cell) - 1e-6)), int(target * MAX_GROWTH / (cell * cell))
    if narrow:
        target = max(rooms[room].area, least)
        lo = max(lo, int(np.ceil(target * NARROW_SPAN[0] / (cell * cell) - 1e-6)))
        hi = int(target * NARROW_SPAN[1] / (cell * cell))
    # the relations whose shared walls must hold, with what they had
    keep = _kept_walls(layout, graph, {room, up})
    old_room, old_up = outline(rooms[room]), outline(rooms[up])
    room_defects = shape_defects(old_room, node.room_type, building_type)
    up_defects = shape_defects(old_up, rooms[up].room_type, building_type)
    up_node = next(n for n in graph.nodes if n.id == up)
    up_least = up_node.min_area if up_node.min_area is not None else 0.0
    up_passable = _passable(labels == k_up)
    # the room comes out a rectangle at least its width each way, so of the realism defects it
    # can only be elongated: never where it was not
    stretch = np.inf if design.circulation or "elongated" in room_defects else ELONGATED_ASPECT
    hs, ws, ys, xs, kept = _windows(region, labels == k_room, side, lo, hi, stretch).T
    misses = np.abs(hs * ws * cell * cell - target)
    # the rectangles in the order of the keys below (each names one rectangle, so any sort
    # gives this order); only the first few are judged
    order = np.lexsort((ws, hs, xs, ys, misses, -kept) if narrow else (ws, hs, xs, ys, misses))
    shapes = [
        (-float(kept[i]), float(misses[i]), int(ys[i]), int(xs[i]), int(hs[i]), int(ws[i])) if narrow
        else (float(misses[i]), 0.0, int(ys[i]), int(xs[i]), int(hs[i]), int(ws[i]))
        for i in order[:MAX_NARROW_TRIED if narrow else MAX_TRIED].tolist()
    ]
    # each rectangle is judged on the region's box and the cells around it (every wall of the two
    # rooms lies there): a floor's whole grid is many times larger
    y0, y1 = max(r0 - 1, 0), min(r1 + 1, labels.shape[0])
    x0, x1 = max(c0 - 1, 0), min(c1 + 1, labels.shape[1])
    sub, sub_region = labels[y0:y1, x0:x1], region[y0:y1, x0:x1]
    # the region all ``up``'s, and its cells (each rectangle lies inside the region)
    given, region_cells = np.where(sub_region, k_up, sub).astype(np.int32), int(sub_region.sum())
    held = held_walls(ids, keep, room, up)
    best: tuple[tuple[float, float, int, int], np.ndarray] | None = None
    for first, miss, y, x, h, w in shapes[:MAX_NARROW_TRIED if narrow else MAX_TRIED]:
        if best is not None and first > best[0][0] + EPS:
            break
        left = region_cells - h * w
        if not left or left * cell * cell + EPS < min(up_least, rooms[up].area):
            continue
        new = given.copy()
        new[y - y0:y - y0 + h, x - x0:x - x0 + w] = k_room
        rest = sub_region.copy()
        rest[y - y0:y - y0 + h, x - x0:x - x0 + w] = False
        # the shared walls first (measured by the core, the cheapest test), then the pieces
        if not walls_hold(new, held, cell, min_contact):
            continue
        if not _rest_holds(rest, cell, rooms[up].room_type, up_defects, up_passable, building_type):
            continue
        ry, rx = np.nonzero(rest)
        fill = rest.sum() / ((ry.max() - ry.min() + 1) * (rx.max() - rx.min() + 1))
        key = (first, miss, y, x) if narrow else (miss, -float(fill), y, x)
        if best is None or key < best[0]:
            best = (key, new)
    if best is None:
        return None
    key, new = best
    whole = labels.astype(np.int32)
    whole[y0:y1, x0:x1] = new
    return (key[0], key[1]), _redrawn(layout, whole)


def _windows(
    region: np.ndarray, own: np.ndarray, side: int, lo: int, hi: int, stretch: float,
) -> np.ndarray:
    """(h, w, row, column, cells of ``own`` it holds), one row of an int64 array each, of every
    h × w rectangle of the grid's cells lying inside ``region``, by its lower-left cell: both
    sides at least ``side`` cells, ``lo`` to ``hi`` cells, its long side at most ``stretch`` times
    its short one. Found by the core (prefix sums of the two masks): a recut weighs thousands."""
    rr, cc = np.nonzero(region)
    box = (int(rr.min()), int(rr.max()) + 1, int(cc.min()), int(cc.max()) + 1)
    return _core.mask_windows(region, own, side, lo, hi, float(stretch), box)


def _rest_holds(
    rest: np.ndarray,
    cell: float,
    room_type: str,
    defects: set[str] | frozenset[str],
    passable: tuple[int, int],
    building_type: str | None,
) -> bool:
    """Whether what a recut leaves the room that gave (``rest``, its cells on a piece of the grid)
    is one piece with no part one cell wide it lacked, no 1 m passage cut in two (``passable``:
    its :func:`_passable` before) and no realism defect beyond ``defects``."""
    if any(a > b for a, b in zip(_passable(rest), passable)):
        return False
    return _connected(rest) and mask_defects(rest, room_type, building_type, cell) <= defects


def _best_suite(
    layout: FloorLayout,
    graph: RoomGraph,
    room: str,
    inner: str,
    up: str,
    building_type: str | None,
    min_contact: float,
) -> tuple[tuple[float, float], FloorLayout] | None:
    """((minus the suite's cells kept, the miss from its area), the layout) of the best suite
    recut of ``room`` and ``inner``, the one room cut from it (a ward and its ensuite), in the
    region the two share with ``up``; or None. The suite becomes a rectangle of about its area
    (:data:`NARROW_SPAN`) at least the room's clear width each way, keeping most of its cells;
    ``inner`` a rectangle in one of its corners (or across one end) at least its own minimum and
    clear width, up to :data:`INNER_GROWTH` times its area, placed so that the room keeps its
    minimum area and gains no realism defect: the arm beside ``inner`` is the room's width, or
    narrower and a tenth of it at most, or ``inner`` a strip across the suite's end.

    The room's shape (an L, or a rectangle) is judged first by :func:`_l_defects` (the realism
    measures worked out for an L of cells) and confirmed on its cells once it passes every other
    rule; ``inner``, a rectangle at least its width each way and no more than three times as
    long as wide, has no realism defect."""
    grid = layout.grid
    labels = grid.array()
    ids = list(grid.ids)
    cell = grid.cell_size
    k_room, k_inner, k_up = ids.index(room), ids.index(inner), ids.index(up)
    suite = (labels == k_room) | (labels == k_inner)
    region = suite | (labels == k_up)
    rooms = {r.id: r for r in layout.rooms}
    nodes = {n.id: n for n in graph.nodes}
    design, inner_design = room_design(rooms[room].room_type), room_design(rooms[inner].room_type)
    least_room, least_inner = _least(nodes[room]), _least(nodes[inner])
    side = max(3, int(np.ceil(design.min_width / cell - 1e-6)))
    inner_side = max(3, int(np.ceil(inner_design.min_width / cell - 1e-6)))
    cells = int(suite.sum())
    lo = max(
        int(np.ceil(cells * NARROW_SPAN[0] - 1e-6)),
        int(np.ceil((least_room + least_inner) / (cell * cell) - 1e-6)),
    )
    hi = int(cells * NARROW_SPAN[1])
    room_least = int(np.ceil(min(least_room, rooms[room].area) / (cell * cell) - 1e-6))
    inner_lo = int(np.ceil(least_inner / (cell * cell) - 1e-6))
    inner_hi = int(max(rooms[inner].area, least_inner) * INNER_GROWTH / (cell * cell))
    inner_target = max(rooms[inner].area, least_inner) / (cell * cell)
    before = {
        rid: shape_defects(outline(rooms[rid]), rooms[rid].room_type, building_type)
        for rid in (room, up)
    }
    allowed = before[room] - {"narrow"}
    passable = {rid: _passable(labels == ids.index(rid)) for rid in (room, up)}
    keep = _kept_walls(layout, graph, {room, inner, up})
    stretch = np.inf if "elongated" in before[room] else ELONGATED_ASPECT
    hs, ws, ys, xs, kept = _windows(region, suite, side, lo, hi, stretch).T
    misses = np.abs(hs * ws - cells)
    shapes = [
        (-int(kept[i]), int(misses[i]), int(ys[i]), int(xs[i]), int(hs[i]), int(ws[i]))
        for i in np.lexsort((ws, hs, xs, ys, misses, -kept))[:MAX_SUITE_TRIED].tolist()
    ]
    # the inner room's sizes (h, w): its minimum and width, its proportions, about its area first
    sizes = sorted(
        ((eh, ew) for eh in range(inner_side, int(inner_hi // inner_side) + 1)
         for ew in range(inner_side, int(inner_hi // inner_side) + 1)
         if inner_lo <= eh * ew <= inner_hi and max(eh, ew) <= ELONGATED_ASPECT * min(eh, ew)),
        key=lambda s: (abs(s[0] * s[1] - inner_target), s),
    )
    rr, cc = np.nonzero(region)
    y0, y1 = max(int(rr.min()) - 1, 0), min(int(rr.max()) + 2, labels.shape[0])
    x0, x1 = max(int(cc.min()) - 1, 0), min(int(cc.max()) + 2, labels.shape[1])
    sub, sub_region = labels[y0:y1, x0:x1], region[y0:y1, x0:x1]
    inner_own = (labels == k_inner)[y0:y1, x0:x1]
    # the region all ``up``'s, and its cells (each rectangle lies inside the region)
    given, region_cells = np.where(sub_region, k_up, sub).astype(np.int32), int(sub_region.sum())
    held = held_walls(ids, keep, room, up)
    best: tuple[tuple[float, float], np.ndarray] | None = None
    for first, miss, y, x, h, w in shapes[:MAX_SUITE_TRIED]:
        if best is not None and first > best[0][0]:
            break
        left = region_cells - h * w
        if not left or left * cell * cell + EPS < min(nodes[up].min_area or 0.0, rooms[up].area):
            continue
        rest = sub_region.copy()
        rest[y - y0:y - y0 + h, x - x0:x - x0 + w] = False
        rest_checked: bool | None = None
        # the inner room in each corner, at each size that leaves the room its minimum and no
        # realism defect it may not have
        spots: list[tuple[int, float, int, int, int, int]] = []
        for eh, ew in sizes:
            if (
                eh > h or ew > w or (eh == h and ew == w) or h * w - eh * ew < room_least
                or not _l_defects(h, w, eh, ew, design.min_width, cell) <= allowed
            ):
                continue
            for ey, ex in {(y, x), (y, x + w - ew), (y + h - eh, x), (y + h - eh, x + w - ew)}:
                kept = int(inner_own[ey - y0:ey - y0 + eh, ex - x0:ex - x0 + ew].sum())
                spots.append((-kept, abs(eh * ew - inner_target), ey, ex, eh, ew))
        for _, _, ey, ex, eh, ew in sorted(spots)[:MAX_INNER_TRIED]:
            new = given.copy()
            new[y - y0:y - y0 + h, x - x0:x - x0 + w] = k_room
            new[ey - y0:ey - y0 + eh, ex - x0:ex - x0 + ew] = k_inner
            if not walls_hold(new, held, cell, min_contact):
                continue
            own = new == k_room
            if any(a > b for a, b in zip(_passable(own), passable[room])):
                continue
            if rest_checked is None:
                rest_checked = _rest_holds(rest, cell, rooms[up].room_type, before[up], passable[up], building_type)
            if not rest_checked:
                break
            if not mask_defects(own, rooms[room].room_type, building_type, cell) <= allowed:
                continue
            key = (float(first), float(miss))
            if best is None or key < best[0]:
                best = (key, new)
            break
    if best is None:
        return None
    key, new = best
    whole = labels.astype(np.int32)
    whole[y0:y1, x0:x1] = new
    return key, _redrawn(layout, whole)


def _l_uncovered(h: int, w: int, eh: int, ew: int, side: int) -> int:
    """The cells of an h × w rectangle less an eh × ew one in its corner that no square ``side``
    cells wide inside it covers: the L is two overlapping bands (beyond the corner, full width;
    beside it, full height), each wholly covered when it is ``side`` wide each way and not at all
    otherwise; a corner across a whole side leaves one band."""
    top = (h - eh) * w if h - eh >= side and w >= side else 0
    beside = (w - ew) * h if w - ew >= side and h >= side else 0
    both = (h - eh) * (w - ew) if top and beside else 0
    return h * w - eh * ew - (top + beside - both)


def _l_defects(h: int, w: int, eh: int, ew: int, width: float, cell: float) -> set[str]:
    """:func:`mansion.building.merge.shape_defects` of an h × w rectangle of cells less an eh × ew
    one in its corner, for a room (not circulation) of clear width ``width``: the squares the
    measures fit (their sides a hair under the width, a hair over the usable 1 m) counted on the
    grid."""
    total = h * w - eh * ew
    clear = int(np.ceil((width - 2 * EPS) / cell))  # a square a hair narrower than the width
    usable = int(np.floor((USABLE_SIDE + 2 * EPS) / cell)) + 1  # one a hair wider than 1 m
    out: set[str] = set()
    bh, bw = (h - eh, w) if ew == w else (h, w - ew) if eh == h else (h, w)  # the L's box
    if max(bh, bw) > ELONGATED_ASPECT * min(bh, bw):
        out.add("elongated")
    if _l_uncovered(h, w, eh, ew, usable) > TOLERANCE * total + SHARE_EPS:
        out.add("sliver")
    if _l_uncovered(h, w, eh, ew, clear) > TOLERANCE * total + SHARE_EPS:
        out.add("narrow")
    if _l_uncovered(h, w, eh, ew, usable) == total:
        out.add("unusable")
    return out


def _walls(
    new: np.ndarray, ids: list[str], cell: float, keep: list[tuple[str, str, float, float]], min_contact: float,
) -> Walls | None:
    """The shared walls of label grid ``new`` (:class:`Walls`: pair → (contact, longest), metres,
    measured by the core), or None when a relation in ``keep`` (its rooms, longest wall and
    contact before) lost its wall: a door's (``min_contact``) where it had one, else what it had."""
    walls = Walls(_core.adjacencies(new.astype(np.int32)), ids, cell)
    for s, t, longest, contact in keep:
        if not wall_kept(walls.pair(s, t), longest, contact, min_contact):
            return None
    return walls


#: What :func:`walls_hold` asks of a label grid: the pairs of labels to measure (the core's
#: :func:`pair_walls`), the (longest, contact) each of the kept relations had (None for the
#: pair whose door's wall is asked), or None when a relation can never hold (a room not on the
#: grid).
Held = tuple[list[tuple[int, int]], list[tuple[float, float] | None]] | None


def held_walls(ids: list[str], keep: list[tuple[str, str, float, float]], room: str, up: str) -> Held:
    """:data:`Held` of a recut of ``room`` with ``up`` on a grid of labels ``ids``: each relation
    of ``keep`` (its rooms, the longest wall and the contact they had) and a door's width of wall
    between ``room`` and ``up`` (:func:`walls_hold`)."""
    where: dict[str, int] = {}
    for k, rid in enumerate(ids):
        where.setdefault(rid, k)  # the first of a repeated id, as list.index finds it
    pairs: list[tuple[int, int]] = []
    had: list[tuple[float, float] | None] = []
    for s, t, longest, contact in keep:
        if s == t or s not in where or t not in where:
            return None  # Walls.pair: no wall, so never kept
        pairs.append((where[s], where[t]))
        had.append((longest, contact))
    pairs.append((where[room], where[up]))
    had.append(None)
    return pairs, had


def walls_hold(new: np.ndarray, held: Held, cell: float, min_contact: float) -> bool:
    """Whether label grid ``new`` keeps the walls ``held`` names (:func:`held_walls`): every kept
    relation's (:func:`wall_kept`) and a door's width (:data:`DOOR_WIDTH`) of wall between the
    room recut and the room that gave. The same test as :func:`_walls` and its ``(room, up)`` look-up, with
    the core measuring only those pairs (the whole grid's walls, read into a dict per candidate,
    took most of the recuts' time)."""
    if held is None:
        return False
    pairs, had = held
    found = _core.pair_walls(np.asarray(new, dtype=np.int32), pairs)
    for (total, longest), was in zip(found, had):
        if was is None:
            if longest * cell + EPS < DOOR_WIDTH:
                return False
        elif not wall_kept((total * cell, longest * cell) if total else None, was[0], was[1], min_contact):
            return False
    return True


class Walls:
    """The shared walls of a label grid read as a dict of pair of room ids (a frozenset) →
    (contact, longest) in metres: only the pairs asked for are looked up by label (a floor's grid
    holds a hundred pairs where a mend asks of a few; naming them all took a tenth of the mends'
    time)."""

    __slots__ = ("_cell", "_ids", "_pairs")

    def __init__(self, pairs: list[tuple[int, int, int, int]], ids: list[str], cell: float) -> None:
        self._pairs = {(a, b): (total, longest) for a, b, total, longest in pairs}  # the core's a < b
        self._ids, self._cell = ids, cell

    def __len__(self) -> int:
        return len(self._pairs)

    def pair(self, s: str, t: str) -> tuple[float, float] | None:
        """(contact, longest) of rooms ``s`` and ``t``, None when they share no wall."""
        if s == t or s not in self._ids or t not in self._ids:
            return None
        a, b = self._ids.index(s), self._ids.index(t)
        found = self._pairs.get((a, b) if a < b else (b, a))
        return None if found is None else (found[0] * self._cell, found[1] * self._cell)

    @overload
    def get(self, key: frozenset[str]) -> tuple[float, float] | None: ...

    @overload
    def get(self, key: frozenset[str], default: tuple[float, float]) -> tuple[float, float]: ...

    def get(self, key: frozenset[str], default: tuple[float, float] | None = None) -> tuple[float, float] | None:
        """As ``dict.get`` for ``key``, a pair of room ids."""
        found = self.pair(*key) if len(key) == 2 else None
        return default if found is None else found


def wall_kept(now: tuple[float, float] | None, longest: float, contact: float, min_contact: float) -> bool:
    """Whether a relation whose wall was ``longest`` at its longest and ``contact`` in all keeps
    it in ``now`` ((contact, longest), None: no wall): a door's (``min_contact``) where it had
    one, else what it had."""
    return (
        now is not None and now[1] + EPS >= min(longest, max(DOOR_WIDTH, min_contact))
        and now[0] + EPS >= min(contact, min_contact)
    )


def _redrawn(layout: FloorLayout, new: np.ndarray) -> FloorLayout:
    """``layout`` with label grid ``new``: its rooms, outlines and shared walls drawn again."""
    grid = layout.grid
    drawn = {r.id: r for r in rooms_from_grid(new, grid, {r.id: r for r in layout.rooms}, {})}
    return layout.model_copy(update={
        "rooms": [drawn.get(r.id, r) for r in layout.rooms],
        "grid": grid.relabelled(new),
        "adjacencies": grid_adjacencies(new, list(grid.ids), grid.cell_size),
    })


def _passable(mask: np.ndarray) -> tuple[int, int]:
    """(cells no 1 m square inside ``mask`` covers, pieces the 1 m squares make when two count as
    joined only where they overlap by a 1 m side): a part one cell (0.5 m) wide is a passage the
    agent cannot take (``mansion validate``'s navigation), and so is a neck where two squares
    meet at one cell, a staircase of the grid the squares' union would call connected (building
    21 of the hundred: a corridor joined to its lift that way, which the navigation bench found).
    Counted by the core: the mends ask it of ten thousand candidates on the hundred."""
    uncovered, pieces = _core.mask_passable(mask)
    return int(uncovered), int(pieces)


def edge_grown(mask: np.ndarray) -> np.ndarray:
    """``mask`` and the cells beside its cells (edge neighbours): the ring round a room is this
    less the room."""
    out = mask.copy()
    out[1:] |= mask[:-1]
    out[:-1] |= mask[1:]
    out[:, 1:] |= mask[:, :-1]
    out[:, :-1] |= mask[:, 1:]
    return out


def _squares(mask: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(the 2 × 2 blocks of ``mask`` by their lower-left cells, the cells they cover): the 1 m
    squares of a room on the 0.5 m grid."""
    window = mask[:-1, :-1] & mask[1:, :-1] & mask[:-1, 1:] & mask[1:, 1:]
    covered = np.zeros_like(mask)
    covered[:-1, :-1] |= window
    covered[1:, :-1] |= window
    covered[:-1, 1:] |= window
    covered[1:, 1:] |= window
    return window, covered


def _box_round(mask: np.ndarray) -> tuple[slice, slice]:
    """The box of the True cells of ``mask`` and one cell round it, within the grid (the whole
    grid when there are none)."""
    rr, cc = np.nonzero(mask.any(axis=1))[0], np.nonzero(mask.any(axis=0))[0]
    if not len(rr):
        return slice(None), slice(None)
    return slice(max(int(rr[0]) - 1, 0), int(rr[-1]) + 2), slice(max(int(cc[0]) - 1, 0), int(cc[-1]) + 2)


def _connected(mask: np.ndarray) -> bool:
    """Whether the True cells of ``mask`` form one 4-connected piece (as the core draws rooms)."""
    return int(_core.mask_pieces(mask)) == 1


#: Rooms a cluster's head serves at most for it to be laid out again (their orders are tried).
MAX_CLUSTER = 4

#: Whether a room below its clear width with two to :data:`MAX_CLUSTER` rooms cut from it (an
#: office bay's open office round a private office, a print room and a phone booth) is laid out
#: again with them, the head's strip as deep as it takes (:func:`recut_narrow_rooms`,
#: ``_relaid_cluster(..., deep=True)``).
DEEP_CLUSTERS = True


def _cluster(
    layout: FloorLayout,
    graph: RoomGraph,
    head: str,
    parent: dict[str, str],
    building_type: str | None,
    min_contact: float,
    deep: bool = False,
) -> tuple[FloorLayout, str] | None:
    """The layout with the cluster of ``head`` laid out again, and its note; None when ``head``
    is the hub, a core or no cluster's head (its rooms are two to :data:`MAX_CLUSTER`, none of
    them with rooms of its own), or no re-layout passes. ``deep``: the head's strip as deep as
    it takes (:func:`_relaid_cluster`)."""
    members = sorted(r for r, up in parent.items() if up == head)
    nodes = {n.id: n for n in graph.nodes}
    if (
        head == graph.hub.id or nodes[head].is_core or not 2 <= len(members) <= MAX_CLUSTER
        or any(up in members for up in parent.values())
    ):
        return None
    found = _relaid_cluster(layout, graph, head, members, building_type, min_contact, deep)
    if found is None:
        return None
    return found[1], f"{head} laid out again with {', '.join(members)} along it"


def _relaid_cluster(
    layout: FloorLayout,
    graph: RoomGraph,
    head: str,
    members: list[str],
    building_type: str | None,
    min_contact: float,
    deep: bool = False,
) -> tuple[float, FloorLayout] | None:
    """(the rooms' total miss from their planned areas in m², the layout) of the best re-layout
    of a cluster, or None when none passes: ``head`` (a toilet lobby) as a strip along one side
    of the cells it and ``members`` (the rooms cut from it) hold, the members side by side along
    the strip in the rest, each a run of whole columns holding its share of the cells.

    ``deep``: the head's strip is tried at every depth from its clear width to all but the last
    row (an office bay's open office, the rooms cut from it in a row along one end), and each
    member's share is at least its clear width across the band's rows as well as its minimum
    area (a phone booth 1.2 m wide where the band is 3 m deep), so that the band's rooms are
    as wide as they must be rather than shares of the planned areas."""
    cluster = [head, *members]
    labels, cell, keys, region, keep, passable = cluster_cells(layout, graph, cluster)
    rooms = {r.id: r for r in layout.rooms}
    nodes = {n.id: n for n in graph.nodes}
    before = {
        rid: shape_defects(outline(rooms[rid]), rooms[rid].room_type, building_type)
        for rid in cluster
    }
    least = {rid: nodes[rid].min_area or 0.0 for rid in cluster}
    targets = {rid: max(rooms[rid].target_area, least[rid]) for rid in cluster}
    depth = max(3, int(np.ceil(room_design(rooms[head].room_type).min_width / cell - 1e-6)))
    best: tuple[float, np.ndarray] | None = None
    # the strip along each of the four sides: the grid turned so that it lies along the bottom
    for turn in range(4):
        view = np.rot90(region, turn)
        rows = np.nonzero(view.any(axis=1))[0]
        for d in range(depth, rows[-1] - rows[0] + 1) if deep else (depth,):
            strip = np.zeros_like(view)
            strip[rows[0]:rows[0] + d] = view[rows[0]:rows[0] + d]
            band = view & ~strip
            floor, want = least, targets
            if deep:
                across = int(band.any(axis=1).sum()) * cell
                floor = {m: max(least[m], needed_width(rooms[m].room_type, building_type) * across) for m in members}
                want = {m: max(targets[m], floor[m]) for m in members}
            shares = band_shares(band, members, floor, want, cell)
            if shares is None:
                continue
            columns = band_columns(band)
            for order in itertools.permutations(members):
                turned = np.rot90(labels, turn).copy()
                turned[strip] = keys[head]
                if in_a_row(turned, band, order, shares, keys, cell, columns):
                    new = np.ascontiguousarray(np.rot90(turned, -turn)).astype(np.int32)
                    score = judged_score(
                        layout, new, cluster, keep, before, least, targets, passable, building_type, min_contact,
                    )
                    if score is not None and (best is None or score < best[0] - EPS):
                        best = (score, new)
    return None if best is None else (best[0], _redrawn(layout, best[1]))


def cluster_cells(
    layout: FloorLayout, graph: RoomGraph, cluster: list[str],
) -> tuple[np.ndarray, float, dict[str, int], np.ndarray, list[tuple[str, str, float, float]], dict[str, tuple[int, int]]]:
    """What a re-layout of the rooms of ``cluster`` starts from: the layout's labels, its cell
    size, each room's label, the cells the rooms hold together, the relations whose walls must
    hold (:func:`_kept_walls`) and each room's passages (:func:`_passable`) as they are."""
    labels = layout.grid.array()
    ids = list(layout.grid.ids)
    keys = {rid: ids.index(rid) for rid in cluster}
    region = np.isin(labels, list(keys.values()))
    keep = _kept_walls(layout, graph, set(cluster))
    passable = {rid: _passable(labels == keys[rid]) for rid in cluster}
    return labels, layout.grid.cell_size, keys, region, keep, passable


def family_rules(
    layout: FloorLayout, graph: RoomGraph, family: list[str], building_type: str | None,
    labels: np.ndarray, keys: dict[str, int],
) -> tuple[dict[str, set[str]], dict[str, float], dict[str, float]]:
    """What a family re-laid is judged against (:func:`judged_score`, ``own``): each room's
    defects as it lies now (on ``labels``, its label in ``keys``), its minimum area, and its
    planned area (at least that minimum)."""
    rooms = {r.id: r for r in layout.rooms}
    nodes = {n.id: n for n in graph.nodes}
    cell = layout.grid.cell_size
    before = {rid: mask_defects(labels == keys[rid], rooms[rid].room_type, building_type, cell) for rid in family}
    least = {rid: _least(nodes[rid]) for rid in family}
    return before, least, {rid: max(rooms[rid].target_area, least[rid]) for rid in family}


def band_shares(
    band: np.ndarray, members: list[str], least: dict[str, float], targets: dict[str, float], cell: float,
) -> dict[str, float] | None:
    """Each of ``members``' share (m²) of the cells of ``band``, laid side by side along it: its
    minimum area, and what the band holds beyond the minimums in proportion to what its planned
    area asks beyond its own, the rest spread evenly; None when the band holds fewer columns than
    the members or less than their minimums."""
    if int(band.any(axis=0).sum()) < len(members):
        return None
    return area_shares(float(band.sum()) * cell * cell, members, least, targets)


def area_shares(
    area: float, members: list[str], least: dict[str, float], targets: dict[str, float],
) -> dict[str, float] | None:
    """Each of ``members``' share of ``area`` m² (:func:`band_shares`), or None when it holds
    less than their minimums."""
    room_left = area - sum(least[m] for m in members)
    if room_left < 0:
        return None
    extra = sum(targets[m] - least[m] for m in members)
    scale = min(1.0, room_left / extra) if extra > 0 else 0.0
    want = {m: least[m] + (targets[m] - least[m]) * scale for m in members}
    spare = (room_left - sum(want[m] - least[m] for m in members)) / len(members)
    return {m: w + spare for m, w in want.items()}


def band_columns(band: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The columns of ``band`` that hold cells of it, and the cells those columns hold summed
    along them: what :func:`in_a_row` cuts the band by (the same for every order tried)."""
    cols = np.nonzero(band.any(axis=0))[0]
    return cols, band[:, cols].sum(axis=0).cumsum()


def in_a_row(
    turned: np.ndarray, band: np.ndarray, order: tuple[str, ...], shares: dict[str, float],
    keys: dict[str, int], cell: float, columns: tuple[np.ndarray, np.ndarray] | None = None,
) -> bool:
    """Label the cells of ``band`` in ``turned`` (in place) with ``order``'s rooms side by side,
    each a run of whole columns holding about its share (:func:`band_shares`), the last the
    rest; False (``turned`` then half written) when a room would get no column. ``columns``: the
    band's :func:`band_columns`, where the caller has them."""
    cols, cum = band_columns(band) if columns is None else columns
    ends, share = [], 0.0
    for m in order[:-1]:
        share += shares[m]
        ends.append(int(np.searchsorted(cum, share / (cell * cell) - EPS)))
    ends.append(len(cols) - 1)
    start = 0
    for m, stop in zip(order, ends):
        if stop < start:
            return False
        # the columns from the run's first to its last: those between hold none of the band
        run = slice(int(cols[start]), int(cols[stop]) + 1)
        turned[:, run][band[:, run]] = keys[m]
        start = stop + 1
    return True


def judged_score(
    layout: FloorLayout,
    new: np.ndarray,
    cluster: list[str],
    keep: list[tuple[str, str, float, float]],
    before: dict[str, set[str]],
    least: dict[str, float],
    targets: dict[str, float],
    passable: dict[str, tuple[int, int]],
    building_type: str | None,
    min_contact: float,
    own: bool = False,
    as_many: bool = False,
) -> float | None:
    """The cluster's defects, then its total miss, of a re-laid cluster (``new``, the labels)
    when it passes the rules, else None: every room in one piece, at its minimum area, with a
    usable square, no new part one cell wide, and every relation keeping its wall; fewer defects
    over the cluster, or as many where a room of it was unusable before. With ``own`` (a family
    re-laid for a room of it below its width, :mod:`mansion.building.families`), no room may
    gain a defect it lacked and the defects must be fewer; with ``as_many`` too, as many will do
    (a room pushed out of its strips, :mod:`mansion.building.sides`, whose caller judges its own
    progress)."""
    grid = layout.grid
    ids = list(grid.ids)
    cell = grid.cell_size
    layout_types = {r.id: r.room_type for r in layout.rooms}
    # judged on the cluster's box and the cells round it (every wall of its rooms lies there): a
    # floor's grid is many times larger, and each measure is the same on the box
    whole = {rid: new == ids.index(rid) for rid in cluster}
    box = _box_round(np.logical_or.reduce(list(whole.values())))
    new = new[box]
    masks = {rid: mask[box] for rid, mask in whole.items()}
    # the cheap rules first (areas, then pieces, then the defects), the costly ones last
    if any(m.sum() * cell ** 2 + EPS < least[rid] for rid, m in masks.items()):
        return None
    if not all(_connected(m) for m in masks.values()):
        return None
    # fewer defects over the cluster than before, none of its rooms unusable (a toilet lobby
    # narrower than the building's corridors for an accessible toilet that holds its square)
    defects, miss = 0, 0.0
    for rid, mask in masks.items():
        found = mask_defects(mask, layout_types[rid], building_type, cell)
        if "unusable" in found or (own and not found <= before[rid]):
            return None
        defects += len(found)
        miss += abs(mask.sum() * cell ** 2 - targets[rid])
    # a cluster whose rooms were unusable may come out with as many defects in all (three toilets
    # a little narrow instead of one without a 1 m square, narrow and a sliver)
    was = sum(len(d) for d in before.values())
    was_unusable = any("unusable" in d for d in before.values())
    if defects > was or (defects == was and not as_many and (own or not was_unusable)):
        return None
    if any(any(a > b for a, b in zip(_passable(m), passable[rid])) for rid, m in masks.items()):
        return None
    if _walls(new, ids, cell, keep, min_contact) is None:
        return None
    return defects * 1e3 + miss
