"""Pockets made stores: the last mend for a room below its clear width (issue 14).

A room can be below its width only because of a pocket the floor's outline or a core leaves
beside it: a shop whose T-shaped floor reaches 3 m deep past a stair and a lift on either side of
its stem (mall 97, every upper floor), a food court's bay beside a stair, a flat's living room
with a corner beside its bathroom. No neighbour takes such a pocket (the only rooms beside it are
cores, or taking it would leave a neighbour too large or misshapen, or cost a door's wall), and
merging the room with a neighbour does not mend it. An architect makes the pocket a store off the
room: a storeroom beside a lift is what real plans do with it.

:func:`store_pockets` does that where it is a sound room of its own: the room keeps the cells its
width's squares cover (one piece, at least its minimum area or what it had, no longer below its
width and with no defect it lacked); every piece left over becomes a store (``storage``) cut
from the room, with a door to it (a door's width of shared wall), that has none of ``mansion eval
realism``'s defects as a store (at least the table's 2 m², a usable square, not a sliver, not
elongated) and is at most :data:`MAX_STORE` m² (a larger leftover is a room the program did not
ask for); every relation of the room keeps its wall. The floor's graph gains the store, with an
access edge from the room, and its ``relaxations`` a note per store. Nothing of the program is
lost: the room keeps its type and, with its store, its floor.

:func:`store_spare_rooms` is the last resort for a whole room: one the mends and the dissolve
leave below its minimum area or clear width, that the program can spare
(:func:`mansion.building.merge.may_spare`: not the hub, a core, circulation, a room the
description asked for, a home's only room of its kind in its flat nor the floor's last room of
its type) but no room beside it may take (its only neighbours a corridor, a core and a store
smaller than it), that is no room a home lives in (:data:`mansion.building.merge.HOME_KINDS`: a
flat's master bedroom of 8.8 m^2 stays a bedroom) and has no rooms cut from it, becomes a store
where it is a sound one (the table's 2 m^2 and 1 m width, a usable square, not elongated, at
most :data:`MAX_STORE` m^2). An office's third meeting room laid out at 6.2 m^2 of its 10 m^2 between a stair, the corridor and
a store becomes ``storage_3``: the program loses that meeting room, recorded in the floor's
``relaxations``, as it would if the room were dropped; the store keeps its relations (the door
from the corridor).
"""

from __future__ import annotations

import numpy as np

from mansion.building.load_bearing import cut_parents
from mansion.building.merge import DOOR_WIDTH, grid_adjacencies, home_kind, mask_defects, may_spare, rooms_from_grid
from mansion.building.recut import _kept_walls, _pieces, _walls, _wide_rectangle, sound_body
from mansion.models.graph import RoomEdge, RoomGraph
from mansion.models.layout import Adjacency, FloorLayout
from mansion.models.room_shape import EPS
from mansion.planning.topology import design_minimums, min_width

__all__ = ["MAX_STORE", "STORE_TYPE", "store_pockets", "store_spare_rooms"]

#: The room type a pocket becomes.
STORE_TYPE = "storage"
#: Largest store made of a pocket, m²: a storeroom, not a room of its own the program lacks.
MAX_STORE = 20.0


def store_pockets(
    layout: FloorLayout,
    graph: RoomGraph,
    building_type: str | None,
    why: str,
    min_contact: float = 1.0,
) -> tuple[FloorLayout, RoomGraph, list[str]]:
    """``layout`` and ``graph`` with the pockets of each room still below its clear width made
    stores off it where the module's rules allow, in the order of the rooms' ids; with a
    relaxation note per store naming the room and ``why`` it was mended."""
    notes: list[str] = []
    nodes = {n.id: n for n in graph.nodes}
    rooms = {r.id: r for r in layout.rooms}
    for room in sorted(rooms):
        node = nodes.get(room)
        if node is None or node.is_core or _wide_rectangle(rooms[room], building_type):
            continue
        found = _stored(layout, graph, room, building_type, min_contact)
        if found is None:
            continue
        layout, graph, stores = found
        nodes = {n.id: n for n in graph.nodes}
        rooms = {r.id: r for r in layout.rooms}
        for store in stores:
            notes.append(f"{store} made a store of {room}'s pocket ({room} {why})")
    return layout, graph, notes


