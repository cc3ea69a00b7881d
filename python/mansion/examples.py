"""Two ready-made floors to try the solver on: a small apartment and an office floor with cores.

Node types follow the paper's topology prompt: ``main`` is the circulation hub, ``area`` a zone
that is cut further into rooms in a later round, ``Entities`` a single room, ``stair`` /
``elevator`` the fixed cores. Target areas sum to the free area of the footprint.
"""

from __future__ import annotations

from mansion.models import Core, Footprint, RoomEdge, RoomGraph, RoomNode

__all__ = ["EXAMPLES", "example_apartment", "example_office"]

_OAK = "oak parquet, matte"
_TILE = "porcelain tile, light grey"
_CARPET = "carpet tiles, charcoal"
_WHITE = "painted plaster, white"
_CONCRETE = "polished concrete"


def _node(
    id: str,
    type: str,
    area: float,
    room_type: str,
    floor: str,
    wall: str = _WHITE,
    open_relation: str = "door",
) -> RoomNode:
    return RoomNode.model_validate(
        {
            "id": id,
            "type": type,
            "area": area,
            "room_type": room_type,
            "floor_material": floor,
            "wall_material": wall,
            "open_relation": open_relation,
        }
    )


def _edge(source: str, target: str, kind: str = "access") -> RoomEdge:
    return RoomEdge.model_validate({"source": source, "target": target, "kind": kind})


def example_apartment() -> tuple[RoomGraph, Footprint]:
    """A two-bedroom apartment of 96 m² on a 12 × 8 m rectangle, the living room as its hub.

    The kitchen is open to the living room; the entrance hall leads to a storage cupboard.
    """
    nodes = [
        _node("living", "main", 32.0, "living_room", _OAK, open_relation="open"),
        _node("hall", "area", 8.0, "entrance_hall", _TILE),
        _node("kitchen", "Entities", 13.0, "kitchen", _TILE, open_relation="open"),
        _node("bedroom_1", "Entities", 17.0, "bedroom", _OAK),
        _node("bedroom_2", "Entities", 14.0, "bedroom", _OAK),
        _node("bathroom", "Entities", 7.0, "bathroom", _TILE, "ceramic tile, white"),
        _node("storage", "Entities", 5.0, "storage", _TILE),
    ]
    edges = [
        _edge("living", "hall"),
        _edge("living", "kitchen"),
        _edge("living", "bedroom_1"),
        _edge("living", "bedroom_2"),
        _edge("living", "bathroom"),
        _edge("hall", "storage"),
    ]
    return RoomGraph(nodes=nodes, edges=edges), Footprint.rectangle(12.0, 8.0)


def example_office() -> tuple[RoomGraph, Footprint]:
    """An office floor of 500 m² (25 × 20 m) with 19 rooms around a corridor hub.

    A stair core fills the south-west corner and an elevator core the north-east corner; the
    corridor reaches both. Two open-office zones, the reception and a toilet lobby are cut into
    smaller rooms in a second round.
    """
    footprint = Footprint.rectangle(
        25.0,
        20.0,
        cores=[
            Core(id="stair_1", type="stair", x=(0.0, 4.0), y=(0.0, 6.0)),
            Core(id="elevator_1", type="elevator", x=(22.0, 25.0), y=(16.0, 20.0)),
        ],
    )
    nodes = [
        _node("corridor", "main", 70.0, "corridor", _CONCRETE, open_relation="open"),
        _node("stair_1", "stair", 24.0, "stair", _CONCRETE),
        _node("elevator_1", "elevator", 12.0, "elevator", _CONCRETE),
        # Reception zone.
        _node("reception", "area", 30.0, "reception", _TILE),
        _node("meeting_room_1", "Entities", 16.0, "meeting_room", _CARPET),
        _node("storage", "Entities", 9.0, "storage", _CONCRETE),
        # Open office A with its enclosed rooms.
        _node("open_office_a", "area", 96.0, "open_office", _CARPET),
        _node("manager_office_1", "Entities", 12.0, "private_office", _CARPET),
        _node("manager_office_2", "Entities", 12.0, "private_office", _CARPET),
        _node("print_room", "Entities", 7.0, "print_room", _CONCRETE),
        _node("phone_booth", "Entities", 4.0, "phone_booth", _CARPET),
        # Open office B with its enclosed rooms.
        _node("open_office_b", "area", 90.0, "open_office", _CARPET),
        _node("meeting_room_2", "Entities", 14.0, "meeting_room", _CARPET),
        _node("quiet_room", "Entities", 8.0, "quiet_room", _CARPET),
        _node("server_room", "Entities", 10.0, "server_room", _CONCRETE),
        # Toilets off a small lobby.
        _node("toilet_lobby", "area", 6.0, "toilet_lobby", _TILE),
        _node("toilet_women", "Entities", 10.0, "toilet", _TILE, "ceramic tile, white"),
        _node("toilet_men", "Entities", 10.0, "toilet", _TILE, "ceramic tile, white"),
        _node("accessible_wc", "Entities", 6.0, "toilet", _TILE, "ceramic tile, white"),
        # Shared rooms on the corridor.
        _node("kitchen", "Entities", 22.0, "kitchen", _TILE, open_relation="open"),
        _node("board_room", "Entities", 32.0, "board_room", _OAK),
    ]
    edges = [
        _edge("corridor", "stair_1"),
        _edge("corridor", "elevator_1"),
        _edge("corridor", "reception"),
        _edge("corridor", "open_office_a"),
        _edge("corridor", "open_office_b"),
        _edge("corridor", "toilet_lobby"),
        _edge("corridor", "kitchen"),
        _edge("corridor", "board_room"),
        _edge("reception", "meeting_room_1"),
        _edge("reception", "storage"),
        _edge("open_office_a", "manager_office_1"),
        _edge("open_office_a", "manager_office_2"),
        _edge("open_office_a", "print_room"),
        _edge("open_office_a", "phone_booth"),
        _edge("open_office_b", "meeting_room_2"),
        _edge("open_office_b", "quiet_room"),
        _edge("open_office_b", "server_room"),
        _edge("toilet_lobby", "toilet_women"),
        _edge("toilet_lobby", "toilet_men"),
        _edge("toilet_lobby", "accessible_wc"),
        # The two toilets share a plumbing wall.
        _edge("toilet_women", "toilet_men", "adjacent"),
    ]
    return RoomGraph(nodes=nodes, edges=edges), footprint


#: The examples by name, as the CLI's ``--example`` offers them.
EXAMPLES = {"apartment": example_apartment, "office": example_office}
