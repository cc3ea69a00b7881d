"""The offline floor planner: a floor's program → its room graph (the paper's bubble graph).

The hub (the program's first room) is the ``main`` node; every core on the floor is a fixed node
reached from the hub through a door; each zone's sub-hub is an ``area`` node reached from the hub,
with the zone's rooms reached from it; the other rooms hang off the hub. Rooms whose type is open
by nature (a kitchenette, a checkout area) open to their parent instead of a door; a room with a
``parent`` (an ensuite) is reached from that room. The typology's adjacencies ("kitchen beside
the dining room") become ``adjacent`` edges where both rooms exist and no edge joins them yet.

Every node gets its minimum clear width from the room design table
(:mod:`mansion.models.room_design`); corridors take the building type's corridor width.
"""

from __future__ import annotations

import math

from mansion.models.building import BuildingCore, FloorProgram
from mansion.models.graph import RoomEdge, RoomGraph, RoomNode
from mansion.models.room_design import (
    CORRIDOR_TYPES,
    ELONGATED_ASPECT,
    corridor_width,
    design_key,
    planned_width,
    room_design,
)
from mansion.planning.vocabulary import room_kind

__all__ = [
    "MAX_NODE_WIDTH",
    "WIDE_ROOM_WIDTH",
    "design_minimums",
    "floor_graph",
    "min_width",
    "with_min_widths",
]

#: A room's minimum width never asks for a squarer room than this (width² · aspect ≤ area), so a
#: room squeezed to its minimum area can still be laid out.
_MIN_ASPECT = 1.5
#: The widest clear width a node asks of the solver: the rooms the table gives at most this ask
#: for their table width (accessible toilets 1.6 m, kitchens 1.8 m: 2.0 m on the 0.5 m grid).
#: Wider rooms (bedrooms 2.15 m, wards 3.2 m, classrooms 5.4 m) and corridors ask for at most
#: :data:`WIDE_ROOM_WIDTH` and keep their shape through their area and the solver's compactness
#: and aspect terms. Measured on the offline hundred (seeds 0–99, with the program's hub spine,
#: issue 14), slivers / rooms below their table width: every node capped at 1.5 m, 2.3 % /
#: 35.6 %; this rule, 2.3 % / 31.8 %; every node at up to 2.0 m, 4.6 % / 32.5 %; corridors at up
#: to 2.0 m and wider rooms at 1.5 m, 3.5 % / 32.5 % (hospital wards and ensuites lose most). On
#: seeds 0–27, every node at up to 2.0 m took 1.6 times as long as at 1.5 m, up to 2.5 m 2.7
#: times. (Before the hub spine: corridors at their building type's full width, up to 2.4 m,
#: relaxed 14 of 100 floors; the table's full widths made half the floors fail and drop every
#: rule.)
MAX_NODE_WIDTH = 2.0
#: The width rule of corridors, and of rooms whose table width is above :data:`MAX_NODE_WIDTH`.
WIDE_ROOM_WIDTH = 1.5


def min_width(room_type: str, area: float, building_type: str | None) -> float:
    """The minimum clear width (m) of a room of ``room_type`` and ``area`` m² in a building of
    ``building_type``: the table's, a corridor's the building type's, never more than a room of
    this area can have nor more than :data:`MAX_NODE_WIDTH` (:data:`WIDE_ROOM_WIDTH` for a
    corridor or a room whose table width is above that)."""
    width = room_design(room_type).min_width
    corridor = design_key(room_type) in CORRIDOR_TYPES
    if corridor:
        # corridors are planned as length × width (their area) at their building type's width
        width = max(width, corridor_width(building_type))
    cap = WIDE_ROOM_WIDTH if corridor or width > MAX_NODE_WIDTH else MAX_NODE_WIDTH
    return round(min(width, cap, math.sqrt(area / _MIN_ASPECT)), 2)


