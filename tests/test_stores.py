"""Pockets of a room below its clear width made stores off it (mansion.building.stores)."""

from __future__ import annotations

from test_merge import graph_of, layout_of

from mansion.building.checks import check_graph
from mansion.building.merge import grid_adjacencies, mask_defects
from mansion.building.steps import NARROW_WHY, narrow_rooms
from mansion.building.stores import MAX_STORE, STORE_TYPE, store_pockets

CELL = 0.5

# Half-metre cells, the top line is the floor's far side. S a shop (4 m stem, a bar 2 m deep
# across the floor's far side), X a stair and Y a lift beside its stem, C the concourse.
SHOP = """
SSSSSSSSSSSSSSSS
SSSSSSSSSSSSSSSS
SSSSSSSSSSSSSSSS
SSSSSSSSSSSSSSSS
XXXXSSSSSSSSYYYY
XXXXSSSSSSSSYYYY
XXXXSSSSSSSSYYYY
XXXXSSSSSSSSYYYY
CCCCCCCCCCCCCCCC
CCCCCCCCCCCCCCCC
CCCCCCCCCCCCCCCC
CCCCCCCCCCCCCCCC
CCCCCCCCCCCCCCCC
CCCCCCCCCCCCCCCC
"""
NAMES = {
    "C": ("concourse", "main", "concourse", 4.0),
    "S": ("shop_1", "Entities", "shop", 12.0),
    "X": ("stair_1", "stair", "stair", 1.0),
    "Y": ("elevator_1", "elevator", "elevator", 1.0),
}
EDGES = [("concourse", "shop_1"), ("concourse", "stair_1"), ("concourse", "elevator_1")]


def test_a_shops_pockets_beside_the_cores_become_its_stores() -> None:
    layout, graph = layout_of(SHOP, NAMES), graph_of(NAMES, EDGES)
    # the bar's ends past the stair and the lift (2 m × 2 m each) are a third of the shop
    assert narrow_rooms(layout.rooms, "shopping_mall") == {"shop_1"}
    stored, more, notes = store_pockets(layout, graph, "shopping_mall", NARROW_WHY)
    assert notes == [
        f"shop_1_store_{n} made a store of shop_1's pocket (shop_1 {NARROW_WHY})" for n in (1, 2)
    ]
    assert narrow_rooms(stored.rooms, "shopping_mall") == set()
    shop = stored.room("shop_1")
    assert shop.area == 16.0 and shop.room_type == "shop"
    for n in (1, 2):
        store = stored.room(f"shop_1_store_{n}")
        assert store.room_type == STORE_TYPE and store.area == 4.0
        # a door's width of wall to the shop, and nothing wrong with it as a store
        assert stored.adjacency("shop_1", store.id).longest == 2.0  # type: ignore[union-attr]
        assert not mask_defects(stored.grid.array() == stored.grid.ids.index(store.id), STORE_TYPE, "shopping_mall", CELL)
        assert any(e.source == "shop_1" and e.target == store.id for e in more.edges)
    # the floor keeps every cell; only the shop's pockets changed hands
    assert (stored.grid.array() >= 0).sum() == (layout.grid.array() >= 0).sum()
    assert stored.adjacencies == grid_adjacencies(stored.grid.array(), stored.grid.ids, CELL)
    assert {n.id for n in more.nodes} == {n.id for n in graph.nodes} | {"shop_1_store_1", "shop_1_store_2"}
    assert next(n for n in more.nodes if n.id == "shop_1").area == 16.0
    check_graph(more, "floor 0")
    # a room no longer below its width is left as it is
    again, same, none = store_pockets(stored, more, "shopping_mall", NARROW_WHY)
    assert none == [] and again == stored and same == more


def test_a_pocket_that_is_no_sound_store_stays() -> None:
    # the bar 1 m deep: its ends (2 m × 1 m) would be stores with no usable square
    shallow = "\n".join(SHOP.strip().splitlines()[2:])
    layout, graph = layout_of(shallow, NAMES), graph_of(NAMES, EDGES)
    assert narrow_rooms(layout.rooms, "shopping_mall") == {"shop_1"}
    same_layout, same_graph, notes = store_pockets(layout, graph, "shopping_mall", NARROW_WHY)
    assert notes == [] and same_layout == layout and same_graph == graph


# An office's small meeting room M (2.5 m × 3 m, 7.5 m² of a meeting room's 10 m²) between a
# stair X, a store T and the corridor C; the floor's other meeting room N is sound.
OFFICE = """
XXXXXXMMMMMTTTNNNNNNNNNN
XXXXXXMMMMMTTTNNNNNNNNNN
XXXXXXMMMMMTTTNNNNNNNNNN
XXXXXXMMMMMTTTNNNNNNNNNN
XXXXXXMMMMMTTTNNNNNNNNNN
XXXXXXMMMMMTTTNNNNNNNNNN
CCCCCCCCCCCCCCCCCCCCCCCC
CCCCCCCCCCCCCCCCCCCCCCCC
CCCCCCCCCCCCCCCCCCCCCCCC
"""
OFFICE_NAMES = {
    "C": ("corridor", "main", "corridor", 4.0),
    "M": ("meeting_room_1", "Entities", "meeting_room", 10.0),
    "N": ("meeting_room_2", "Entities", "meeting_room", 10.0),
    "T": ("storage_1", "Entities", "storage", 2.0),
    "X": ("stair_1", "stair", "stair", 1.0),
}
OFFICE_EDGES = [
    ("corridor", "meeting_room_1"), ("corridor", "meeting_room_2"), ("corridor", "storage_1"),
    ("corridor", "stair_1"),
]


