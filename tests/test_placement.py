"""Object placement (issue 6): the engine through the binding, checked independently.

The reachability oracle is `mansion.eval.placement.reachable`, a shapely + numpy flood fill over
the placed objects alone; it must agree with the engine, which claims an interaction cell for every
object it kept.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from llm_replay import Replay

from mansion.agents.llm import LLMClient
from mansion.eval.placement import PAPER, ROOMS, footprint, reachable, score_room
from mansion.exceptions import InvalidInputError
from mansion.models.objects import ObjectPlan, RoomPlacement
from mansion.placement import RoomSpec, furnish_room, furnish_rooms, plan_objects, room_kind, thor_objects
from mansion.placement.assets import database
from mansion.placement.llm import LLMObjectPlanner
from shapely.geometry import Point, Polygon


@pytest.fixture(scope="module", params=["bedroom", "classroom", "restaurant", "library"])
def placed(request) -> tuple[str, RoomPlacement]:
    name = request.param
    room = ROOMS[name]
    plan = plan_objects(name, name, room.polygon, "", seed=3)
    return name, furnish_room(room, plan, seed=3)


def test_paper_rooms_meet_the_issue(placed) -> None:
    name, result = placed
    score = score_room(result)
    assert (score.ob, score.cn, score.rch) == (0, 0, 100.0), score.unreachable
    floor, small = PAPER[name]
    # one run is noisier than the ten-run mean the issue asks for; it still clears the paper
    assert score.floor_obj >= floor and score.small_obj >= small, score
    assert result.stats.seconds < 1.0


def test_engine_interaction_cells_are_free_and_connected_for_the_oracle(placed) -> None:
    _, result = placed
    assert all(reachable(result))
    poly = Polygon(result.polygon)
    fps = [footprint(o) for o in result.objects]
    for o, fp in zip(result.objects, fps):
        p = Point(o.interaction)
        assert poly.contains(p)
        assert fp.distance(p) < 0.5
        # the agent's disc at the interaction cell touches no object
        assert min(f.distance(p) for f in fps) >= result.agent_radius - 1e-9


def test_oracle_sees_a_blocked_object() -> None:
    # an object walled in by a fake ring of boxes must be unreachable for the oracle too
    room = ROOMS["bedroom"]
    plan = ObjectPlan.model_validate({"room_id": "b", "room_type": "bedroom", "items": [
        {"id": "safe", "object_type": "Safe", "tag": "edge", "max_width": 0.5},
    ]})
    result = furnish_room(room, plan, seed=0)
    assert reachable(result) == [True]
    o = result.objects[0]
    cage = []
    for k, (dx, dy) in enumerate([(1, 0), (-1, 0), (0, 1), (0, -1)]):
        cx, cy = o.center[0] + dx * 0.8, o.center[1] + dy * 0.8
        cage.append(o.model_copy(update={"id": f"wall{k}", "center": (cx, cy), "size": (1.9, 0.3, 1.0),
                                         "yaw": 0.0 if dy else 90.0, "has_front": False}))
    caged = result.model_copy(update={"objects": [o, *cage]})
    assert reachable(caged)[0] is False


def test_thor_objects_follow_the_house_json_conventions(placed) -> None:
    _, result = placed
    objs = thor_objects(result)
    assert len(objs) == len(result.objects)
    db = database()
    known = {a.asset_id for assets in db.assets.values() for a in assets}
    for o, src in zip(objs, result.objects):
        assert o["assetId"] in known
        assert o["position"] == {"x": src.center[0], "y": src.size[2] / 2, "z": src.center[1]}
        assert o["rotation"]["y"] == src.yaw and isinstance(o["kinematic"], bool)
        for c, child in zip(o.get("children", []), src.children):
            assert math.isclose(c["position"]["y"], src.size[2] + child.size[2] / 2)
            # a child stands on its parent's top
            assert footprint(src).buffer(1e-6).contains(Point(child.center))
    assert json.loads(json.dumps(objs)) == objs


def test_same_seed_same_room_and_parallel_equals_serial() -> None:
    room = ROOMS["classroom"]
    plan = plan_objects("classroom", "classroom", room.polygon, seed=1)
    a = furnish_room(room, plan, seed=5)
    b = furnish_room(room, plan, seed=5)
    strip = lambda r: r.model_dump(exclude={"stats"})  # noqa: E731
    assert strip(a) == strip(b)
    both = furnish_rooms([(room, plan), (ROOMS["bedroom"], plan_objects("b", "bedroom", ROOMS["bedroom"].polygon))], seed=5)
    assert strip(both[0]) == strip(a)  # type: ignore[arg-type]


def test_bad_input_is_a_typed_error_naming_the_room() -> None:
    room = RoomSpec("den", [(0, 0), (4, 0), (4, 4), (0, 4)], [((1.0, 1.0), (2.0, 1.0))])
    plan = plan_objects("den", "bedroom", room.polygon)
    with pytest.raises(InvalidInputError, match="den"):
        furnish_room(room, plan)
    out = furnish_rooms([(room, plan)])
    assert isinstance(out[0], InvalidInputError)
    with pytest.raises(InvalidInputError, match="no asset"):
        furnish_room(ROOMS["bedroom"], ObjectPlan(room_id="b", room_type="b", items=[
            {"id": "x", "object_type": "Spaceship"}]))  # type: ignore[list-item]


@pytest.mark.parametrize("room_type,kind", [
    ("Classroom 2", "classroom"), ("reading_room", "library"), ("patient ward", "ward"),
    ("main corridor", "circulation"), ("gift shop", "shop"), ("storage", "generic"),
    # a toilet lobby is circulation (no WC fixture to shut its door off); its toilets are toilets
    ("toilet_lobby", "circulation"), ("accessible_toilet", "toilet"), ("wc", "toilet"),
    # an ensuite is a bathroom, not a suite (a master suite is a bedroom)
    ("ensuite", "toilet"), ("Ensuite", "toilet"), ("master_suite", "bedroom"),
])
def test_room_kinds(room_type: str, kind: str) -> None:
    assert room_kind(room_type) == kind


def test_every_room_kind_gives_a_valid_reachable_placement() -> None:
    room = RoomSpec("r", [(0, 0), (7, 0), (7, 5), (0, 5)], [((3.0, 0.0), (4.0, 0.0))])
    from mansion.placement.offline import ROOM_KINDS

    jobs = [(room, plan_objects("r", kind, room.polygon, "office", seed=2)) for kind in ROOM_KINDS]
    for res in furnish_rooms(jobs, seed=2):
        assert isinstance(res, RoomPlacement)
        s = score_room(res)
        assert (s.ob, s.cn, s.rch) == (0, 0, 100.0)


def test_llm_object_planner_replayed_through_the_sdk() -> None:
    replay = Replay()
    planner = LLMObjectPlanner(LLMClient(replay.client()))  # type: ignore[arg-type]
    room = ROOMS["bedroom"]
    plan = planner.plan("bedroom", "bedroom", room.polygon, "house")
    # the first answer used a type AI2-THOR does not have; the retry carried the problem
    assert replay.served == ["objects_bedroom.attempt1", "objects_bedroom"]
    assert "KingBed" in json.dumps(replay.requests[1]["messages"][-1])
    assert {i.object_type for i in plan.items} >= {"Bed", "SideTable", "Desk", "Chair"}
    result = furnish_room(room, plan, seed=0)
    s = score_room(result)
    assert (s.ob, s.cn, s.rch) == (0, 0, 100.0) and s.floor_obj >= 6


def test_reach_grid_matches_numpy_definition_on_an_empty_room() -> None:
    # with nothing placed, the oracle's free space is the room shrunk by the radius
    room = ROOMS["bedroom"]
    res = furnish_room(room, ObjectPlan(room_id="b", room_type="b", items=[]))
    assert res.objects == [] and reachable(res) == []
    assert np.isclose(res.agent_radius, 0.25)


def test_the_checks_flood_fill_matches_a_plain_breadth_first_search() -> None:
    """The run-sweeping flood of mansion.placement.check against a cell-by-cell BFS."""
    from collections import deque

    import numpy as np

    from mansion.placement.check import FreeSpace

    rng = np.random.default_rng(5)
    for _ in range(30):
        h, w = int(rng.integers(1, 40)), int(rng.integers(1, 40))
        free = rng.random((h, w)) < 0.6
        seeds = rng.random((h, w)) < 0.02
        space = FreeSpace(np.zeros(h * w), np.zeros(h * w), (h, w), free.ravel(), free.ravel())
        got = space.flood(seeds.ravel()).reshape(h, w)
        want = np.zeros((h, w), dtype=bool)
        queue = deque(zip(*np.nonzero(seeds & free)))
        for y, x in queue:
            want[y, x] = True
        while queue:
            y, x = queue.popleft()
            for yy, xx in ((y + 1, x), (y - 1, x), (y, x + 1), (y, x - 1)):
                if 0 <= yy < h and 0 <= xx < w and free[yy, xx] and not want[yy, xx]:
                    want[yy, xx] = True
                    queue.append((yy, xx))
        assert (got == want).all()


def test_the_checks_free_cells_match_shapely_distances() -> None:
    """FreeSpace.build measures distances with numpy (rectangles in one formula, other shapes
    edge by edge); every cell must agree with shapely's own point-to-shape distance."""
    import numpy as np
    import shapely
    from shapely.geometry import Polygon

    from mansion.placement.check import FreeSpace, footprint, solid_walls

    rng = np.random.default_rng(11)
    rooms = [
        # an L (shapely's containment), a rectangle (compared with its bounds; a gap reaching a
        # corner, one given end first) and a turned quadrilateral (a gap along a slanted edge)
        ([(0.0, 0.0), (4.0, 0.0), (4.0, 2.5), (2.5, 2.5), (2.5, 3.5), (0.0, 3.5)],
         [((1.0, 0.0), (1.9, 0.0)), ((2.5, 2.6), (2.5, 3.4))]),
        ([(0.0, 0.0), (4.0, 0.0), (4.0, 3.5), (0.0, 3.5)],
         [((3.1, 0.0), (4.0, 0.0)), ((0.0, 3.0), (0.0, 1.2))]),
        ([(0.0, 0.0), (4.0, 0.5), (3.5, 4.0), (-0.5, 3.5)], [((1.6, 0.2), (2.4, 0.3))]),
    ]
    for k in range(15):
        ring, gaps = rooms[k % len(rooms)]
        obstacles = [footprint((float(rng.uniform(0, 4)), float(rng.uniform(0, 3.5))), float(rng.uniform(0.1, 1.5)),
                               float(rng.uniform(0.1, 1.5)), float(rng.choice([0, 90, 33.3, -147.0])))
                     for _ in range(int(rng.integers(1, 6)))]
        # an L-shaped obstacle takes the edge-by-edge path
        obstacles.append(Polygon([(3, 0.2), (3.8, 0.2), (3.8, 1.2), (3.5, 1.2), (3.5, 0.5), (3, 0.5)]))
        radius = float(rng.choice([0.25, 0.3]))
        space = FreeSpace.build(ring, gaps, obstacles, radius, cell=0.05)
        pts = shapely.points(space.px, space.py)
        inside = shapely.contains_xy(Polygon(ring), space.px, space.py)
        walls = shapely.distance(solid_walls(ring, gaps), pts)
        objs = shapely.distance(shapely.union_all(obstacles), pts)
        want_open = inside & (walls >= radius)
        want_free = want_open & (objs >= radius)
        # cells within a nanometre of the radius may fall either way
        edge = (np.abs(walls - radius) < 1e-9) | (np.abs(objs - radius) < 1e-9)
        assert np.array_equal(space.open[~edge], want_open[~edge])
        assert np.array_equal(space.free[~edge], want_free[~edge])
        assert space.free.sum() < space.open.sum()


