"""Arms of a room below its clear width made halls off it (mansion.building.halls)."""

from __future__ import annotations

from test_merge import graph_of, layout_of

from mansion.building.checks import check_graph
from mansion.building.halls import hall_arms, hall_type
from mansion.building.merge import grid_adjacencies, mask_defects
from mansion.building.steps import NARROW_WHY, narrow_rooms

CELL = 0.5

# Half-metre cells, the top line is the floor's far side. P a kindergarten's play hall (the
# floor's hub): a body 8 m × 6 m and an arm 2 m wide running up between G, a group room, and S,
# its sleep room, which it reaches only along the arm; O an office beside the body.
FLOOR = """
GGGGGGGGGGGGPPPPSSSSSSSS
GGGGGGGGGGGGPPPPSSSSSSSS
GGGGGGGGGGGGPPPPSSSSSSSS
GGGGGGGGGGGGPPPPSSSSSSSS
GGGGGGGGGGGGPPPPSSSSSSSS
GGGGGGGGGGGGPPPPSSSSSSSS
GGGGGGGGGGGGPPPPSSSSSSSS
GGGGGGGGGGGGPPPPSSSSSSSS
GGGGGGGGGGGGPPPPSSSSSSSS
GGGGGGGGGGGGPPPPSSSSSSSS
PPPPPPPPPPPPPPPPOOOOOOOO
PPPPPPPPPPPPPPPPOOOOOOOO
PPPPPPPPPPPPPPPPOOOOOOOO
PPPPPPPPPPPPPPPPOOOOOOOO
PPPPPPPPPPPPPPPPOOOOOOOO
PPPPPPPPPPPPPPPPOOOOOOOO
PPPPPPPPPPPPPPPPOOOOOOOO
PPPPPPPPPPPPPPPPOOOOOOOO
PPPPPPPPPPPPPPPPOOOOOOOO
PPPPPPPPPPPPPPPPOOOOOOOO
PPPPPPPPPPPPPPPPOOOOOOOO
PPPPPPPPPPPPPPPPOOOOOOOO
"""
NAMES = {
    "P": ("play_hall", "main", "play_hall", 30.0),
    "G": ("group_room_1", "Entities", "group_room", 20.0),
    "S": ("sleep_room", "Entities", "sleep_room", 15.0),
    "O": ("staff_office", "Entities", "office", 10.0),
}
EDGES = [("play_hall", "group_room_1"), ("play_hall", "sleep_room"), ("play_hall", "staff_office")]


def test_a_play_halls_arm_to_its_sleep_room_becomes_a_corridor_with_the_sleep_rooms_door() -> None:
    layout, graph = layout_of(FLOOR, NAMES), graph_of(NAMES, EDGES)
    # the arm (2 m × 5 m) is a sixth of the hall, narrower than a play hall's 4.5 m
    assert narrow_rooms(layout.rooms, "kindergarten") == {"play_hall"}
    split, more, notes = hall_arms(layout, graph, "kindergarten", NARROW_WHY)
    assert notes == [f"play_hall_hall_1 made a hall of play_hall's arm (play_hall {NARROW_WHY})"]
    assert narrow_rooms(split.rooms, "kindergarten") == set()
    hall = split.room("play_hall_hall_1")
    assert hall.room_type == hall_type("kindergarten") == "corridor" and hall.area == 10.0
    assert split.room("play_hall").area == 48.0
    assert not mask_defects(split.grid.array() == split.grid.ids.index(hall.id), "corridor", "kindergarten", CELL)
    # the sleep room's door passed to the hall, which opens onto the play hall; the group room
    # and the office keep their doors onto the play hall's body
    pairs = {frozenset((e.source, e.target)) for e in more.edges}
    assert pairs == {
        frozenset(p) for p in [
            ("play_hall", "group_room_1"), ("play_hall", "staff_office"),
            ("play_hall_hall_1", "sleep_room"), ("play_hall", "play_hall_hall_1"),
        ]
    }
    for a, b in pairs:
        assert split.adjacency(a, b).longest >= 1.0  # type: ignore[union-attr]
    node = next(n for n in more.nodes if n.id == "play_hall_hall_1")
    assert node.open_relation == "open" and node.type == "Entities"
    check_graph(more, "floor 0")
    # the floor keeps every cell; only the arm changed hands
    assert (split.grid.array() >= 0).sum() == (layout.grid.array() >= 0).sum()
    assert split.adjacencies == grid_adjacencies(split.grid.array(), split.grid.ids, CELL)
    # a room no longer below its width is left as it is
    again, same, none = hall_arms(split, more, "kindergarten", NARROW_WHY)
    assert none == [] and again == split and same == more


def test_homes_get_a_hallway_and_a_corridor_is_held_to_the_buildings_width() -> None:
    assert hall_type("family_apartment") == "hallway" and hall_type("apartment_block") == "hallway"
    assert hall_type("office") == hall_type(None) == "corridor"
    # in a hospital the arm (2 m) is below the 2.4 m its corridors need: no hall is made of it
    names = {**NAMES, "P": ("day_room", "main", "play_hall", 30.0)}
    edges = [("day_room", "group_room_1"), ("day_room", "sleep_room"), ("day_room", "staff_office")]
    layout, graph = layout_of(FLOOR, names), graph_of(names, edges)
    assert "day_room" in narrow_rooms(layout.rooms, "hospital")
    same_layout, same_graph, notes = hall_arms(layout, graph, "hospital", NARROW_WHY)
    assert notes == [] and same_layout == layout and same_graph == graph


