"""Families laid out again as a row along a side (mansion.building.families), or cut again by the
solver on their own cells (mansion.building.family_solve)."""

from __future__ import annotations

import pytest
from test_merge import graph_of, layout_of

from mansion.building.checks import check_graph
from mansion.building.families import relay_families, touching
from mansion.building.merge import grid_adjacencies, mask_defects
from mansion.building.steps import narrow_rooms
from mansion.models.room_design import needed_width

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


def _defects(layout, rid: str, kind: str = "office") -> set[str]:  # type: ignore[no-untyped-def]
    room = layout.room(rid)
    return mask_defects(layout.grid.array() == layout.grid.ids.index(rid), room.room_type, kind, CELL)


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
# too narrow, and along the 12 m side they leave the open office too narrow; at the bay's two
# ends they fit.
TIGHT = BAY.replace("RRRRRRRBBBBB", "RRRRRRQQQQBB").replace("MMMMMMMBBBBB", "MMMMMMMMMMBB")


def _rows(layout, rid: str) -> set[int]:  # type: ignore[no-untyped-def]
    return set(map(int, (layout.grid.array() == layout.grid.ids.index(rid)).nonzero()[0]))


def _relay(  # type: ignore[no-untyped-def]
    picture: str, names: dict[str, tuple[str, str, str, float]], edges: list[tuple[str, str]], kind: str,
):
    """The layout and graph a picture draws, and what relay_families makes of them."""
    layout, graph = layout_of(picture, names), graph_of(names, edges)
    return layout, graph, *relay_families(layout, graph, kind)


def test_a_bay_whose_rooms_fit_only_at_its_two_ends_gets_them_in_two_rows() -> None:
    edges = [*EDGES, ("bay_1", "private_office_2")]
    layout, graph, relaid, same, notes = _relay(TIGHT, NAMES, edges, "office")
    assert narrow_rooms(layout.rooms, "office") >= {"bay_1"}
    assert same == graph
    assert notes == [
        "bay_1 laid out again with meeting_room_1, private_office_1, private_office_2 in two rows, along "
        "opposite sides of it (a room of it laid out narrower than its clear width)"
    ]
    assert narrow_rooms(relaid.rooms, "office") == set()
    for rid in NAMES.values():
        assert _defects(relaid, rid[0]) == set()
    # the open office runs across the bay between the meeting room at one end and the two
    # private offices side by side at the other
    bay, meeting = _rows(relaid, "bay_1"), _rows(relaid, "meeting_room_1")
    offices = _rows(relaid, "private_office_1")
    assert offices == _rows(relaid, "private_office_2")
    ends = sorted([meeting, offices], key=min)
    assert max(ends[0]) < min(bay) and max(bay) < min(ends[1])
    for a, b in edges:
        assert relaid.adjacency(a, b).longest >= 1.0  # type: ignore[union-attr]
    assert relaid.adjacencies == grid_adjacencies(relaid.grid.array(), relaid.grid.ids, CELL)
    check_graph(same, "floor 1")


# A bay 5 m × 12 m with the meeting room and two private offices: at its minimums the open office
# does not fit between them (5 m × 5 m left of its 30 m²), and neither private office fits beside
# the meeting room across 5 m.
TIGHTER = "\n".join(["BBBBBBBBBBCCCC"] * 8 + ["RRRRRQQQQBCCCC"] * 8 + ["MMMMMMMMBBCCCC"] * 8) + "\n"


