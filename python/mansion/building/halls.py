"""Arms made halls: a mend for a room below its clear width because it is also a way through
(issue 14).

A room that rooms are cut from (a floor's hub, a flat's living room, an office bay's open
office) reaches every room it opens onto. When the floor is tight the cut gives it what the
others leave: a body at its width and arms narrower than it that run to the rooms it serves (a
kindergarten's play hall with a 2 m arm to its sleep room, a library's reading hall reaching
its study rooms along the stacks, a flat's living room with an arm to its bedrooms). The realism
measure rightly calls the room below its width: nobody reads in a 2 m arm. An architect draws the
arm as what it is, a corridor (a hallway in a home) off the room, with the doors the arm
carried.

:func:`hall_arms` does that where the corridor is a sound one: the room keeps the cells its
width's squares cover (one piece, at least its minimum area or what it had, no longer below its
width and with no defect it lacked); every piece left over becomes a hall cut from the room
(``corridor``; ``hallway`` in residential buildings) that

- serves: it carries a relation of the room's (a door to a room it was cut from it, a core's
  door) that the room's body no longer has the wall for, so no hall is a leftover;
- is a sound corridor: none of ``mansion eval realism``'s defects as one (at least the building
  type's corridor width, a usable square, not a sliver);
- opens onto the room: a door's width of wall, and the floor's graph gains an access edge from
  the room to it (the hall is deeper in the cut tree, so its opening follows its own
  ``open_relation``, "open": a corridor off a hall has no door).

Every relation of the room then has its wall: kept by the body, or passed to the hall that has
it (the sleep room's door moves from the play hall to its corridor; an ``adjacent`` relation,
which promises a shared wall and no passage, is never passed). A piece that serves nothing is a
store where :mod:`mansion.building.stores`' rules make one, else the room is left as it was. On
floors that carry walls the hub is never split and no room's first-round region changes, so the
walls the floor above follows stay where they are. Each hall is recorded in the floor's
``relaxations``. Nothing of the program is lost: the room keeps its type and, with its halls, its
floor.
"""

from __future__ import annotations

import numpy as np

from mansion.building.load_bearing import cut_parents, first_round_groups
from mansion.building.merge import DOOR_WIDTH, grid_adjacencies, mask_defects, rooms_from_grid
from mansion.building.recut import Walls, _pieces, _walls, _wide_rectangle, sound_body, wall_kept
from mansion.building.stores import MAX_STORE, STORE_TYPE
from mansion.models.graph import RoomEdge, RoomGraph, RoomNode
from mansion.models.layout import FloorLayout
from mansion.models.room_design import SANITARY_TYPES, design_key, room_design
from mansion.models.room_shape import EPS
from mansion.planning.room_requests import family
from mansion.planning.topology import design_minimums, min_width

__all__ = ["ENTRY_TYPE", "hall_arms", "hall_type"]

#: The room type of an arm that leads only to rooms cut from its room (its ensuite): the room's
#: own entrance lobby, held to its table width (1.2 m), not the corridors'.
ENTRY_TYPE = "entry_lobby"


def hall_type(building_type: str | None) -> str:
    """The room type of a hall made of an arm: a home's ``hallway``, elsewhere a ``corridor``
    (both take the building type's corridor width)."""
    return "hallway" if family(building_type) == "residential" else "corridor"


def hall_arms(
    layout: FloorLayout,
    graph: RoomGraph,
    building_type: str | None,
    why: str,
    min_contact: float = 1.0,
    same_region: bool = False,
) -> tuple[FloorLayout, RoomGraph, list[str]]:
    """``layout`` and ``graph`` with the arms of each room still below its clear width made
    halls off it where the module's rules allow, in the order of the rooms' ids; with a
    relaxation note per hall (and per store of a piece that serves nothing) naming the room and
    ``why`` it was mended. ``same_region``: the floor carries walls (the hub is never split, no
    room changes first-round region)."""
    notes: list[str] = []
    for room in sorted(r.id for r in layout.rooms):
        nodes = {n.id: n for n in graph.nodes}
        rooms = {r.id: r for r in layout.rooms}
        node = nodes.get(room)
        if (
            node is None or node.is_core or room not in rooms or _wide_rectangle(rooms[room], building_type)
            or (same_region and room == graph.hub.id)
        ):
            continue
        found = _split(layout, graph, room, building_type, min_contact, same_region)
        if found is None:
            continue
        layout, graph, made = found
        for new, kind in made:
            what = {STORE_TYPE: "a store", ENTRY_TYPE: "an entry"}.get(kind, "a hall")
            notes.append(f"{new} made {what} of {room}'s arm ({room} {why})")
    return layout, graph, notes


