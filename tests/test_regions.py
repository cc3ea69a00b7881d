"""First-round regions too narrow for their rooms give their arms to the hub
(mansion.building.regions)."""

from __future__ import annotations

import pytest
from test_merge import CELL, graph_of, layout_of

from mansion.building.checks import check_graph
from mansion.building.merge import grid_adjacencies
from mansion.building.regions import hub_takes_arms, narrow_regions

# Half-metre cells, the top line the floor's far side. C corridor (the hub); a flat cut from it:
# B its living room, K its kitchen, R a bedroom, A a second bedroom 1.5 m wide for 5 m between
# the corridor and the facade (the region's arm).
FLAT = "\n".join(["CCCAAA.........."] * 10 + ["CCCBBBBBBBBKKKKK"] * 6 + ["CCCBBBBBBBBRRRRR"] * 6)
NAMES = {
    "C": ("corridor", "main", "corridor", 4.0),
    "B": ("bay_1", "area", "unit_living", 13.0),
    "K": ("kitchen_1", "area", "kitchen", 5.5),
    "R": ("bedroom_1", "area", "bedroom", 7.5),
    "A": ("bedroom_2", "area", "bedroom", 7.5),
}
EDGES = [("corridor", "bay_1"), ("bay_1", "kitchen_1"), ("bay_1", "bedroom_1"), ("bay_1", "bedroom_2")]


def test_a_room_in_the_arm_of_a_narrow_region_is_left_out_and_the_hub_takes_the_arm() -> None:
    layout, graph = layout_of(FLAT, NAMES), graph_of(NAMES, EDGES)
    # the flat's living room needs 3 m: the 1.5 m arm is 30 of the region's 186 cells
    assert narrow_regions(layout, graph, "apartment_block") == ["bay_1"]
    taken, fewer, notes = hub_takes_arms(layout, graph, "apartment_block")
    assert notes == [
        "bedroom_2 left out: its floor, an arm of its region narrower than the region's rooms need, "
        "given to corridor (the floors above repeat the region)"
    ]
    assert narrow_regions(taken, fewer, "apartment_block") == []
    assert taken.room("corridor").area == pytest.approx(16.5 + 7.5)
    assert taken.grid.ids == ["corridor", "bay_1", "kitchen_1", "bedroom_1"]
    assert taken.adjacencies == grid_adjacencies(taken.grid.array(), taken.grid.ids, CELL)
    # the rest of the flat as it was, its relations kept; the bedroom and its door gone
    for rid in ("bay_1", "kitchen_1", "bedroom_1"):
        assert taken.room(rid).polygon == layout.room(rid).polygon
    assert "bedroom_2" not in {n.id for n in fewer.nodes} | {x for e in fewer.edges for x in (e.source, e.target)}
    assert {frozenset((e.source, e.target)) for e in fewer.edges} == {frozenset(e) for e in EDGES[:3]}
    check_graph(fewer, "floor 0")


def test_an_arm_of_the_room_a_region_is_cut_into_goes_to_the_hub_and_the_room_keeps_the_rest() -> None:
    picture = FLAT.replace("A", "B")
    names = {k: v for k, v in NAMES.items() if k != "A"}
    layout, graph = layout_of(picture, names), graph_of(names, EDGES[:3])
    taken, same, notes = hub_takes_arms(layout, graph, "apartment_block")
    assert notes == [] and same == graph
    assert taken.room("bay_1").area == pytest.approx(24.0)
    assert taken.room("corridor").area == pytest.approx(24.0)
    assert narrow_regions(taken, same, "apartment_block") == []


def test_no_arm_moves_where_its_room_cannot_be_spared_or_the_hub_is_no_circulation() -> None:
    # the flat's only bedroom: a home keeps it
    picture = FLAT.replace("R", "K")
    names = {k: v for k, v in NAMES.items() if k != "R"}
    layout, graph = layout_of(picture, names), graph_of(names, [e for e in EDGES if "bedroom_1" not in e])
    assert hub_takes_arms(layout, graph, "apartment_block") == (layout, graph, [])
    # a room the description asked for
    layout, graph = layout_of(FLAT, NAMES), graph_of(NAMES, EDGES)
    assert hub_takes_arms(layout, graph, "apartment_block", keep=frozenset({"bedroom_2"})) == (layout, graph, [])
    # a hub a home lives in (a villa's living room) takes no arm
    names = {**NAMES, "C": ("corridor", "main", "living_room", 12.0)}
    layout, graph = layout_of(FLAT, names), graph_of(names, EDGES)
    assert hub_takes_arms(layout, graph, "apartment_block") == (layout, graph, [])