def test_a_bay_too_tight_for_its_rooms_is_laid_out_again_without_the_smallest_it_can_drop() -> None:
    edges = [*EDGES, ("bay_1", "private_office_2")]
    layout, graph = layout_of(TIGHTER, NAMES), graph_of(NAMES, edges)
    assert "bay_1" in narrow_rooms(layout.rooms, "office")
    kept, same, none = relay_families(layout, graph, "office")
    assert none == [] and kept == layout and same == graph
    relaid, fewer, notes = relay_families(layout, graph, "office", drop=True)
    assert notes == [
        "private_office_2 dropped, its floor given to bay_1; bay_1 laid out again with meeting_room_1, "
        "private_office_1 in two rows, along opposite sides of it (a room of it laid out narrower than its "
        "clear width)"
    ]
    assert "private_office_2" not in {n.id for n in fewer.nodes} | set(relaid.grid.ids)
    assert narrow_rooms(relaid.rooms, "office") == set()
    assert relaid.room("bay_1").area >= 30.0
    check_graph(fewer, "floor 1")
    # a room the description asked for is never the one dropped
    kept, same, none = relay_families(layout, graph, "office", keep=["private_office_2"], drop=True)
    assert all("private_office_2 dropped" not in n for n in none)



# A hotel's dining zone (D the dining hall, its head; R the restaurant; K the commercial kitchen)
# off the lobby L, the hub: the zone is an L round the lobby's corner, and its kitchen runs 3 m
# wide down the foot of the L where it needs 3.6 m. No band of rooms along a side holds the
# three; the solver, cutting the zone's cells again, puts the dining hall in the foot by the lobby
# and the kitchen 4 m wide above it.
DINING = "\n".join(
    ["KKKKKKKKKDDDDDDDDDDDDLLL"] * 3 + ["KKKKKKRRRRRRRRRRRRRRRLLL"] * 11 + ["KKKKKKLLLLLLLLLLLLLLLLLL"] * 3
) + "\n"
DINING_NAMES = {
    "L": ("lobby", "main", "lobby", 15.0),
    "D": ("dining", "Entities", "corridor", 4.0),
    "R": ("restaurant", "Entities", "restaurant", 40.0),
    "K": ("commercial_kitchen", "Entities", "commercial_kitchen", 18.0),
}
DINING_EDGES = [("lobby", "dining"), ("dining", "restaurant"), ("dining", "commercial_kitchen")]
#: The areas the floor planned (the zone holds less than they ask: the floor was tight).
DINING_PLANNED = {"lobby": 24.0, "dining": 8.8, "restaurant": 55.9, "commercial_kitchen": 23.4}


def _dining():  # type: ignore[no-untyped-def]
    """The dining zone's layout and graph, the rooms' planned areas and widths as a generated
    floor's planner sets them (``clear_width`` from the design table)."""
    layout, graph = layout_of(DINING, DINING_NAMES), graph_of(DINING_NAMES, DINING_EDGES)
    layout = layout.model_copy(update={
        "rooms": [r.model_copy(update={"target_area": DINING_PLANNED[r.id]}) for r in layout.rooms],
    })
    graph = graph.model_copy(update={"nodes": [
        n.model_copy(update={
            "area": DINING_PLANNED[n.id], "clear_width": needed_width(n.room_type, "hotel"), "min_width": 1.5,
            "max_aspect": None if n.type == "main" or n.room_type == "corridor" else 3.0,
        })
        for n in graph.nodes
    ]})
    return layout, graph