def _split(
    layout: FloorLayout, graph: RoomGraph, room: str, building_type: str | None, min_contact: float,
    same_region: bool,
) -> tuple[FloorLayout, RoomGraph, list[tuple[str, str]]] | None:
    """(the layout, the graph, the new rooms' ids and types) with ``room``'s arms made halls, or
    None when the room is not below its width or a rule of the module fails."""
    rooms = {r.id: r for r in layout.rooms}
    nodes = {n.id: n for n in graph.nodes}
    cell = layout.grid.cell_size
    found = sound_body(layout, room, nodes, building_type)
    if found is None:
        return None
    labels, ids, mask, keep = found
    hall = hall_type(building_type)
    need = max(DOOR_WIDTH, min_contact)
    # the grid with every arm a room of its own, numbered after the floor's rooms (each named
    # once it is known to be a hall or a store)
    new = labels.copy()
    pieces = _pieces(mask & ~keep)
    made: list[tuple[str, str, float]] = []
    for piece in pieces:
        rows, cols = zip(*piece)
        new[rows, cols] = len(ids) + len(made)
        made.append((f"arm {len(made)}", hall, len(piece) * cell * cell))
    all_ids = ids + [m[0] for m in made]
    walls: Walls | dict[frozenset[str], tuple[float, float]] = _walls(new, all_ids, cell, [], min_contact) or {}
    before_walls = {frozenset((a.a, a.b)): (a.contact, a.longest) for a in layout.adjacencies}

    def holds(x: str, y: str, was: tuple[float, float]) -> bool:
        return wall_kept(walls.get(frozenset((x, y))), was[1], was[0], min_contact)

    # each relation of the room kept by its body or passed to the one arm that has its wall
    edges: list[RoomEdge] = []
    serves: dict[str, int] = {m[0]: 0 for m in made}
    own: dict[str, int] = {m[0]: 0 for m in made}
    parent = cut_parents(graph)
    own_bathroom = room_design(rooms[room].room_type).own_bathroom
    for e in graph.edges:
        if room not in (e.source, e.target):
            edges.append(e)
            continue
        other = e.target if e.source == room else e.source
        was = before_walls.get(frozenset((room, other)))
        if was is None or holds(room, other, was):
            edges.append(e)
            continue
        if e.kind != "access":
            return None
        arm = next((m[0] for m in made if holds(m[0], other, was)), None)
        if arm is None:
            return None
        serves[arm] += 1
        # a bathroom of the room's own (an ensuite cut from a guest room or a ward)
        own[arm] += parent.get(other) == room and design_key(nodes[other].room_type) in SANITARY_TYPES
        edges.append(RoomEdge(source=arm, target=other, kind=e.kind) if e.source == room
                     else RoomEdge(source=other, target=arm, kind=e.kind))
    # each arm a sound hall that serves, or a sound store that needs none; each opening onto
    # the room by a door's width of wall
    final: list[tuple[str, str, float]] = []
    for (rid, _, area), piece in zip(made, pieces):
        part = np.zeros_like(mask)
        rows, cols = zip(*piece)
        part[rows, cols] = True
        wall = walls.get(frozenset((room, rid)))
        if wall is None or wall[1] + EPS < need:
            return None
        if serves[rid]:
            # an arm of a room with a bathroom of its own that leads only to it (a guest room's
            # or a ward's arm to its ensuite) is the room's own entry, not a corridor
            kind = ENTRY_TYPE if own_bathroom and own[rid] == serves[rid] else hall
            if mask_defects(part, kind, building_type, cell):
                return None
            final.append((rid, kind, area))
        elif area <= MAX_STORE + EPS and not mask_defects(part, STORE_TYPE, building_type, cell):
            final.append((rid, STORE_TYPE, area))
        else:
            return None
    # the arms named: room_hall_1, room_entry_1, room_store_1, ...
    taken, name = set(ids), {}
    for rid, typ, _ in final:
        what, n = {STORE_TYPE: "store", ENTRY_TYPE: "entry"}.get(typ, "hall"), 1
        while f"{room}_{what}_{n}" in taken:
            n += 1
        name[rid] = f"{room}_{what}_{n}"
        taken.add(name[rid])
    all_ids = [name.get(rid, rid) for rid in all_ids]
    final = [(name[rid], typ, area) for rid, typ, area in final]
    edges = [e.model_copy(update={"source": name.get(e.source, e.source), "target": name.get(e.target, e.target)}) for e in edges]
    grid = layout.grid.relabelled(new, ids=all_ids)
    old = dict(rooms)
    for rid, typ, area in final:
        old[rid] = rooms[room].model_copy(update={"id": rid, "room_type": typ, "type": "Entities", "target_area": area})
    split_area = sum(area for *_, area in final)
    kept_area = float(keep.sum()) * cell * cell
    targets = {room: max(rooms[room].target_area - split_area, kept_area)}
    host = nodes[room]
    added = [
        RoomNode.model_validate({
            "id": rid, "type": "Entities", "room_type": typ, "area": area,
            "open_relation": "open" if typ != STORE_TYPE else "door",
            "min_width": min_width(typ, area, building_type), **design_minimums(typ, building_type),
        })
        for rid, typ, area in final
    ]
    kept = host.model_copy(update={"area": max(host.area - split_area, kept_area)})
    more = RoomGraph(
        nodes=[kept if n.id == room else n for n in graph.nodes] + added,
        edges=[*edges, *(RoomEdge(source=room, target=rid) for rid, *_ in final)],
    )
    if same_region:
        # the walls the floor above follows are those between first-round regions
        now, was_groups = first_round_groups(more), first_round_groups(graph)
        if any(now.get(r) != g for r, g in was_groups.items()):
            return None
    laid = layout.model_copy(update={
        "rooms": rooms_from_grid(new, grid, old, targets),
        "grid": grid,
        "adjacencies": grid_adjacencies(new, all_ids, cell),
    })
    return laid, more, [(rid, typ) for rid, typ, _ in final]

