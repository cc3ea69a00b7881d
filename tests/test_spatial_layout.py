"""Rooms laid out as rectangles from what a description says (mansion.planning.spatial_layout)."""

from __future__ import annotations

import numpy as np
import pytest

from mansion.planning.spatial_language import KnownRoom, read_description
from mansion.planning.spatial_layout import LayoutWeights, layout_rectangles, rectangle_seeds
from mansion.planning.spatial_seeds import FreeGrid, SeedRoom

ROOMS = [
    SeedRoom("living_room_0", "living_room", 300.0),
    SeedRoom("kitchen_1", "kitchen", 60.0),
    SeedRoom("bathroom_2", "bathroom", 40.0),
    SeedRoom("common_room_3", "common_room", 100.0),
]
KNOWN = [KnownRoom(r.id, r.room_type) for r in ROOMS]


def square(side: int = 30, grid: int = 40) -> FreeGrid:
    mask = np.zeros((grid, grid), dtype=bool)
    mask[5 : 5 + side, 5 : 5 + side] = True
    return FreeGrid(mask)


def boxes_of(text: str, free: FreeGrid, pairs=(), **weights):
    reading = read_description(text, KNOWN)
    return {b.id: b for b in layout_rectangles(reading, ROOMS, free, pairs, weights=LayoutWeights(**weights))}


def test_a_corner_puts_the_rooms_walls_on_the_plans_walls() -> None:
    free = square()  # cells 5..35 on both axes, y up
    b = boxes_of("The kitchen is in the northeast corner. The bathroom is in the southwest corner.", free)
    k, w = b["kitchen_1"], b["bathroom_2"]
    assert k.cx + k.hx == pytest.approx(35, abs=1.0) and k.cy + k.hy == pytest.approx(35, abs=1.0)
    assert w.cx - w.hx == pytest.approx(5, abs=1.0) and w.cy - w.hy == pytest.approx(5, abs=1.0)


def test_a_side_and_a_relation_order_two_rooms() -> None:
    free = square()
    text = "The common room is on the west side. The kitchen is to the north of the common room."
    b = boxes_of(text, free)
    c, k = b["common_room_3"], b["kitchen_1"]
    assert c.cx - c.hx == pytest.approx(5, abs=1.0)
    # north of it, the boxes apart on y and overlapping on x
    assert k.cy - k.hy >= c.cy + c.hy - 1.5
    assert abs(k.cx - c.cx) < k.hx + c.hx


def test_boxes_keep_their_area_and_do_not_overlap_much() -> None:
    free = square()
    text = (
        "The kitchen is in the northwest corner. The bathroom is in the northwest corner too. "
        "The common room is on the south side."
    )
    b = boxes_of(text, free)
    for r in ROOMS:
        area = r.area * (0.5 if r.id == "living_room_0" else 1.0)  # the hub's box is half its area
        assert 4 * b[r.id].hx * b[r.id].hy == pytest.approx(area, rel=1e-6)
    k, w = b["kitchen_1"], b["bathroom_2"]
    overlap = max(0.0, k.hx + w.hx - abs(k.cx - w.cx)) * max(0.0, k.hy + w.hy - abs(k.cy - w.cy))
    # both claim the same corner: they share it side by side rather than stack
    assert overlap < 0.15 * min(4 * k.hx * k.hy, 4 * w.hx * w.hy)


def test_stated_width_and_depth_shape_the_box() -> None:
    free = square()
    b = boxes_of("The common room is on the south side. It is 25 feet wide by 8 feet deep.", free)
    c = b["common_room_3"]
    assert c.hx > 1.5 * c.hy
    b = boxes_of("The common room is on the south side. It is 8 feet wide by 25 feet deep.", free)
    assert b["common_room_3"].hy > 1.5 * b["common_room_3"].hx


def test_a_corner_is_the_corner_of_the_free_region_not_of_its_bounding_box() -> None:
    # the west wall steps in by 7 cells on the plan's southern half
    mask = np.zeros((40, 40), dtype=bool)
    mask[5:20, 12:35] = True
    mask[20:35, 5:35] = True
    free = FreeGrid(mask)
    b = boxes_of("The bathroom is in the southwest corner.", free)["bathroom_2"]
    assert b.cx - b.hx == pytest.approx(12, abs=1.0) and b.cy - b.hy == pytest.approx(5, abs=1.0)
    inside = mask[int(b.cy - b.hy + 0.5) : int(b.cy + b.hy - 0.5), int(b.cx - b.hx + 0.5) : int(b.cx + b.hx - 0.5)]
    assert inside.mean() > 0.95


def test_adjacency_makes_boxes_touch() -> None:
    free = square()
    text = "The kitchen is in the northeast corner. The bathroom is in the southwest corner."
    apart = boxes_of(text, free)
    touch = boxes_of(text, free, pairs=[("kitchen_1", "bathroom_2")], adjacency=8.0)

    def gap(b) -> float:
        k, w = b["kitchen_1"], b["bathroom_2"]
        return max(abs(k.cx - w.cx) - k.hx - w.hx, abs(k.cy - w.cy) - k.hy - w.hy)

    assert gap(touch) < gap(apart) - 3


def test_seeds_are_free_cells_distinct_and_deterministic() -> None:
    mask = np.zeros((40, 40), dtype=bool)
    mask[5:35, 20:35] = True
    mask[20:35, 5:35] = True
    free = FreeGrid(mask, origin=(100.0, -50.0), cell=0.5)
    text = (
        "The kitchen is in the southwest corner with the bathroom to the east. The common room is in "
        "the centre. The living room is on the north side."
    )
    reading = read_description(text, KNOWN)
    seeds = rectangle_seeds(reading, ROOMS, free, [("living_room_0", "kitchen_1")])
    assert set(seeds) == {r.id for r in ROOMS}
    assert all(free.contains(p) for p in seeds.values())
    assert len(set(seeds.values())) == len(seeds)
    assert seeds == rectangle_seeds(reading, ROOMS, free, [("living_room_0", "kitchen_1")])


def test_a_room_nothing_is_said_about_still_gets_a_seed() -> None:
    free = square()
    seeds = rectangle_seeds(read_description("", KNOWN), ROOMS, free)
    assert all(free.contains(p) for p in seeds.values())