def test_footprint_is_the_box_turned_by_the_yaw() -> None:
    """check.footprint computes the corners itself: the same polygon as shapely's box turned
    by -yaw about the centre and moved there."""
    from shapely.affinity import rotate, translate
    from shapely.geometry import box

    from mansion.placement.check import footprint

    for yaw in (0.0, 90.0, 180.0, 270.0, -90.0, 33.3, 359.0):
        got = footprint((1.2, -3.4), 0.8, 0.3, yaw)
        want = translate(rotate(box(-0.4, -0.15, 0.4, 0.15), -yaw, origin=(0, 0)), 1.2, -3.4)
        assert got.equals_exact(want, 1e-12)
    # a quarter turn stays exactly axis-aligned
    assert footprint((0.0, 0.0), 2.0, 1.0, 90.0).bounds == (-0.5, -1.0, 0.5, 1.0)


def test_grid_inside_test_is_shapelys_on_rectilinear_rooms_and_others() -> None:
    """The free-space grid's point-in-room test answers as shapely.contains_xy: on unions of
    random boxes (L, U, T and stepped rooms, either orientation), with grid points on their
    edges and vertices (not contained), and on rooms with a slanted edge or a hole."""
    import shapely
    from shapely.geometry import box

    from mansion.placement.check import _inside

    rng = np.random.default_rng(7)
    rooms = []
    for _ in range(60):
        boxes = []
        for _ in range(rng.integers(1, 4)):
            x = np.sort(rng.choice(np.arange(0, 13) * 0.5, 2, replace=False))
            y = np.sort(rng.choice(np.arange(0, 13) * 0.5, 2, replace=False))
            boxes.append(box(x[0], y[0], x[1], y[1]))
        shape = shapely.union_all(boxes)
        if shape.geom_type == "Polygon":
            rooms += [shape, Polygon(list(shape.exterior.coords)[::-1])]
    rooms += [Polygon([(0, 0), (4, 0), (4, 3), (1, 5)]), box(0, 0, 6, 6).difference(box(2, 2, 3, 3))]
    assert len(rooms) > 60
    for room in rooms:
        x0, y0, x1, y1 = room.bounds
        for step, offset in ((0.25, 0.0), (0.05, 0.025)):  # through the edges; between them
            gx, gy = np.meshgrid(np.arange(x0 - 0.5, x1 + 0.5, step) + offset,
                                 np.arange(y0 - 0.5, y1 + 0.5, step) + offset)
            want = shapely.contains_xy(room, gx, gy)
            assert (_inside(room, gx, gy) == want).all(), room.wkt
    assert not _inside(box(0, 0, 2, 2), np.array([[0.0, 1.0, 2.0]]), np.array([[1.0, 1.0, 1.0]]))[0, [0, 2]].any()


