"""Rooms cut again from the region they were cut from: a floor's first mend for a room the
layout left too small or without a usable square (issue 14).

A room cut from a region (an ensuite from its guest room, a kitchen from its flat, an accessible
toilet from its toilet lobby) shares that region with the room that keeps the rest. When the
layout leaves the room unfit (below its minimum area, or with no usable square: a 2.5 m² ensuite,
an accessible toilet 1 m wide), an architect draws it again inside the same region as a rectangle
of its size, and the room it was cut from keeps the rest; or takes the floor from a sibling
beside it, cut from the same region, that can give it. Nothing of the program is lost, so this
is tried before a merge or a drop (:mod:`mansion.building.merge`).

The new room is a rectangle of the region's cells, at least its minimum area and its clear width
on each side (the design table's), as close to its planned area as the region allows. A recut is
kept only when

- the room is no longer unfit, and neither it nor the room it was cut from has a defect of
  ``mansion eval realism`` (elongated, a sliver, below its width, no usable square) it lacked;
  the room it was cut from stays at its minimum area if it was;
- the room it was cut from stays in one piece, and every relation of either room in the room graph
  keeps its shared wall: a door's (``min_contact``) where it had one, else what it had;
- the room has no rooms cut from it (their regions would move) and is no core; on a floor whose
  walls carry the floor above both rooms sit in one first-round region, so no carried wall moves.

Of the rectangles that pass, the one closest to the room's planned area wins, then the one whose
remainder is most compact (the most of its box filled), then the region it was cut from over a
sibling, then the lowest, leftmost one. Each recut is recorded in the floor's ``relaxations``
("bathroom_2 cut again from bay_3 at 5.2 m² (bathroom_2 laid out at 2.2 m², below its 3.5 m²
minimum; it was 2.2 m²)").
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from shapely.geometry import Polygon

from mansion.building.load_bearing import cut_parents, first_round_groups
from mansion.building.merge import DOOR_WIDTH, grid_adjacencies, rooms_from_grid, shape_defects
from mansion.models.graph import RoomGraph
from mansion.models.layout import FloorLayout
from mansion.models.room_design import room_design
from mansion.models.room_shape import EPS

__all__ = ["recut_unfit_rooms"]

#: A rectangle is tried up to this many times its room's planned area (or minimum, the larger).
MAX_GROWTH = 1.6
#: Rectangles judged per room at most, closest to its planned area first (each is drawn and its
#: shared walls measured).
MAX_TRIED = 200


def recut_unfit_rooms(
    layout: FloorLayout,
    graph: RoomGraph,
    unfit: Callable[[FloorLayout, RoomGraph], dict[str, str]],
    building_type: str | None = None,
    min_contact: float = 1.0,
    same_region: bool = False,
) -> tuple[FloorLayout, list[str]]:
    """Cut each room ``unfit`` names (id → why) again inside the region it shares with the room
    it was cut from (or with a sibling beside it), where the module's rules allow; the smallest
    unfit room first. ``same_region``: only within one first-round region (floors that carry
    walls). Returns the layout and a relaxation note per recut."""
    notes: list[str] = []
    tried: set[str] = set()
    parent = cut_parents(graph)
    group = first_round_groups(graph) if same_region else {}
    has_children = set(parent.values())
    nodes = {n.id: n for n in graph.nodes}
    while True:
        bad = {r: why for r, why in unfit(layout, graph).items() if r not in tried}
        if not bad:
            return layout, notes
        rooms = {r.id: r for r in layout.rooms}
        room = min(bad, key=lambda r: (rooms[r].area, r))
        tried.add(room)
        up = parent.get(room)
        if up is None or room in has_children or nodes[room].is_core:
            continue
        # the region it was cut from first, then a sibling beside it (cut from the same region)
        # that can give floor; never across a carried wall
        donors = [up] + sorted(
            other for a in layout.adjacencies if room in (a.a, a.b) and a.longest + EPS >= DOOR_WIDTH
            for other in [a.b if a.a == room else a.a]
            if other in nodes and not nodes[other].is_core and parent.get(other) == up
        )
        best: tuple[tuple[float, float, int], str, FloorLayout] | None = None
        for rank, donor in enumerate(donors):
            if donor not in rooms or (same_region and group.get(donor) != group.get(room)):
                continue
            found = _best_recut(layout, graph, room, donor, building_type, min_contact)
            if found is not None and (best is None or (found[0], min(rank, 1)) < (best[0][:2], best[0][2])):
                best = ((*found[0], min(rank, 1)), donor, found[1])
        if best is None:
            continue
        _, donor, layout = best
        before = rooms[room].area
        after = next(r for r in layout.rooms if r.id == room).area
        where = f"from {donor}" if donor == up else f"with floor from {donor}"
        notes.append(f"{room} cut again {where} at {after:.1f} m² ({room} {bad[room]}; it was {before:.1f} m²)")


def _best_recut(
    layout: FloorLayout,
    graph: RoomGraph,
    room: str,
    up: str,
    building_type: str | None,
    min_contact: float,
) -> tuple[tuple[float, float], FloorLayout] | None:
    """((the miss from the room's planned area, minus the remainder's fill of its box), the
    layout) of the best rectangle for ``room`` in the region it shares with ``up``, or None."""
    grid = layout.grid
    labels = grid.array()
    ids = list(grid.ids)
    k_room, k_up = ids.index(room), ids.index(up)
    region = (labels == k_room) | (labels == k_up)
    rr, cc = np.nonzero(region)
    r0, r1, c0, c1 = rr.min(), rr.max() + 1, cc.min(), cc.max() + 1
    cell = grid.cell_size
    rooms = {r.id: r for r in layout.rooms}
    node = next(n for n in graph.nodes if n.id == room)
    design = room_design(node.room_type)
    least = node.min_area if node.min_area is not None else design.min_area
    target = max(rooms[room].target_area, least)
    side = max(3, int(np.ceil(design.min_width / cell - 1e-6)))
    lo, hi = int(np.ceil(least / (cell * cell) - 1e-6)), int(target * MAX_GROWTH / (cell * cell))
    # the relations whose shared walls must hold, with what they had
    adj = {frozenset((a.a, a.b)): a for a in layout.adjacencies}
    keep: list[tuple[str, str, float, float]] = []
    for e in graph.edges:
        if room in (e.source, e.target) or up in (e.source, e.target):
            a = adj.get(frozenset((e.source, e.target)))
            if a is not None:
                keep.append((e.source, e.target, a.longest, a.contact))
    old_room = Polygon(rooms[room].polygon, rooms[room].holes)
    old_up = Polygon(rooms[up].polygon, rooms[up].holes)
    room_defects = shape_defects(old_room, node.room_type, building_type)
    up_defects = shape_defects(old_up, rooms[up].room_type, building_type)
    up_node = next(n for n in graph.nodes if n.id == up)
    up_least = up_node.min_area if up_node.min_area is not None else 0.0
    # prefix sums of the region: a rectangle lies inside it when it holds h * w region cells
    inside = np.zeros((region.shape[0] + 1, region.shape[1] + 1), dtype=np.int64)
    inside[1:, 1:] = np.cumsum(np.cumsum(region, axis=0), axis=1)
    shapes: list[tuple[float, int, int, int, int]] = []
    for h in range(side, r1 - r0 + 1):
        for w in range(side, c1 - c0 + 1):
            if not lo <= h * w <= hi:
                continue
            # the h × w windows of the region's box, by their lower-left cell
            full = (
                inside[r0 + h:r1 + 1, c0 + w:c1 + 1] - inside[r0:r1 + 1 - h, c0 + w:c1 + 1]
                - inside[r0 + h:r1 + 1, c0:c1 + 1 - w] + inside[r0:r1 + 1 - h, c0:c1 + 1 - w]
            ) == h * w
            miss = abs(h * w * cell * cell - target)
            shapes += [(miss, int(y) + r0, int(x) + c0, h, w) for y, x in zip(*np.nonzero(full))]
    shapes.sort()
    best: tuple[float, float, int, int, FloorLayout] | None = None
    for miss, y, x, h, w in shapes[:MAX_TRIED]:
        if best is not None and miss > best[0] + EPS:
            break
        new = np.where(region, k_up, labels).astype(np.int32)
        new[y:y + h, x:x + w] = k_room
        rest = region.copy()
        rest[y:y + h, x:x + w] = False
        if not rest.any():
            continue
        # the shared walls first (measured by the core, the cheapest test), then the pieces
        adjacencies = grid_adjacencies(new, ids, cell)
        after = {frozenset((a.a, a.b)): a for a in adjacencies}
        if any(
            (a := after.get(frozenset((s, t)))) is None
            or a.longest + EPS < min(longest, max(DOOR_WIDTH, min_contact))
            or a.contact + EPS < min(contact, min_contact)
            for s, t, longest, contact in keep
        ):
            continue
        pair = after.get(frozenset((room, up)))
        if pair is None or pair.longest + EPS < DOOR_WIDTH or not _connected(rest):
            continue
        drawn = {r.id: r for r in rooms_from_grid(new, grid, rooms, {})}
        shape_room = Polygon(drawn[room].polygon, drawn[room].holes)
        shape_up = Polygon(drawn[up].polygon, drawn[up].holes)
        if not shape_defects(shape_room, node.room_type, building_type) <= room_defects - {"unusable"}:
            continue
        if not shape_defects(shape_up, rooms[up].room_type, building_type) <= up_defects:
            continue
        if drawn[up].area + EPS < min(up_least, rooms[up].area):
            continue
        ry, rx = np.nonzero(rest)
        fill = rest.sum() / ((ry.max() - ry.min() + 1) * (rx.max() - rx.min() + 1))
        key = (miss, -float(fill), y, x)
        if best is None or key < best[:4]:
            relabelled = layout.model_copy(update={
                "rooms": [drawn.get(r.id, r) for r in layout.rooms],
                "grid": grid.model_copy(update={"labels": new.tolist()}),
                "adjacencies": adjacencies,
            })
            best = (*key, relabelled)
    return None if best is None else ((best[0], best[1]), best[4])


def _connected(mask: np.ndarray) -> bool:
    """Whether the True cells of ``mask`` form one 4-connected piece (grown from one cell, a ring
    of neighbours at a time)."""
    reached = np.zeros_like(mask)
    first = np.argwhere(mask)[0]
    reached[first[0], first[1]] = True
    while True:
        grown = reached.copy()
        grown[1:] |= reached[:-1]
        grown[:-1] |= reached[1:]
        grown[:, 1:] |= reached[:, :-1]
        grown[:, :-1] |= reached[:, 1:]
        grown &= mask
        if (grown == reached).all():
            return bool((reached == mask).all())
        reached = grown