def test_a_family_no_rows_mend_is_cut_again_by_the_solver_on_its_own_cells() -> None:
    from mansion.building import families
    from mansion.building.steps import solver_options

    layout, graph = _dining()
    assert narrow_rooms(layout.rooms, "hotel") == {"commercial_kitchen"}
    # rows of rectangles find nothing, and without the floor's solver options nothing more is tried
    kept, same, none = relay_families(layout, graph, "hotel")
    assert none == [] and kept == layout and same == graph
    relaid, same, notes = relay_families(layout, graph, "hotel", solver=solver_options())
    assert same == graph
    assert notes == [
        "dining cut again with commercial_kitchen, restaurant on their own floor (a room of it laid out "
        "narrower than its clear width)"
    ]
    assert narrow_rooms(relaid.rooms, "hotel") == set()
    for rid, _, _, least in DINING_NAMES.values():
        assert _defects(relaid, rid, "hotel") == set()
        assert relaid.room(rid).area >= least
        assert (relaid.grid.array() == relaid.grid.ids.index(rid)).any()
    # every relation keeps a door's wall, the dining hall's to the lobby too; the lobby keeps its
    # cells, so no wall of the zone's border moves
    for a, b in DINING_EDGES:
        assert relaid.adjacency(a, b).longest >= 1.0  # type: ignore[union-attr]
    lobby = layout.grid.ids.index("lobby")
    assert ((layout.grid.array() == lobby) == (relaid.grid.array() == lobby)).all()
    assert relaid.adjacencies == grid_adjacencies(relaid.grid.array(), relaid.grid.ids, CELL)
    # the kitchen is a rectangle 4 m wide
    kitchen = relaid.grid.array() == relaid.grid.ids.index("commercial_kitchen")
    rows, cols = kitchen.any(axis=1).sum(), kitchen.any(axis=0).sum()
    assert kitchen.sum() == rows * cols and min(rows, cols) * CELL >= 3.6
    # the same every time (the solver's seeds are fixed), and nothing left to mend after it
    assert relay_families(layout, graph, "hotel", solver=solver_options())[0] == relaid
    again, _, none = relay_families(relaid, graph, "hotel", solver=solver_options())
    assert none == [] and again == relaid
    # the switch off, nothing
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(families, "SOLVED_FAMILIES", False)
        assert relay_families(layout, graph, "hotel", solver=solver_options())[2] == []

def _hall() -> str:
    """A reading hall H 8 m × 12 m, the hub, with two study rooms S and T in its middle (the hall
    2.5 m wide on one side of them, 3 m on the other), toilets W and an office O at its two top
    corners, the stacks X along its foot."""
    rows = []
    for r in range(24):
        middle = list("H" * 16)
        if 6 <= r < 13:
            middle[5:10] = "SSSSS"
        elif 13 <= r < 20:
            middle[5:10] = "TTTTT"
        rows.append(("WWWWWW" if r < 6 else "......") + "".join(middle) + ("OOOOOO" if r < 6 else "......"))
    rows += ["......" + "X" * 16 + "......"] * 10
    return "\n".join(rows) + "\n"


HALL_NAMES = {
    "H": ("reading_hall", "main", "reading_hall", 40.0),
    "S": ("study_room_1", "Entities", "study_room", 7.5),
    "T": ("study_room_2", "Entities", "study_room", 7.5),
    "W": ("toilets", "Entities", "toilet", 2.5),
    "O": ("office", "Entities", "office", 8.0),
    "X": ("stacks", "Entities", "stacks", 30.0),
}


def test_a_hall_moves_the_rooms_it_closes_round_to_a_side_keeping_its_walls() -> None:
    edges = [("reading_hall", rid) for c, (rid, *_) in HALL_NAMES.items() if c != "H"]
    layout, graph, relaid, same, notes = _relay(_hall(), HALL_NAMES, edges, "library")
    assert narrow_rooms(layout.rooms, "library") == {"reading_hall"}
    assert same == graph
    assert notes == [
        "reading_hall laid out again with study_room_1, study_room_2 in a row along it (a room of it laid out "
        "narrower than its clear width)"
    ]
    assert narrow_rooms(relaid.rooms, "library") == set()
    for rid in ("reading_hall", "study_room_1", "study_room_2"):
        assert _defects(relaid, rid, "library") == set()
    # the hall keeps a wall with every room it serves; only the hall's and the study rooms'
    # cells changed hands
    for a, b in edges:
        assert relaid.adjacency(a, b).longest >= 1.0  # type: ignore[union-attr]
    before, after = layout.grid.array(), relaid.grid.array()
    ids = layout.grid.ids
    moved = before != after
    assert set(before[moved].tolist()) <= {ids.index(r) for r in ("reading_hall", "study_room_1", "study_room_2")}
    # no longer closed round: each study room lies on the hall's edge (on the outline or against
    # another room)
    for rid in ("study_room_1", "study_room_2"):
        assert touching(relaid, rid) - {"reading_hall", "study_room_1", "study_room_2"}
