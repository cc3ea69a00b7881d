"""Rooms no mend brings to their width dissolved, their floor shared by the rooms beside them
(mansion.building.dissolve)."""

from __future__ import annotations

import numpy as np
import pytest
from test_merge import graph_of, layout_of

import mansion.building.steps as steps
from mansion.building import generate_building
from mansion.building.dissolve import dissolve_unfit_rooms
from mansion.building.merge import grid_adjacencies, mask_defects, merge_unfit_rooms
from mansion.building.steps import NARROW_WHY, narrow_rooms
from mansion.eval.realism import bench_case

CELL = 0.5

# Half-metre cells, the top line the floor's far side: a hotel's corridor (C, the hub) along the
# bottom and up the east side; guest room N a strip 2.5 m wide and 12 m long on the west (its
# width 3.3 m), with guest rooms A and B, 5 m × 6 m each, stacked between it and the corridor.
HOTEL = "\n".join(
    ["NNNNN" + "A" * 10 + "CCCC"] * 12
    + ["NNNNN" + "B" * 10 + "CCCC"] * 12
    + ["C" * 19] * 4
)
NAMES = {
    "C": ("corridor", "main", "corridor", 4.0),
    "N": ("guest_room_3", "Entities", "guest_room", 16.0),
    "A": ("guest_room_1", "Entities", "guest_room", 16.0),
    "B": ("guest_room_2", "Entities", "guest_room", 16.0),
}
EDGES = [("corridor", "guest_room_3"), ("corridor", "guest_room_1"), ("corridor", "guest_room_2")]


def narrow(layout, graph):  # noqa: ANN001, ANN201
    return dict.fromkeys(narrow_rooms(layout.rooms, "hotel"), NARROW_WHY)


def test_a_strip_of_a_guest_room_is_shared_by_the_two_rooms_beside_it() -> None:
    layout, graph = layout_of(HOTEL, NAMES), graph_of(NAMES, EDGES)
    assert narrow(layout, graph) == {"guest_room_3": NARROW_WHY}
    # neither room beside it can take it whole: either would become an L with a 2.5 m arm
    assert merge_unfit_rooms(layout, graph, narrow, "hotel", cure="narrow")[2] == []
    shared, fewer, notes = dissolve_unfit_rooms(layout, graph, narrow(layout, graph), "hotel")
    assert notes == [
        f"guest_room_3 dropped, its floor shared by guest_room_1, guest_room_2 (guest_room_3 {NARROW_WHY})"
    ]
    assert "guest_room_3" not in {n.id for n in fewer.nodes} | {r.id for r in shared.rooms} | set(shared.grid.ids)
    # each takes the half beside it: two rooms 7.5 m × 6 m, at their width, with no defect
    for rid in ("guest_room_1", "guest_room_2"):
        room = shared.room(rid)
        assert room.area == 45.0 and room.target_area == 45.0
        assert next(n for n in fewer.nodes if n.id == rid).area == 20.0 + 15.0
        cells = shared.grid.array() == shared.grid.ids.index(rid)
        assert not mask_defects(cells, "guest_room", "hotel", CELL)
    assert narrow_rooms(shared.rooms, "hotel") == set()
    # no cell lost; the walls are drawn again; every room keeps its door to the corridor, and
    # the dropped room's relation goes (its takers already have theirs)
    assert (shared.grid.array() >= 0).sum() == (layout.grid.array() >= 0).sum()
    assert shared.adjacencies == grid_adjacencies(shared.grid.array(), shared.grid.ids, CELL)
    assert {frozenset((e.source, e.target)) for e in fewer.edges} == {
        frozenset(("corridor", "guest_room_1")), frozenset(("corridor", "guest_room_2")),
    }
    for rid in ("guest_room_1", "guest_room_2"):
        assert shared.adjacency("corridor", rid).longest >= 0.9  # type: ignore[union-attr]


