"""Rooms dissolved: the last resort for a room the mends leave below its clear width or its
minimum area (issue 14).

Every mend before this one keeps the program: rooms are cut again, pushed out, laid out again in
rows, merged into a room of their kind or dropped whole into one neighbour. Some rooms no mend
reaches: a hotel's guest room 2.5 m wide between two guest rooms and the corridor, whose
neighbours cannot give without falling below their own width, and which no single neighbour can
take without becoming a 10 m long L. A program that does not fit "drops, merges or moves rooms,
never shrinks a room below its minimum" (issue 14): an architect would leave that guest room out
and give its floor to the rooms on either side of it, each taking the part beside it.

:func:`dissolve_unfit_rooms` does that for each room still below its clear width, below its
minimum area or without a usable square, the smallest first, where

- the program can do without it (:func:`mansion.building.merge.may_spare`: never the hub, a
  core, circulation, a room the description asked for, a home's only room of its kind in its
  flat, the floor's last room of its type, unless its floor's template plans it only where it
  fits: ``optional``, :data:`mansion.building.steps.SPARE_OPTIONAL`); the rooms cut from it go
  with it only when they are its own bathroom (a guest room's ensuite), else it stays;
- its floor goes to one to :data:`MAX_SHARERS` of the rooms beside it that may take it
  (:func:`mansion.building.merge.may_receive`: never a core, circulation, across the sanitary
  line or to a smaller kind of room; the region it was cut from or a room cut from the same
  region, never a room of another flat or wing; on floors that carry walls, rooms of its own
  first-round region), each growing into it from the wall they share, a row of cells at a time,
  so each takes the part nearest it;
- every room that takes a part stays in one piece, gains none of ``mansion eval realism``'s
  defects, no part the agent cannot pass, and every relation of the floor keeps its wall; the
  dropped room's relations with the rooms that stay pass to every taker that now has a door's
  wall with them (a store that opened into it opens into both rooms that took its floor), and
  one with a door that no taker has the wall for refuses the way. No room loses its way in: a
  room reached only through the dropped one was cut from it, and such a room stays.

A room the program cannot spare (a floor's only board room, 3 m wide where it needs 3.6 m) may
instead take the floor of a room beside it that the program can spare (one of two meeting
rooms), by the same rules, where it is itself among the takers and comes out at its width and
minimum area.

Of the ways that pass, the one with fewest defects over the rooms that take a part wins, then
the one that leaves them closest to their planned areas, then fewer rooms. Each dissolved room is
recorded in the floor's ``relaxations``; the rooms that take its floor take its share of the
planned area too.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterable

import numpy as np

from mansion.building.load_bearing import cut_parents, first_round_groups
from mansion.building.merge import (
    DOOR_WIDTH, grid_adjacencies, mask_defects, may_receive, may_spare, rooms_from_grid,
)
from mansion.building.recut import Walls, _connected, _kept_walls, _least, _passable, _walls, edge_grown
from mansion.models.graph import RoomEdge, RoomGraph, RoomNode
from mansion.models.layout import FloorLayout
from mansion.models.room_design import SANITARY_TYPES, design_key, room_design
from mansion.models.room_shape import EPS

__all__ = ["MAX_SHARERS", "dissolve_unfit_rooms"]

#: Rooms that may share a dissolved room's floor, at most.
MAX_SHARERS = 3


def dissolve_unfit_rooms(
    layout: FloorLayout,
    graph: RoomGraph,
    unfit: dict[str, str],
    building_type: str | None,
    keep: Iterable[str] = (),
    min_contact: float = 1.0,
    same_region: bool = False,
    optional: Iterable[str] = (),
) -> tuple[FloorLayout, RoomGraph, list[str]]:
    """``layout`` and ``graph`` with each room of ``unfit`` (id → why) dissolved where the
    module's rules allow, the smallest first; with a relaxation note per room dissolved.
    ``keep``: rooms the description asked for, never dissolved. ``same_region``: the floor
    carries walls (its floor goes only to rooms of its first-round region). ``optional``: rooms
    the program can do without though they are the last of their type
    (:func:`mansion.building.merge.may_spare`)."""
    kept = frozenset(keep)
    extra = frozenset(optional)
    notes: list[str] = []
    rooms = {r.id: r for r in layout.rooms}
    grew: set[str] = set()
    for room in sorted((r for r in unfit if r in rooms), key=lambda r: (rooms[r].area, r)):
        nodes = {n.id: n for n in graph.nodes}
        if room not in nodes:
            continue
        # a room that took a dissolved room's floor may have come out at its width and area
        if room in grew and _fit(layout, nodes[room], building_type):
            continue
        found = _best_dissolve(layout, graph, room, building_type, kept, min_contact, same_region, optional=extra)
        # a room the program cannot spare (the floor's only music room, a board room) may take
        # the floor of a room beside it that it can, where that brings it to its width and area
        for other in [] if found is not None else _beside(layout, room):
            found = _best_dissolve(
                layout, graph, other, building_type, kept, min_contact, same_region, cure=room, optional=extra,
            )
            if found is not None:
                break
        if found is None:
            continue
        layout, graph, gone, takers = found
        grew |= set(takers)
        also = f" with {', '.join(gone[1:])}" if len(gone) > 1 else ""
        why = f"{room} {unfit[room]}"
        notes.append(f"{gone[0]} dropped{also}, its floor shared by {', '.join(takers)} ({why})")
    return layout, graph, notes


def _fit(layout: FloorLayout, node: RoomNode, building_type: str | None) -> bool:
    """Whether room ``node`` is at its clear width and minimum area, with a usable square."""
    grid = layout.grid
    mask = grid.array() == grid.ids.index(node.id)
    return _cured(mask, node, layout.room(node.id).room_type, building_type, grid.cell_size)


def _beside(layout: FloorLayout, room: str) -> list[str]:
    """The rooms sharing a wall with ``room``, by id."""
    return sorted(a.b if a.a == room else a.a for a in layout.adjacencies if room in (a.a, a.b))


def _grown(labels: np.ndarray, hole: np.ndarray, takers: dict[int, np.ndarray]) -> np.ndarray | None:
    """``labels`` with the cells of ``hole`` given to the rooms ``takers`` (label → the cells it
    may take), each growing into them from its own cells a ring of edge neighbours at a time, in
    turn; None when a cell of the hole is out of their reach."""
    new = labels.copy()
    left = hole.copy()
    while left.any():
        moved = False
        for k, may in takers.items():
            front = edge_grown(new == k) & left & may
            if front.any():
                new[front] = k
                left &= ~front
                moved = True
        if not moved:
            return None
    return new


def _best_dissolve(
    layout: FloorLayout,
    graph: RoomGraph,
    room: str,
    building_type: str | None,
    keep: frozenset[str],
    min_contact: float,
    same_region: bool,
    cure: str | None = None,
    optional: frozenset[str] = frozenset(),
) -> tuple[FloorLayout, RoomGraph, list[str], list[str]] | None:
    """(the layout, the graph, the rooms that went, the rooms that took their floor) of the best
    way to dissolve ``room``, or None when none passes the module's rules. ``cure``: a room that
    must be among the takers and come out at its width and minimum area. ``optional``: as for
    :func:`dissolve_unfit_rooms`."""
    nodes = {n.id: n for n in graph.nodes}
    if room not in nodes:
        return None
    parent = cut_parents(graph)
    if not may_spare(nodes[room], graph, parent, keep, optional):
        return None
    own = sorted(kid for kid, up in parent.items() if up == room)
    # only a room's own bathroom goes with it (a guest room's ensuite); a room others were cut
    # from (a flat's living room, a toilet lobby) stays
    if own and not (room_design(nodes[room].room_type).own_bathroom and all(
        design_key(nodes[kid].room_type) in SANITARY_TYPES and kid not in keep
        and not any(up == kid for up in parent.values())
        for kid in own
    )):
        return None
    gone = [room, *own]
    grid = layout.grid
    cell = grid.cell_size
    ids = list(grid.ids)
    labels = grid.array().astype(np.int32)
    hole = np.isin(labels, [ids.index(g) for g in gone])
    region = first_round_groups(graph) if same_region else {}
    rooms = {r.id: r for r in layout.rooms}
    # the rooms beside the dropped ones that may take floor, each the cells of the dropped rooms
    # it may take: the room's floor goes to its region or its siblings, its ensuite's to theirs
    # (a bathroom's floor to a bathroom)
    ring = edge_grown(hole) & ~hole
    near = sorted({ids[k] for k in np.unique(labels[ring]) if k >= 0} - set(gone))
    allowed: dict[str, np.ndarray] = {}
    for other in near:
        if other not in nodes or (same_region and region.get(other) != region.get(room)):
            continue
        kin = parent.get(room) in (parent.get(other), other)
        may = np.zeros_like(hole)
        for g in gone:
            sibling = kin or (g != room and parent.get(parent.get(other, ""), "") == parent.get(room))
            if sibling and may_receive(nodes[g], nodes[other]):
                may |= labels == ids.index(g)
        if may.any():
            allowed[other] = may
    beside = sorted(allowed)
    if not beside or (cure is not None and cure not in beside):
        return None
    # the relations that must keep their walls: the takers' own (no other room's cells move),
    # and the dropped rooms' relations with rooms that stay, which pass to whichever taker then
    # has the wall
    kept_walls = [w for w in _kept_walls(layout, graph, set(beside)) if not {w[0], w[1]} & set(gone)]
    outward = [
        (e, e.target if e.source in gone else e.source)
        for e in graph.edges
        if (e.source in gone) != (e.target in gone)
    ]
    before = {
        t: (mask_defects(labels == ids.index(t), rooms[t].room_type, building_type, cell),
            _passable(labels == ids.index(t)))
        for t in beside
    }
    best: tuple[tuple[int, float, int, tuple[str, ...]], np.ndarray, dict[tuple[str, str], list[str]]] | None = None
    for n in range(1, min(MAX_SHARERS, len(beside)) + 1):
        for takers in itertools.combinations(beside, n):
            if cure is not None and cure not in takers:
                continue
            new = _grown(labels, hole, {ids.index(t): allowed[t] for t in takers})
            if new is None:
                continue
            judged = _judged(new, ids, cell, takers, before, rooms, building_type)
            if judged is None or (cure is not None and not _cured(new == ids.index(cure), nodes[cure], rooms[cure].room_type, building_type, cell)):
                continue
            walls = _walls(new, ids, cell, kept_walls, min_contact)
            if walls is None:
                continue
            passed = _passed(outward, takers, walls, min_contact)
            if passed is None:
                continue
            defects, miss = judged
            key = (defects, miss, n, takers)
            if best is None or key < best[0]:
                best = (key, new, passed)
    if best is None:
        return None
    (_, _, _, takers), new, passed = best
    took = {t: float((hole & (new == ids.index(t))).sum()) * cell * cell for t in takers}
    return _dissolved_layout(layout, new, gone, took), _dissolved_graph(graph, gone, took, passed), gone, list(takers)


def _cured(mask: np.ndarray, node: RoomNode, room_type: str, building_type: str | None, cell: float) -> bool:
    """Whether the room ``node`` (laid out as ``room_type``) holding the cells ``mask`` is at its
    width and minimum area, with a usable square."""
    found = mask_defects(mask, room_type, building_type, cell)
    return not found & {"narrow", "unusable"} and float(mask.sum()) * cell * cell + EPS >= _least(node)


def _judged(
    new: np.ndarray, ids: list[str], cell: float, takers: tuple[str, ...],
    before: dict[str, tuple[set[str], tuple[int, int]]], rooms: dict, building_type: str | None,
) -> tuple[int, float] | None:
    """(the takers' defects, their miss of the areas planned for them before) when
    each stays in one piece with no defect and no impassable part it lacked, else None."""
    defects, miss = 0, 0.0
    for t in takers:
        mask = new == ids.index(t)
        if not _connected(mask):
            return None
        found = mask_defects(mask, rooms[t].room_type, building_type, cell)
        was, passable = before[t]
        if not found <= was:
            return None
        if any(a > b for a, b in zip(_passable(mask), passable)):
            return None
        defects += len(found)
        # against the areas planned before: the floor goes first to the rooms short of theirs
        miss += abs(float(mask.sum()) * cell * cell - rooms[t].target_area)
    return defects, miss


def _passed(
    outward: list[tuple[RoomEdge, str]],
    takers: tuple[str, ...],
    walls: Walls,
    min_contact: float,
) -> dict[tuple[str, str], list[str]] | None:
    """For each relation of a dropped room with a room that stays (the relation, that room): the
    takers it passes to, every one that now has a door's wall with that room (the corridor's
    door to a dropped guest room passes to both guest rooms that took its floor, so neither
    loses its way in); a relation with a taker itself goes. None when a relation with a door
    finds no taker with the wall."""
    out: dict[tuple[str, str], list[str]] = {}
    for edge, other in outward:
        if other in takers:
            continue
        walled = [
            t for t in takers
            for contact, longest in [walls.get(frozenset((t, other)), (0.0, 0.0))]
            if longest + EPS >= max(DOOR_WIDTH, min_contact) and contact + EPS >= min_contact
        ]
        if not walled:
            # an adjacency promised a wall with a room that is gone; a door must find a new one
            if edge.kind == "adjacent":
                continue
            return None
        out[(edge.source, edge.target)] = walled
    return out


def _dissolved_layout(layout: FloorLayout, new: np.ndarray, gone: list[str], took: dict[str, float]) -> FloorLayout:
    """``layout`` with labels ``new`` (the dropped rooms' cells given to the takers) and the
    dropped rooms gone: the labels after each move down, each taker's planned area grown by the
    floor it took (``took``, m²)."""
    grid = layout.grid
    old_ids = list(grid.ids)
    ids = [rid for rid in old_ids if rid not in gone]
    # old label → new label (the dropped rooms hold no cells any more)
    lut = np.full(len(old_ids), -1, dtype=np.int32)
    for k, rid in enumerate(old_ids):
        if rid not in gone:
            lut[k] = ids.index(rid)
    relabelled = np.where(new >= 0, lut[np.maximum(new, 0)], new).astype(np.int32)
    rooms = {r.id: r for r in layout.rooms}
    targets = {t: rooms[t].target_area + area for t, area in took.items()}
    grid = grid.relabelled(relabelled, ids=ids)
    kept = {rid: r for rid, r in rooms.items() if rid not in gone}
    drawn = {r.id: r for r in rooms_from_grid(relabelled, grid, kept, targets)}
    return layout.model_copy(update={
        "rooms": [drawn.get(r.id, r) for r in layout.rooms if r.id not in gone],
        "grid": grid,
        "adjacencies": grid_adjacencies(relabelled, ids, grid.cell_size),
    })


def _dissolved_graph(
    graph: RoomGraph, gone: list[str], took: dict[str, float], passed: dict[tuple[str, str], list[str]],
) -> RoomGraph:
    """``graph`` without the dropped rooms: each taker's planned area grown by the floor it took
    (``took``, m²), the dropped rooms' relations passed to their takers (an access wins over an
    adjacency)."""
    edges = _dissolved_edges(graph.edges, gone, passed)
    nodes = [
        n.model_copy(update={"area": n.area + took[n.id]}) if n.id in took else n
        for n in graph.nodes if n.id not in gone
    ]
    return RoomGraph(nodes=nodes, edges=edges)


def _dissolved_edges(
    edges: list[RoomEdge], gone: list[str], passed: dict[tuple[str, str], list[str]],
) -> list[RoomEdge]:
    """``edges`` without the dropped rooms', their relations passed to their takers (an access
    wins over an adjacency)."""
    out: dict[frozenset[str], RoomEdge] = {}
    for e in edges:
        if e.source in gone or e.target in gone:
            pairs = [
                (t, e.target) if e.source in gone else (e.source, t) for t in passed.get((e.source, e.target), [])
            ]
        else:
            pairs = [(e.source, e.target)]
        for a, b in pairs:
            key = frozenset((a, b))
            if key in out and out[key].kind == "access":
                continue
            out[key] = RoomEdge(source=a, target=b, kind=e.kind)
    return list(out.values())

