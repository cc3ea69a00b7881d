"""Pockets of a room below its clear width made stores off it (mansion.building.stores)."""

from __future__ import annotations

from test_merge import graph_of, layout_of

from mansion.building.checks import check_graph
from mansion.building.merge import grid_adjacencies, mask_defects
from mansion.building.steps import NARROW_WHY, narrow_rooms
from mansion.building.stores import STORE_TYPE, store_pockets

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