def test_the_dropped_rooms_doors_pass_to_every_room_that_takes_their_wall() -> None:
    # a store L along the strip's west side opens into it: its door passes to both rooms that
    # take the strip's floor, each now with a 6 m wall with it
    picture = "\n".join(
        ["LLLLNNNNN" + "A" * 10 + "CCCC"] * 12 + ["LLLLNNNNN" + "B" * 10 + "CCCC"] * 12 + ["C" * 23] * 4
    )
    names = {**NAMES, "L": ("storage", "Entities", "storage", 2.0)}
    edges = [*EDGES, ("corridor", "storage"), ("guest_room_3", "storage")]
    layout, graph = layout_of(picture, names), graph_of(names, edges)
    shared, fewer, notes = dissolve_unfit_rooms(layout, graph, narrow(layout, graph), "hotel")
    assert len(notes) == 1
    pairs = {frozenset((e.source, e.target)) for e in fewer.edges}
    assert {frozenset(("guest_room_1", "storage")), frozenset(("guest_room_2", "storage"))} <= pairs
    assert shared.adjacency("guest_room_1", "storage").longest == 6.0  # type: ignore[union-attr]


def test_a_room_others_are_reached_through_stays() -> None:
    # guest_room_2 is reached only through the strip, so it was cut from it: the strip stays
    edges = [("corridor", "guest_room_3"), ("corridor", "guest_room_1"), ("guest_room_3", "guest_room_2")]
    layout, graph = layout_of(HOTEL, NAMES), graph_of(NAMES, edges)
    assert dissolve_unfit_rooms(layout, graph, narrow(layout, graph), "hotel") == (layout, graph, [])


def test_a_room_the_program_cannot_spare_takes_the_floor_of_one_beside_it_that_it_can() -> None:
    # the office floor's only board room, 3 m wide (its width 3.6 m), between the corridor's
    # end and the first of two meeting rooms: the meeting room is left out for it
    picture = "\n".join(["RRRRRR" + "MMMMMM" + "NNNNNNNN"] * 12 + ["C" * 20] * 4)
    names = {
        "C": ("corridor", "main", "corridor", 4.0),
        "R": ("board_room", "Entities", "board_room", 20.0),
        "M": ("meeting_room_1", "Entities", "meeting_room", 10.0),
        "N": ("meeting_room_2", "Entities", "meeting_room", 10.0),
    }
    edges = [("corridor", "board_room"), ("corridor", "meeting_room_1"), ("corridor", "meeting_room_2")]
    layout, graph = layout_of(picture, names), graph_of(names, edges)
    unfit = dict.fromkeys(narrow_rooms(layout.rooms, "office"), NARROW_WHY)
    assert unfit == {"board_room": NARROW_WHY}
    shared, fewer, notes = dissolve_unfit_rooms(layout, graph, unfit, "office")
    assert len(notes) == 1 and notes[0].startswith("meeting_room_1 dropped, its floor shared by board_room")
    assert notes[0].endswith(f"(board_room {NARROW_WHY})")
    assert narrow_rooms(shared.rooms, "office") == set()
    assert "meeting_room_1" not in {n.id for n in fewer.nodes}
    assert shared.room("board_room").area >= 20.0


def test_a_room_that_took_a_dissolved_rooms_floor_and_came_out_at_its_width_stays() -> None:
    # two guest rooms too narrow side by side (2.5 m and 2 m of their 3.3 m): the smaller goes
    # first, into the other, which then is 4.5 m wide and is not dissolved in its turn
    picture = "\n".join(["AAAAABBBBCCCCCCCCCC"] * 12 + ["D" * 19] * 4)
    names = {
        "D": ("corridor", "main", "corridor", 4.0),
        "A": ("guest_room_1", "Entities", "guest_room", 14.0),
        "B": ("guest_room_2", "Entities", "guest_room", 10.0),
        "C": ("guest_room_3", "Entities", "guest_room", 16.0),
    }
    edges = [("corridor", names[k][0]) for k in "ABC"]
    layout, graph = layout_of(picture, names), graph_of(names, edges)
    unfit = narrow(layout, graph)
    assert set(unfit) == {"guest_room_1", "guest_room_2"}
    shared, fewer, notes = dissolve_unfit_rooms(layout, graph, unfit, "hotel")
    assert notes == [f"guest_room_2 dropped, its floor shared by guest_room_1 (guest_room_2 {NARROW_WHY})"]
    assert shared.room("guest_room_1").area == 27.0
    assert narrow_rooms(shared.rooms, "hotel") == set()


