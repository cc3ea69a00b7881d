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
"""

from __future__ import annotations

import numpy as np

from mansion.building.merge import DOOR_WIDTH, grid_adjacencies, mask_defects, rooms_from_grid
from mansion.building.recut import _kept_walls, _pieces, _walls, _wide_rectangle, sound_body
from mansion.models.graph import RoomEdge, RoomGraph
from mansion.models.layout import FloorLayout
from mansion.models.room_shape import EPS
from mansion.planning.topology import design_minimums, min_width

__all__ = ["MAX_STORE", "STORE_TYPE", "store_pockets"]

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
