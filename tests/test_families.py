"""Families laid out again as a row along a side (mansion.building.families)."""

from __future__ import annotations

from test_merge import graph_of, layout_of

from mansion.building.checks import check_graph
from mansion.building.families import relay_families
from mansion.building.merge import grid_adjacencies, mask_defects
from mansion.building.steps import narrow_rooms

CELL = 0.5

# Half-metre cells, the top line is the floor's far side. An office bay 6 m × 12 m off the
# corridor C: its open office B curls round a meeting room M and a private office R, 2.5 m wide
# where it runs past them.
BAY = """
BBBBBBBBBBBBCCCC
BBBBBBBBBBBBCCCC
BBBBBBBBBBBBCCCC
BBBBBBBBBBBBCCCC
BBBBBBBBBBBBCCCC
BBBBBBBBBBBBCCCC
BBBBBBBBBBBBCCCC
BBBBBBBBBBBBCCCC
RRRRRRRBBBBBCCCC
RRRRRRRBBBBBCCCC
RRRRRRRBBBBBCCCC
RRRRRRRBBBBBCCCC
RRRRRRRBBBBBCCCC
RRRRRRRBBBBBCCCC
RRRRRRRBBBBBCCCC
RRRRRRRBBBBBCCCC
MMMMMMMBBBBBCCCC
MMMMMMMBBBBBCCCC
MMMMMMMBBBBBCCCC
MMMMMMMBBBBBCCCC
MMMMMMMBBBBBCCCC
MMMMMMMBBBBBCCCC
MMMMMMMBBBBBCCCC
MMMMMMMBBBBBCCCC
"""
NAMES = {
    "C": ("corridor", "main", "corridor", 4.0),
    "B": ("bay_1", "Entities", "open_office", 30.0),
    "R": ("private_office_1", "Entities", "private_office", 10.0),
    "Q": ("private_office_2", "Entities", "private_office", 8.0),
    "M": ("meeting_room_1", "Entities", "meeting_room", 10.0),
}
EDGES = [("corridor", "bay_1"), ("bay_1", "private_office_1"), ("bay_1", "meeting_room_1")]


def _defects(layout, rid: str) -> set[str]:  # type: ignore[no-untyped-def]
    room = layout.room(rid)
    return mask_defects(layout.grid.array() == layout.grid.ids.index(rid), room.room_type, "office", CELL)


def test_an_open_office_curled_round_its_cellular_rooms_gets_them_in_a_row_along_one_end() -> None:
    names = {k: v for k, v in NAMES.items() if k != "Q"}
    layout, graph = layout_of(BAY, names), graph_of(names, EDGES)
    assert narrow_rooms(layout.rooms, "office") == {"bay_1"}
    relaid, same, notes = relay_families(layout, graph, "office")
    assert same == graph
    assert len(notes) == 1 and notes[0].startswith("bay_1 laid out again with meeting_room_1, private_office_1")
    assert narrow_rooms(relaid.rooms, "office") == set()
    for rid in ("bay_1", "meeting_room_1", "private_office_1"):
        assert _defects(relaid, rid) == set()
        assert relaid.room(rid).area >= graph.node(rid).min_area  # type: ignore[operator]
    # every relation keeps a door's wall; the corridor and the bay's outline are as they were
    for a, b in EDGES:
        assert relaid.adjacency(a, b).longest >= 1.0  # type: ignore[union-attr]
    before, after = layout.grid.array(), relaid.grid.array()
    corridor = layout.grid.ids.index("corridor")
    assert ((before == corridor) == (after == corridor)).all()
    assert relaid.adjacencies == grid_adjacencies(after, relaid.grid.ids, CELL)
    check_graph(same, "floor 1")
    # nothing left to mend
    again, _, none = relay_families(relaid, graph, "office")
    assert none == [] and again == relaid


# The same bay with a second private office Q: three cellular rooms in a row 6 m long are each
# too narrow, and along the 12 m side they leave the open office too narrow.
TIGHT = BAY.replace("RRRRRRRBBBBB", "RRRRRRQQQQBB").replace("MMMMMMMBBBBB", "MMMMMMMMMMBB")


def test_a_bay_too_tight_for_its_rooms_is_laid_out_again_without_the_smallest_it_can_drop() -> None:
    edges = [*EDGES, ("bay_1", "private_office_2")]
    layout, graph = layout_of(TIGHT, NAMES), graph_of(NAMES, edges)
    assert "bay_1" in narrow_rooms(layout.rooms, "office")
    kept, same, none = relay_families(layout, graph, "office")
    assert none == [] and kept == layout and same == graph
    relaid, fewer, notes = relay_families(layout, graph, "office", drop=True)
    assert notes == [
        "private_office_2 dropped, its floor given to bay_1; bay_1 laid out again with meeting_room_1, "
        "private_office_1 in a row along it (a room of it laid out narrower than its clear width)"
    ]
    assert "private_office_2" not in {n.id for n in fewer.nodes} | set(relaid.grid.ids)
    assert narrow_rooms(relaid.rooms, "office") == set()
    check_graph(fewer, "floor 1")
    # a room the description asked for is never the one dropped
    kept, same, none = relay_families(layout, graph, "office", keep=["private_office_2"], drop=True)
    assert all("private_office_2 dropped" not in n for n in none)