def test_a_spare_room_too_small_for_its_type_that_no_neighbour_takes_becomes_a_store() -> None:
    from mansion.building.merge import may_receive
    from mansion.building.steps import unfit_rooms
    from mansion.building.stores import store_spare_rooms

    layout, graph = layout_of(OFFICE, OFFICE_NAMES), graph_of(OFFICE_NAMES, OFFICE_EDGES)
    unfit = unfit_rooms(layout.rooms, graph)
    assert unfit == {"meeting_room_1": "laid out at 7.5 m², below its 10 m² minimum"}
    nodes = {n.id: n for n in graph.nodes}
    # no room beside it may take its floor: a core, the corridor and a smaller kind of room
    assert not any(may_receive(nodes["meeting_room_1"], nodes[o]) for o in ("corridor", "storage_1"))
    stored, more, notes = store_spare_rooms(layout, graph, unfit, "office")
    assert notes == [
        "meeting_room_1 dropped, its floor made a store, storage_2 "
        "(meeting_room_1 laid out at 7.5 m², below its 10 m² minimum)"
    ]
    store = stored.room("storage_2")
    assert store.room_type == STORE_TYPE and store.area == 7.5
    # the same cells, walls and relations under the store's id; the rest of the floor as it was
    assert (stored.grid.array() == layout.grid.array()).all()
    assert stored.grid.ids == ["corridor", "storage_2", "meeting_room_2", "storage_1", "stair_1"]
    assert stored.adjacencies == grid_adjacencies(stored.grid.array(), stored.grid.ids, CELL)
    assert [r for r in stored.rooms if r.id != "storage_2"] == [r for r in layout.rooms if r.id != "meeting_room_1"]
    assert any({e.source, e.target} == {"corridor", "storage_2"} for e in more.edges)
    assert "meeting_room_1" not in {n.id for n in more.nodes} | {x for e in more.edges for x in (e.source, e.target)}
    node = next(n for n in more.nodes if n.id == "storage_2")
    assert node.room_type == STORE_TYPE and node.area == 7.5 and node.min_area == 2.0
    assert unfit_rooms(stored.rooms, more) == {}
    check_graph(more, "floor 0")


def test_a_room_the_program_cannot_spare_nor_a_home_lives_in_is_never_made_a_store() -> None:
    from mansion.building.load_bearing import cut_parents
    from mansion.building.merge import may_spare
    from mansion.building.steps import unfit_rooms
    from mansion.building.stores import store_spare_rooms

    layout, graph = layout_of(OFFICE, OFFICE_NAMES), graph_of(OFFICE_NAMES, OFFICE_EDGES)
    unfit = unfit_rooms(layout.rooms, graph)
    # a room the description asked for
    assert store_spare_rooms(layout, graph, unfit, "office", keep={"meeting_room_1"}) == (layout, graph, [])
    # the floor's only meeting room (its other one an office)
    names = {**OFFICE_NAMES, "N": ("office_1", "Entities", "office", 9.0)}
    edges = [(a, "office_1" if b == "meeting_room_2" else b) for a, b in OFFICE_EDGES]
    alone, alone_graph = layout_of(OFFICE, names), graph_of(names, edges)
    assert store_spare_rooms(alone, alone_graph, unfit, "office") == (alone, alone_graph, [])
    # unless the floor's template plans it only where it fits (an optional room)
    stored, _, notes = store_spare_rooms(alone, alone_graph, unfit, "office", optional={"meeting_room_1"})
    assert stored.room("storage_2").area == 7.5 and len(notes) == 1
    # a room a home lives in, though its flat keeps another bedroom
    home = {
        **OFFICE_NAMES,
        "C": ("landing", "main", "landing", 4.0),
        "M": ("master_bedroom", "Entities", "master_bedroom", 11.5),
        "N": ("bedroom", "Entities", "bedroom", 7.0),
    }
    home_edges = [("landing", b) for b in ("master_bedroom", "bedroom", "storage_1", "stair_1")]
    flat, flat_graph = layout_of(OFFICE, home), graph_of(home, home_edges)
    small = unfit_rooms(flat.rooms, flat_graph)
    assert small == {"master_bedroom": "laid out at 7.5 m², below its 11.5 m² minimum"}
    assert may_spare(next(n for n in flat_graph.nodes if n.id == "master_bedroom"), flat_graph, cut_parents(flat_graph), frozenset())
    assert store_spare_rooms(flat, flat_graph, small, "townhouse") == (flat, flat_graph, [])
    # a room too large to be a store (MAX_STORE: the other meeting room, 8 m by 3 m, were it
    # below a minimum of 30 m²) stays what it is
    longer = "\n".join(line + line[-1] * 6 for line in OFFICE.strip().splitlines())
    big = {**OFFICE_NAMES, "N": ("meeting_room_2", "Entities", "meeting_room", 30.0)}
    wide, wide_graph = layout_of(longer, big), graph_of(big, OFFICE_EDGES)
    assert wide.room("meeting_room_2").area == 24.0 > MAX_STORE
    too_big = {"meeting_room_2": "laid out at 24.0 m², below its 30 m² minimum"}
    assert store_spare_rooms(wide, wide_graph, too_big, "office") == (wide, wide_graph, [])
