"""Families laid out again as a row along a side (mansion.building.families)."""

from __future__ import annotations

from test_merge import graph_of, layout_of

from mansion.building.checks import check_graph
from mansion.building.families import relay_families, touching
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