@pytest.mark.parametrize("why", ["asked", "last of its type", "circulation only"])
def test_a_room_the_program_cannot_spare_or_no_room_may_take_stays(why: str) -> None:
    names, keep = dict(NAMES), ()
    if why == "asked":
        keep = ("guest_room_3",)
    elif why == "last of its type":
        names["N"] = ("laundry", "Entities", "laundry", 6.0)
    else:
        # its only neighbours are corridors: a corridor is planned, never what is left over
        names["A"] = ("wing_1", "Entities", "corridor", 4.0)
        names["B"] = ("wing_2", "Entities", "corridor", 4.0)
    edges = [(a, b) for a, b in ((names["C"][0], names[k][0]) for k in "NAB")]
    layout, graph = layout_of(HOTEL, names), graph_of(names, edges)
    unfit = {names["N"][0]: NARROW_WHY}
    assert dissolve_unfit_rooms(layout, graph, unfit, "hotel", keep=keep) == (layout, graph, [])


def test_generated_floors_record_each_room_dissolved_and_keep_the_rest() -> None:
    # an office whose floor 1 keeps a meeting room 2.5 m wide no mend widens (its floors not
    # laid out again whole, which could lay them out without it); the steps after the dissolve
    # off on both sides (without the dissolve, the spare room would be made a store)
    kind, floors, text = bench_case(61)
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(steps, "LAST_PAIRS", False)
        mp.setattr(steps, "SPARE_STORES", False)
        mp.setattr(steps, "LAST_FAMILIES", False)
        on = generate_building(text, building_type=kind, floors=floors, seed=61, relayouts=0)
        mp.setattr(steps, "DISSOLVE", False)
        off = generate_building(text, building_type=kind, floors=floors, seed=61, relayouts=0)
    found = 0
    for a, b in zip(on.floors, off.floors):
        notes = [x for x in a.relaxations if "its floor shared by" in x]
        assert [x for x in a.relaxations if x not in notes] == b.relaxations
        for note in notes:
            room = note.split(" dropped")[0]
            takers = note.split("shared by ")[1].split(" (")[0].split(", ")
            found += 1
            assert room in narrow_rooms(b.layout.rooms, on.program.building_type)
            assert room not in {n.id for n in a.graph.nodes} | set(a.layout.grid.ids)
            # what it held went to its takers, cell for cell
            before, after = b.layout.grid.array(), a.layout.grid.array()
            held = before == b.layout.grid.ids.index(room)
            assert {a.layout.grid.ids[k] for k in np.unique(after[held])} <= set(takers)
    assert found >= 1


def test_a_floor_left_with_rooms_below_their_width_is_laid_out_again() -> None:
    # school 21: without a relayout floor 2 keeps its science lab below its width after every
    # mend (hotel 96's guest floor, the case before, is now laid out as banks:
    # mansion.building.banks); laid out again whole under a seed of its own (the default), it
    # comes out with none
    kind, floors, text = bench_case(21)
    once = generate_building(text, building_type=kind, floors=floors, seed=21, relayouts=0)
    again = generate_building(text, building_type=kind, floors=floors, seed=21, relayouts=1)
    bad = [narrow_rooms(f.layout.rooms, kind) for f in once.floors]
    assert bad[2] == {"science_lab"} and not any(bad[:2])
    assert all(not narrow_rooms(f.layout.rooms, kind) for f in again.floors)
    # the ground floor had nothing to mend: the same floor, cell for cell
    assert again.floors[0].model_dump_json() == once.floors[0].model_dump_json()
    # the default lays it out again once, and the same inputs give the same building
    assert generate_building(text, building_type=kind, floors=floors, seed=21).model_dump_json() == again.model_dump_json()


def test_a_floor_that_carries_walls_is_laid_out_again_and_the_floors_above_follow_it() -> None:
    from mansion.building.load_bearing import carry_walls
    from mansion.building.steps import floor_footprint

    # apartment block 116: its ground floor keeps a flat's living bay below its width; the block's
    # walls carry the floors above, and the floor is laid out again before they are solved (the
    # last families, which would drop a children's room to mend it, off without the relayout)
    kind, floors, text = bench_case(116)
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(steps, "LAST_FAMILIES", False)
        once = generate_building(text, building_type=kind, floors=floors, seed=116, relayouts=0)
    again = generate_building(text, building_type=kind, floors=floors, seed=116, relayouts=1)
    assert again.program.load_bearing_walls
    assert narrow_rooms(once.floors[0].layout.rooms, kind)
    assert all(not narrow_rooms(f.layout.rooms, kind) for f in again.floors)
    assert again.floors[0].carried_walls != once.floors[0].carried_walls
    # every floor above follows the walls of the floor kept below it
    for index in range(1, len(again.floors)):
        above, below = again.floors[index], again.floors[index - 1]
        if above.copy_of is None:
            walls = carry_walls(below.carried_walls, floor_footprint(again.program, index))
            assert walls and above.footprint.fixed_walls == walls