def test_a_kitchen_too_shallow_for_a_table_for_four_gets_a_table_for_two() -> None:
    """A galley kitchen 2.0 m deep has no room for a 1.0 m table with chairs on all sides; it is
    planned a table for two, which the engine places, where a table for four is dropped. A
    kitchen 3.5 m deep keeps the table for four."""
    from mansion.placement import offline

    galley = RoomSpec("staff_kitchen", [(0, 0), (4, 0), (4, 2.0), (0, 2.0)], [((0.3, 0.0), (1.2, 0.0))])
    plan = plan_objects("staff_kitchen", "kitchen", galley.polygon, "office", seed=1)
    table = next(i for i in plan.items if i.object_type == "DiningTable")
    chairs = next(i for i in plan.items if i.object_type == "Chair")
    assert table.max_depth == 0.7 and chairs.count == 2
    assert "DiningTable" in {o.object_type for o in furnish_room(galley, plan, seed=3).objects}
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(offline, "SMALL_TABLE_BELOW", 0.0)
        four = plan_objects("staff_kitchen", "kitchen", galley.polygon, "office", seed=1)
    assert "DiningTable" not in {o.object_type for o in furnish_room(galley, four, seed=3).objects}
    deep = plan_objects("k", "kitchen", [(0, 0), (5, 0), (5, 3.5), (0, 3.5)], "office", seed=1)
    assert next(i for i in deep.items if i.object_type == "Chair").count == 4
