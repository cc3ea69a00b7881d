"""Rooms below their clear width widened by pushing a side out (mansion.building.sides)."""

from __future__ import annotations

from test_merge import graph_of, layout_of

from mansion.building.merge import grid_adjacencies, mask_defects
from mansion.building.sides import enlarge_rooms, widen_sides
from mansion.building.steps import narrow_rooms

CELL = 0.5


def picture(west: int, hall: int, east: int, rows: int = 24) -> str:
    """Half-metre cells, the top line the floor's far side: W a room ``west`` cells deep, P a
    kindergarten's play hall (the hub) ``hall`` cells wide, and two group rooms ``east`` cells
    deep stacked beside it, G on top of H."""
    top = "W" * west + "P" * hall + "G" * east
    bottom = "W" * west + "P" * hall + "H" * east
    return "\n".join([top] * (rows // 2) + [bottom] * (rows // 2))


NAMES = {
    "P": ("play_hall", "main", "play_hall", 30.0),
    "W": ("sleep_room", "Entities", "sleep_room", 18.0),
    "G": ("group_room_1", "Entities", "group_room", 30.0),
    "H": ("group_room_2", "Entities", "group_room", 30.0),
}
EDGES = [("play_hall", "sleep_room"), ("play_hall", "group_room_1"), ("play_hall", "group_room_2")]


def cells_of(layout, rid: str):  # noqa: ANN001, ANN201
    return layout.grid.array() == layout.grid.ids.index(rid)


def test_a_play_hall_between_rooms_moves_its_wall_a_metre_into_the_group_rooms() -> None:
    # a play hall 3.5 m wide (its width 4.5 m) beside group rooms 6.5 m deep that can each give
    # a metre: the repair's one column at a time gains nothing (4 m is as narrow as 3.5 m)
    layout, graph = layout_of(picture(8, 7, 13), NAMES), graph_of(NAMES, EDGES)
    assert narrow_rooms(layout.rooms, "kindergarten") == {"play_hall"}
    wide = widen_sides(layout, graph, "kindergarten")
    assert narrow_rooms(wide.rooms, "kindergarten") == set()
    # the whole east side moved two cells: the hall 4.5 m × 12 m, each group room 5.5 m × 6 m
    assert wide.room("play_hall").area == 54.0
    assert wide.room("group_room_1").area == wide.room("group_room_2").area == 33.0
    assert wide.room("sleep_room").area == layout.room("sleep_room").area
    for rid in ("play_hall", "group_room_1", "group_room_2"):
        assert not mask_defects(cells_of(wide, rid), wide.room(rid).room_type, "kindergarten", CELL)
    # every relation keeps its wall; the floor keeps every cell
    for a, b in EDGES:
        assert wide.adjacency(a, b).longest >= 1.0  # type: ignore[union-attr]
    assert (wide.grid.array() >= 0).sum() == (layout.grid.array() >= 0).sum()
    assert wide.adjacencies == grid_adjacencies(wide.grid.array(), wide.grid.ids, CELL)
    # a room at its width is left as it is
    assert widen_sides(wide, graph, "kindergarten") == wide


def test_a_hall_between_two_rooms_that_can_give_half_a_metre_each_moves_both_walls() -> None:
    # group rooms 5 m deep on both sides (their minimum area 25 m² here): a metre from either
    # would leave it 4 m, below its 4.5 m, so each gives half a metre
    names = {
        **NAMES, "W": ("group_room_3", "Entities", "group_room", 25.0),
        "G": ("group_room_1", "Entities", "group_room", 25.0), "H": ("group_room_2", "Entities", "group_room", 25.0),
    }
    edges = [("play_hall", "group_room_3"), *EDGES[1:]]
    layout, graph = layout_of(picture(10, 7, 10, rows=26), names), graph_of(names, edges)
    wide = widen_sides(layout, graph, "kindergarten")
    assert narrow_rooms(wide.rooms, "kindergarten") == set()
    assert wide.room("play_hall").area == 58.5
    assert wide.room("group_room_3").area == 58.5
    assert wide.room("group_room_1").area == wide.room("group_room_2").area == 29.25


def test_a_push_that_would_leave_a_neighbour_narrow_or_small_is_refused() -> None:
    # group rooms 5 m deep beside a hall against the outline: a metre from them leaves them
    # 4 m wide; and on a floor whose walls carry the floor above, the hub never takes floor
    # from another first-round region
    layout = layout_of(picture(0, 7, 10).replace("W", ""), NAMES)
    graph = graph_of(NAMES, EDGES).model_copy()
    graph = graph.model_copy(update={
        "nodes": [n for n in graph.nodes if n.id != "sleep_room"],
        "edges": [e for e in graph.edges if "sleep_room" not in (e.source, e.target)],
    })
    assert widen_sides(layout, graph, "kindergarten") == layout
    wide_enough = layout_of(picture(8, 7, 13), NAMES)
    assert widen_sides(wide_enough, graph_of(NAMES, EDGES), "kindergarten", same_region=True) == wide_enough


# A private office O 2.5 m × 3 m (7.5 m², its minimum 8 m²) between a store S and a meeting room
# M, all off a corridor C 1.5 m wide (an office's corridor width: it can give nothing).
SMALL = "\n".join(["SSSOOOOOMMMMMMMM"] * 6 + ["CCCCCCCCCCCCCCCC"] * 3)
SMALL_NAMES = {
    "C": ("corridor", "main", "corridor", 4.0),
    "S": ("storage_1", "Entities", "storage", 2.0),
    "O": ("private_office_1", "Entities", "private_office", 8.0),
    "M": ("meeting_room_1", "Entities", "meeting_room", 10.0),
}
SMALL_EDGES = [("corridor", "storage_1"), ("corridor", "private_office_1"), ("corridor", "meeting_room_1")]


def test_a_room_below_its_minimum_area_takes_what_it_needs_from_the_room_beside_it() -> None:
    layout, graph = layout_of(SMALL, SMALL_NAMES), graph_of(SMALL_NAMES, SMALL_EDGES)
    assert layout.room("private_office_1").area == 7.5
    grown = enlarge_rooms(layout, graph, "office")
    # the wall moved half a metre into the meeting room: 3 m × 3 m and 3.5 m × 3 m
    assert grown.room("private_office_1").area == 9.0
    assert grown.room("meeting_room_1").area == 10.5
    assert grown.room("corridor").area == layout.room("corridor").area
    assert grown.room("storage_1").area == layout.room("storage_1").area
    for rid in ("private_office_1", "meeting_room_1", "corridor", "storage_1"):
        assert not mask_defects(cells_of(grown, rid), grown.room(rid).room_type, "office", CELL)
    for a, b in SMALL_EDGES:
        assert grown.adjacency(a, b).longest >= 1.0  # type: ignore[union-attr]
    assert grown.adjacencies == grid_adjacencies(grown.grid.array(), grown.grid.ids, CELL)
    # a room at its minimum is left as it is
    assert enlarge_rooms(grown, graph, "office") == grown
    # a neighbour that would fall below its own minimum gives nothing
    narrower = SMALL.replace("OOOOOMMMMMMMM", "OOOOOMMMMMMM.").replace("CCCCCCCCCCCCCCCC", "CCCCCCCCCCCCCCC.")
    tight = layout_of(narrower, SMALL_NAMES)
    assert tight.room("meeting_room_1").area == 10.5
    assert enlarge_rooms(tight, graph, "office") == tight


# A classroom K 10 m × 5 m (its width 5.4 m) over a school's corridor C 2.5 m deep, toilets T
# beside it reaching half a metre lower: pushed a row into the corridor, the classroom would leave
# the corridor's cell in the corner by the toilets outside every 1 m square (no agent passes it).
CORNER = "\n".join(["TTTTT" + "K" * 20] * 10 + ["TTTT" + "C" * 21] + ["C" * 25] * 4)
CORNER_NAMES = {
    "C": ("corridor", "main", "corridor", 4.0),
    "T": ("toilets", "Entities", "toilet", 2.5),
    "K": ("classroom_1", "Entities", "classroom", 40.0),
}


def test_a_push_gives_the_corridor_cell_it_would_strand_to_the_room_it_completes() -> None:
    layout = layout_of(CORNER, CORNER_NAMES)
    graph = graph_of(CORNER_NAMES, [("corridor", "toilets"), ("corridor", "classroom_1")])
    assert narrow_rooms(layout.rooms, "school") == {"classroom_1"}
    wide = widen_sides(layout, graph, "school")
    assert narrow_rooms(wide.rooms, "school") == set()
    # the classroom 10 m × 5.5 m, the corridor 2 m deep along it, the corner cell the toilets'
    assert wide.room("classroom_1").area == 55.0
    assert wide.room("toilets").area == layout.room("toilets").area + 0.25
    corridor = cells_of(wide, "corridor")
    assert corridor.sum() == 100 and corridor[:4].all()
    for rid in CORNER_NAMES.values():
        assert not mask_defects(cells_of(wide, rid[0]), rid[2], "school", CELL)


def test_pushes_that_leave_a_neighbour_below_its_area_do_not_count_among_those_judged(monkeypatch) -> None:  # type: ignore[no-untyped-def]
    # a play hall 3 m wide between a sleep room that can give half a metre (60 m², its minimum
    # 54 m²) and group rooms that can give a metre (33 m², their minimum 25 m², 4.5 m wide at
    # least): the pushes ranked first take 1.5 m from one side and leave it too small; judged
    # one at a time, the push that splits the 1.5 m between the two sides is still reached
    import mansion.building.sides as sides

    monkeypatch.setattr(sides, "MAX_JUDGED", 1)
    names = {
        **NAMES, "W": ("sleep_room", "Entities", "sleep_room", 54.0),
        "G": ("group_room_1", "Entities", "group_room", 25.0), "H": ("group_room_2", "Entities", "group_room", 25.0),
    }
    layout, graph = layout_of(picture(10, 6, 11), names), graph_of(names, EDGES)
    wide = widen_sides(layout, graph, "kindergarten")
    assert narrow_rooms(wide.rooms, "kindergarten") == set()
    assert wide.room("play_hall").area == 54.0 and wide.room("sleep_room").area == 54.0
    assert wide.room("group_room_1").area == wide.room("group_room_2").area == 27.0


def test_a_room_at_its_width_slides_over_into_the_room_beyond_it(monkeypatch) -> None:  # type: ignore[no-untyped-def]
    # a play hall 3.5 m wide beside a group room exactly at its 4.5 m, a sleep room 5 m deep
    # beyond: the group room cannot give a metre, but it can move a metre over into the sleep room
    names = {**NAMES, "W": ("sleep_room", "Entities", "sleep_room", 18.0)}
    layout = layout_of("\n".join(["PPPPPPPGGGGGGGGGWWWWWWWWWW"] * 24), names)
    graph = graph_of(names, [("play_hall", "group_room_1"), ("group_room_1", "sleep_room")])
    assert narrow_rooms(layout.rooms, "kindergarten") == {"play_hall"}
    wide = widen_sides(layout, graph, "kindergarten")
    assert narrow_rooms(wide.rooms, "kindergarten") == set()
    assert wide.room("play_hall").area == 54.0
    assert wide.room("group_room_1").area == layout.room("group_room_1").area
    assert wide.room("sleep_room").area == 48.0
    for a, b in (("play_hall", "group_room_1"), ("group_room_1", "sleep_room")):
        assert wide.adjacency(a, b).longest >= 1.0  # type: ignore[union-attr]
    # without the slide, no push passes: the group room would be left 3.5 m wide
    import mansion.building.sides as sides

    monkeypatch.setattr(sides, "SLIDES", False)
    assert widen_sides(layout, graph, "kindergarten") == layout