def test_an_arm_that_serves_nothing_is_no_corridor() -> None:
    # the sleep room reached from the office instead: the arm carries no door and is too large
    # for a store (10 m² is a store; a longer arm is not)
    tall = "\n".join(["GGGGGGGGGGGGPPPPSSSSSSSS"] * 14 + FLOOR.strip().splitlines()[10:])
    edges = [("play_hall", "group_room_1"), ("staff_office", "sleep_room"), ("play_hall", "staff_office")]
    layout, graph = layout_of(tall, NAMES), graph_of(NAMES, edges)
    assert "play_hall" in narrow_rooms(layout.rooms, "kindergarten")
    same_layout, same_graph, notes = hall_arms(layout, graph, "kindergarten", NARROW_WHY)
    assert notes == [] and same_layout == layout and same_graph == graph


def test_an_adjacency_the_arm_holds_is_not_passed_and_the_hub_of_a_floor_that_carries_walls_stays() -> None:
    from mansion.models.graph import RoomGraph

    layout = layout_of(FLOOR, NAMES)
    # the sleep room must share a wall with the play hall (no door; it is reached through the
    # office): a hall cannot keep that
    plain = graph_of(NAMES, EDGES)
    edges = [
        {"source": "play_hall", "target": "group_room_1"}, {"source": "play_hall", "target": "staff_office"},
        {"source": "staff_office", "target": "sleep_room"},
        {"source": "play_hall", "target": "sleep_room", "kind": "adjacent"},
    ]
    graph = RoomGraph.model_validate({"nodes": [n.model_dump() for n in plain.nodes], "edges": edges})
    same_layout, _, notes = hall_arms(layout, graph, "kindergarten", NARROW_WHY)
    assert notes == [] and same_layout == layout
    # a floor whose walls the floor above follows never splits its hub
    same_layout, same_graph, notes = hall_arms(layout, plain, "kindergarten", NARROW_WHY, same_region=True)
    assert notes == [] and same_layout == layout and same_graph == plain


# A hotel floor: G a guest room 4 m × 5 m off the corridor C with an arm 1.5 m wide to its
# ensuite E, which it reaches only along the arm; S a store.
GUEST = """
GGGGGGGGGGGEEEE
GGGGGGGGGGGEEEE
GGGGGGGGGGGEEEE
GGGGGGGGGGGEEEE
GGGGGGGGGGGSSSS
GGGGGGGGSSSSSSS
GGGGGGGGSSSSSSS
GGGGGGGGSSSSSSS
GGGGGGGGSSSSSSS
GGGGGGGGSSSSSSS
CCCCCCCCCCCCCCC
CCCCCCCCCCCCCCC
CCCCCCCCCCCCCCC
CCCCCCCCCCCCCCC
"""
GUEST_NAMES = {
    "C": ("corridor", "main", "corridor", 4.0),
    "G": ("guest_room_1", "Entities", "guest_room", 16.0),
    "E": ("guest_room_1_ensuite", "Entities", "ensuite", 3.0),
    "S": ("store_1", "Entities", "storage", 2.0),
}
GUEST_EDGES = [("corridor", "guest_room_1"), ("guest_room_1", "guest_room_1_ensuite"), ("corridor", "store_1")]


def test_a_guest_rooms_arm_to_its_ensuite_becomes_its_entry_not_a_corridor() -> None:
    from mansion.building.halls import ENTRY_TYPE

    layout, graph = layout_of(GUEST, GUEST_NAMES), graph_of(GUEST_NAMES, GUEST_EDGES)
    assert "guest_room_1" in narrow_rooms(layout.rooms, "hotel")
    split, more, notes = hall_arms(layout, graph, "hotel", NARROW_WHY)
    assert notes == [f"guest_room_1_entry_1 made an entry of guest_room_1's arm (guest_room_1 {NARROW_WHY})"]
    entry = split.room("guest_room_1_entry_1")
    assert entry.room_type == ENTRY_TYPE and entry.area == 3.75
    assert narrow_rooms(split.rooms, "hotel") == set()
    # the ensuite's door moved to the entry, which opens onto the room; the entry is held to its
    # own table width (1.2 m), not the building's corridors' (a ward's arm 2 m wide would not be
    # a hospital corridor of 2.4 m)
    pairs = {frozenset((e.source, e.target)) for e in more.edges}
    assert frozenset(("guest_room_1_entry_1", "guest_room_1_ensuite")) in pairs
    assert frozenset(("guest_room_1", "guest_room_1_entry_1")) in pairs
    assert frozenset(("guest_room_1", "guest_room_1_ensuite")) not in pairs
    assert not mask_defects(split.grid.array() == split.grid.ids.index(entry.id), ENTRY_TYPE, "hotel", CELL)
    check_graph(more, "floor 1")
