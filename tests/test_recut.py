"""Rooms the layout left unfit are cut again inside the region they were cut from
(mansion.building.recut)."""

from __future__ import annotations

from shapely.geometry import Polygon

from mansion.building.merge import shape_defects
from mansion.building.recut import recut_unfit_rooms
from test_merge import graph_of, layout_of, unfit

# Half-metre cells, the top line the floor's far side. C corridor (the hub), G a guest room, E its
# ensuite: a strip 1 m wide and 2.5 m long (2.5 m², its minimum 3 m², no usable square).
SUITE = """
GGGGGGGGGGGGEE
GGGGGGGGGGGGEE
GGGGGGGGGGGGEE
GGGGGGGGGGGGEE
GGGGGGGGGGGGEE
GGGGGGGGGGGGGG
GGGGGGGGGGGGGG
GGGGGGGGGGGGGG
GGGGGGGGGGGGGG
GGGGGGGGGGGGGG
GGGGGGGGGGGGGG
CCCCCCCCCCCCCC
CCCCCCCCCCCCCC
CCCCCCCCCCCCCC
"""
NAMES = {
    "C": ("corridor", "main", "corridor", 4.0),
    "G": ("guest_room_1", "area", "guest_room", 16.0),
    "E": ("guest_room_1_ensuite", "area", "ensuite", 3.0),
}
EDGES = [("corridor", "guest_room_1"), ("guest_room_1", "guest_room_1_ensuite")]


def test_an_ensuite_too_small_is_cut_again_in_its_guest_room() -> None:
    layout, graph = layout_of(SUITE, NAMES), graph_of(NAMES, EDGES)
    assert set(unfit(layout, graph)) == {"guest_room_1_ensuite"}
    fixed, notes = recut_unfit_rooms(layout, graph, unfit, "hotel")
    assert len(notes) == 1 and notes[0].startswith("guest_room_1_ensuite cut again from guest_room_1 at ")
    assert unfit(fixed, graph) == {}
    rooms = {r.id: r for r in fixed.rooms}
    ensuite = Polygon(rooms["guest_room_1_ensuite"].polygon)
    guest = Polygon(rooms["guest_room_1"].polygon, rooms["guest_room_1"].holes)
    # a rectangle of at least its minimum, as wide as the table asks (1.4 m: three cells)
    assert ensuite.area >= 3.0 and ensuite.area == ensuite.envelope.area
    assert min(ensuite.bounds[2] - ensuite.bounds[0], ensuite.bounds[3] - ensuite.bounds[1]) >= 1.5
    # the guest room keeps the rest, in one piece, with no defect it lacked, and both doors
    assert guest.geom_type == "Polygon" and guest.area + ensuite.area == 11 * 14 * 0.25
    assert not shape_defects(guest, "guest_room", "hotel")
    assert fixed.adjacency("corridor", "guest_room_1").longest >= 1.0  # type: ignore[union-attr]
    assert fixed.adjacency("guest_room_1", "guest_room_1_ensuite").longest >= 0.9  # type: ignore[union-attr]
    # the grid and the outlines agree
    labels = fixed.grid.array()
    for k, rid in enumerate(fixed.grid.ids):
        assert (labels == k).sum() * 0.25 == rooms[rid].area


def test_a_recut_that_would_leave_the_region_below_its_minimum_is_refused() -> None:
    # K, a kitchen of 4.5 m² (its minimum 5.5 m²) cut from L, a flat's living room of 13.5 m²
    # (its minimum 13 m²): a kitchen of its minimum would leave the living room at 12.5 m²; in a
    # deeper flat the kitchen is cut again and the living room keeps its minimum
    picture = """
LLLLLLLLLKKK
LLLLLLLLLKKK
LLLLLLLLLKKK
LLLLLLLLLKKK
LLLLLLLLLKKK
LLLLLLLLLKKK
CCCCCCCCCCCC
CCCCCCCCCCCC
CCCCCCCCCCCC
"""
    names = {
        "C": ("corridor", "main", "corridor", 4.0),
        "L": ("flat_1", "area", "unit_living", 13.0),
        "K": ("kitchen_1", "area", "kitchen", 5.5),
    }
    graph = graph_of(names, [("corridor", "flat_1"), ("flat_1", "kitchen_1")])
    layout = layout_of(picture, names)
    assert set(unfit(layout, graph)) == {"kitchen_1"}
    fixed, notes = recut_unfit_rooms(layout, graph, unfit, "apartment_block")
    assert notes == [] and fixed == layout
    deep = picture.replace("LLLLLLLLLKKK\n", "LLLLLLLLLLLL\nLLLLLLLLLLLL\nLLLLLLLLLKKK\n", 1)
    fixed, notes = recut_unfit_rooms(layout_of(deep, names), graph, unfit, "apartment_block")
    assert len(notes) == 1 and unfit(fixed, graph) == {}
    flat = next(r for r in fixed.rooms if r.id == "flat_1")
    assert flat.area >= 13.0 and not shape_defects(Polygon(flat.polygon, flat.holes), "unit_living", None)


def test_generated_floors_cut_rooms_again_before_merging_or_dropping_them() -> None:
    """Seed 60 of the realism hundred (an apartment block on load-bearing walls) lays a flat's
    bathroom out at 2.2 m² and two bedrooms below their minimum: each is cut again inside its
    flat, the floors record it, and the building passes its checks."""
    from mansion.building import generate_building
    from mansion.building.steps import unfit_rooms
    from mansion.eval.realism import bench_case

    kind, floors, description = bench_case(60)
    b = generate_building(description, building_type=kind, floors=floors, seed=60)
    notes = [(f, n) for f in b.floors if f.copy_of is None for n in f.relaxations if " cut again from " in n]
    assert {n.split(" cut again")[0] for _, n in notes} >= {"bathroom_2", "bedroom_3"}
    for f, note in notes:
        room = note.split(" cut again")[0]
        assert room in {n.id for n in f.graph.nodes}
        assert room not in unfit_rooms(f.layout.rooms, f.graph)