def design_minimums(room_type: str, building_type: str | None) -> dict[str, float | None]:
    """What the solver's repair brings a finished room of ``room_type`` up to
    (:attr:`RoomNode.min_area`, ``clear_width``, ``max_aspect``): the table's minimum area, its
    clear width (:func:`~mansion.models.room_design.planned_width`: circulation's its building
    type's corridor width), and for rooms that are not circulation the box proportions beyond
    which a room counts as elongated. The figures ``mansion eval realism`` measures, but a toilet
    lobby planned as wide as a corridor though judged at its own width."""
    d = room_design(room_type)
    width = planned_width(room_type, building_type)
    return {
        "min_area": d.min_area,
        "clear_width": width,
        "max_aspect": None if d.circulation else max(d.max_aspect, ELONGATED_ASPECT),
    }


def with_min_widths(graph: RoomGraph, building_type: str | None) -> RoomGraph:
    """``graph`` with :attr:`RoomNode.min_width` filled for every room that has none, and the
    design minimums of :func:`design_minimums` where a room has none of them (cores keep none:
    the footprint fixes them)."""
    def filled(n: RoomNode) -> RoomNode:
        update: dict[str, float | None] = {}
        if n.min_width is None:
            update["min_width"] = min_width(n.room_type, n.area, building_type)
        if n.min_area is None and n.clear_width is None and n.max_aspect is None:
            update.update(design_minimums(n.room_type, building_type))
        return n.model_copy(update=update) if update else n

    nodes = [n if n.is_core or n.area <= 0 else filled(n) for n in graph.nodes]
    return RoomGraph(nodes=nodes, edges=graph.edges)


def floor_graph(
    program: FloorProgram,
    cores: list[BuildingCore],
    adjacent: tuple[tuple[str, str], ...] = (),
    building_type: str | None = None,
) -> RoomGraph:
    """The room graph of ``program`` with the cores that serve its floor."""
    hub = program.rooms[0]
    nodes = [
        RoomNode(
            id=hub.id, type="main", area=hub.area, room_type=hub.room_type,
            floor_material=hub.floor_material, wall_material=hub.wall_material,
            open_relation="open", min_width=min_width(hub.room_type, hub.area, building_type),
            **design_minimums(hub.room_type, building_type),
        )
    ]
    edges: list[RoomEdge] = []
    for core in cores:
        if program.index in core.floors:
            nodes.append(
                RoomNode(
                    id=core.id, type=core.type,
                    area=(core.x[1] - core.x[0]) * (core.y[1] - core.y[0]), room_type=core.type,
                    floor_material=hub.floor_material, wall_material=hub.wall_material,
                    open_relation="door",
                )
            )
            edges.append(RoomEdge(source=hub.id, target=core.id, kind="access"))
    zone_hub: dict[str, str] = {}
    for room in program.rooms[1:]:
        is_sub_hub = room.parent is None and room.zone is not None and room.zone not in zone_hub
        if room.parent is not None:
            parent = room.parent
        elif is_sub_hub:
            assert room.zone is not None
            zone_hub[room.zone] = room.id
            parent = hub.id
        else:
            parent = zone_hub[room.zone] if room.zone is not None else hub.id
        nodes.append(
            RoomNode(
                id=room.id, type="area" if is_sub_hub else "Entities", area=room.area,
                room_type=room.room_type, floor_material=room.floor_material,
                wall_material=room.wall_material,
                open_relation="open" if room_kind(room.room_type).open else "door",
                min_width=min_width(room.room_type, room.area, building_type),
                **design_minimums(room.room_type, building_type),
            )
        )
        edges.append(RoomEdge(source=parent, target=room.id, kind="access"))
    joined = {frozenset((e.source, e.target)) for e in edges}
    by_type: dict[str, list[str]] = {}
    for node in nodes:
        by_type.setdefault(node.room_type, []).append(node.id)
    for a, b in adjacent:
        for ida in by_type.get(a, [])[:1]:
            for idb in by_type.get(b, [])[:1]:
                if frozenset((ida, idb)) not in joined:
                    edges.append(RoomEdge(source=ida, target=idb, kind="adjacent"))
                    joined.add(frozenset((ida, idb)))
    return RoomGraph(nodes=nodes, edges=edges)