def test_a_relayout_draws_a_sixth_of_the_candidates_and_of_the_fallback_without_backtracks() -> None:
    from mansion.building import steps

    solver = steps.solver_options()
    quick, relayout = steps._quick(solver), steps._relayout_options(solver)
    assert quick["batch"] == relayout["batch"] == solver["batch"] // steps.RESOLVE_DIVISOR
    # the second layouts keep the solver's fallback and backtracks (the default's buildings)
    assert quick["settings"] == solver["settings"]
    assert relayout["settings"].fallback_samples == solver["settings"].fallback_samples // steps.RESOLVE_DIVISOR
    assert relayout["settings"].max_backtracks == steps.RELAYOUT_BACKTRACKS == 0
    assert relayout["settings"].model_copy(update={
        "fallback_samples": solver["settings"].fallback_samples, "max_backtracks": solver["settings"].max_backtracks,
    }) == solver["settings"]
    # no width rules, no settings: only the batch
    bare = steps.solver_options(min_width=None)
    assert steps._relayout_options(bare) == {**bare, "batch": quick["batch"]}


@pytest.mark.parametrize("bad", [-1, 6, True, 1.0, "1"])
def test_relayouts_out_of_range_is_a_typed_error(bad: object) -> None:
    from mansion.exceptions import InvalidInputError

    with pytest.raises(InvalidInputError, match="relayouts"):
        generate_building("a small office", relayouts=bad)  # type: ignore[arg-type]


def test_cli_realism_generates_with_relayouts(tmp_path) -> None:  # noqa: ANN001
    import json

    from typer.testing import CliRunner

    from mansion.cli import app

    out = tmp_path / "r.json"
    r = CliRunner().invoke(app, ["eval", "realism", "--generate", "1", "--seed", "96", "--relayouts", "1", "--json", str(out)])
    assert r.exit_code == 0, r.output
    assert json.loads(out.read_text())["overall"]["below_width"] == 0
    r = CliRunner().invoke(app, ["eval", "realism", "--generate", "1", "--relayouts", "9"])
    assert r.exit_code != 0


def test_an_optional_room_the_last_of_its_type_may_be_spared_last() -> None:
    """Kindergarten 78 of the realism hundred lays its ground floor's staff office out at 7.5 m²
    of its 9 m² beside a sick room at 7.5 m², both the floor's only ones of their type, so
    neither could be dissolved. Both are rooms the template plans only where they fit
    (``optional``); ``steps.SPARE_OPTIONAL`` lets the last steps spare them: the sick room's floor
    goes to the staff office, which comes to its minimum, recorded."""
    from mansion.building.steps import unfit_rooms

    kind, floors, text = bench_case(78)
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(steps, "SPARE_OPTIONAL", False)
        mp.setattr(steps, "LEAVE_OPTIONAL", False)  # else the floor is laid out again without them
        before = generate_building(text, building_type=kind, floors=floors, seed=78).floors[0]
    assert unfit_rooms(before.layout.rooms, before.graph) == {
        "staff_office": "laid out at 7.5 m², below its 9 m² minimum",
    }
    with pytest.MonkeyPatch.context() as mp:
        # else the floor, its sleep room still below its width, is laid out again without its
        # staff office (steps.MAKE_ROOM_OPTIONAL)
        mp.setattr(steps, "MAKE_ROOM_OPTIONAL", False)
        built = generate_building(text, building_type=kind, floors=floors, seed=78)
    after = built.floors[0]
    assert unfit_rooms(after.layout.rooms, after.graph) == {}
    # the template's optional rooms, never one the description asked for
    optional = steps._optional_rooms(built.program, 0, before.graph, set())
    assert {"staff_office", "sick_room"} <= optional and "group_room_1" not in optional
    assert "staff_office" not in steps._optional_rooms(built.program, 0, before.graph, {"staff_office"})
    gone = [n for n in after.relaxations if n not in before.relaxations]
    assert gone == [
        "sick_room dropped, its floor shared by staff_office "
        "(staff_office laid out at 7.5 m², below its 9 m² minimum)"
    ]
    assert {r.id for r in before.layout.rooms} - {r.id for r in after.layout.rooms} == {"sick_room"}
    office = after.layout.room("staff_office")
    assert office.area == pytest.approx(15.0)