def _stored(
    layout: FloorLayout, graph: RoomGraph, room: str, building_type: str | None, min_contact: float,
) -> tuple[FloorLayout, RoomGraph, list[str]] | None:
    """(the layout, the graph, the stores' ids) with ``room``'s pockets made stores, or None when
    the room is not below its width or a rule of :mod:`mansion.building.stores` fails."""
    rooms = {r.id: r for r in layout.rooms}
    nodes = {n.id: n for n in graph.nodes}
    cell = layout.grid.cell_size
    found = sound_body(layout, room, nodes, building_type)
    if found is None:
        return None
    labels, ids, mask, keep = found
    new = labels.copy()
    stores: list[tuple[str, float]] = []
    taken = set(ids)
    for piece in _pieces(mask & ~keep):
        part = np.zeros_like(mask)
        rows, cols = zip(*piece)
        part[rows, cols] = True
        area = len(piece) * cell * cell
        if area > MAX_STORE + EPS or mask_defects(part, STORE_TYPE, building_type, cell):
            return None
        n = 1
        while f"{room}_store_{n}" in taken:
            n += 1
        sid = f"{room}_store_{n}"
        taken.add(sid)
        new[rows, cols] = len(ids) + len(stores)
        stores.append((sid, area))
    all_ids = ids + [sid for sid, _ in stores]
    # every relation of the room keeps its wall, and each store has a door's width of it
    walls = _walls(new, all_ids, cell, _kept_walls(layout, graph, {room}), min_contact)
    if walls is None or any(
        walls.get(frozenset((room, sid)), (0.0, 0.0))[1] + EPS < max(DOOR_WIDTH, min_contact) for sid, _ in stores
    ):
        return None
    grid = layout.grid.relabelled(new, ids=all_ids)
    old = dict(rooms)
    for sid, area in stores:
        old[sid] = rooms[room].model_copy(update={"id": sid, "room_type": STORE_TYPE, "type": "Entities", "target_area": area})
    taken_area = sum(area for _, area in stores)
    targets = {room: max(rooms[room].target_area - taken_area, float(keep.sum()) * cell * cell)}
    laid = layout.model_copy(update={
        "rooms": rooms_from_grid(new, grid, old, targets),
        "grid": grid,
        "adjacencies": grid_adjacencies(new, all_ids, cell),
    })
    host = nodes[room]
    added = [
        host.model_copy(update={
            "id": sid, "type": "Entities", "room_type": STORE_TYPE, "area": area,
            "floor_material": None, "wall_material": None, "open_relation": "door",
            "min_width": min_width(STORE_TYPE, area, building_type),
            **design_minimums(STORE_TYPE, building_type),
        })
        for sid, area in stores
    ]
    # the room's target is what it keeps; its stores hold the rest
    kept = host.model_copy(update={"area": max(host.area - taken_area, float(keep.sum()) * cell * cell)})
    more = RoomGraph(
        nodes=[kept if n.id == room else n for n in graph.nodes] + added,
        edges=[*graph.edges, *(RoomEdge(source=room, target=sid) for sid, _ in stores)],
    )
    return laid, more, [sid for sid, _ in stores]


def store_spare_rooms(
    layout: FloorLayout,
    graph: RoomGraph,
    unfit: dict[str, str],
    building_type: str | None,
    keep: frozenset[str] | set[str] = frozenset(),
    optional: frozenset[str] | set[str] = frozenset(),
) -> tuple[FloorLayout, RoomGraph, list[str]]:
    """``layout`` and ``graph`` with each room of ``unfit`` (id -> why) that the program can
    spare made a store where it is a sound one (the module's rules), the smallest first; with a
    relaxation note per room. ``keep``: rooms the description asked for, never made stores.
    ``optional``: rooms the program can do without though they are the last of their type
    (:func:`mansion.building.merge.may_spare`)."""
    notes: list[str] = []
    cell = layout.grid.cell_size
    for room in sorted(unfit, key=lambda r: (layout.room(r).area, r)):
        nodes = {n.id: n for n in graph.nodes}
        node, laid = nodes.get(room), layout.room(room)
        parent = cut_parents(graph)
        if node is None or room in parent.values():
            continue
        if not may_spare(node, graph, parent, frozenset(keep), frozenset(optional)):
            continue
        # a room a home lives in stays one (a master bedroom of 8.8 m^2 is no store)
        if home_kind(node.room_type) is not None:
            continue
        if laid.area > MAX_STORE + EPS:
            continue
        labels = layout.grid.array()
        mask = labels == layout.grid.ids.index(room)
        if mask_defects(mask, STORE_TYPE, building_type, cell):
            continue
        n = 1
        while f"{STORE_TYPE}_{n}" in nodes:
            n += 1
        sid = f"{STORE_TYPE}_{n}"
        layout, graph = _renamed(layout, graph, room, sid, building_type)
        notes.append(f"{room} dropped, its floor made a store, {sid} ({room} {unfit[room]})")
    return layout, graph, notes


def _renamed(
    layout: FloorLayout, graph: RoomGraph, room: str, sid: str, building_type: str | None,
) -> tuple[FloorLayout, RoomGraph]:
    """``layout`` and ``graph`` with ``room`` a store of id ``sid``: its cells, walls and
    relations kept, its type, planned area and minimums a store's."""

    def name(rid: str) -> str:
        return sid if rid == room else rid

    laid = layout.room(room)
    grid = layout.grid.model_copy(update={"ids": [name(r) for r in layout.grid.ids]})
    rooms = [
        r.model_copy(update={"id": sid, "room_type": STORE_TYPE, "type": "Entities", "target_area": r.area})
        if r.id == room else r
        for r in layout.rooms
    ]
    adjacencies = [
        Adjacency(a=name(a.a), b=name(a.b), contact=a.contact, longest=a.longest) for a in layout.adjacencies
    ]
    node = next(n for n in graph.nodes if n.id == room)
    store = node.model_copy(update={
        "id": sid, "type": "Entities", "room_type": STORE_TYPE, "area": laid.area,
        "floor_material": None, "wall_material": None, "open_relation": "door",
        "min_width": min_width(STORE_TYPE, laid.area, building_type),
        **design_minimums(STORE_TYPE, building_type),
    })
    more = RoomGraph(
        nodes=[store if n.id == room else n for n in graph.nodes],
        edges=[e.model_copy(update={"source": name(e.source), "target": name(e.target)}) for e in graph.edges],
    )
    return layout.model_copy(update={"rooms": rooms, "grid": grid, "adjacencies": adjacencies}), more
