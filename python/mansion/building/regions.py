"""First-round regions too narrow for the rooms that will fill them (issue 14).

On a building whose walls carry the floor above (an apartment block, an office), the walls of a
floor's first cut round go up through every floor (:mod:`mansion.building.load_bearing`): each
floor above lays the same flat, the same office bay, out inside the same region. A region the
lowest floor leaves with an arm narrower than the rooms it holds need (a flat's region running
1.5 m wide for 10 m between the corridor and the facade, where the ground floor put a long
bathroom) is then the same arm on every floor above, and there the flat's living room, its
bedroom or its kitchen must take it: below its clear width on each floor, and no mend moves a
carried wall. The floor whose walls go up is where such a region can still change.

:func:`narrow_regions` names those regions: the cells of the region (every room the first round's
room was cut into) that no square of the widest clear width among its rooms covers, more than
``mansion eval realism``'s share (:data:`mansion.models.room_shape.TOLERANCE`) of its cells,
measured as the realism measure measures a room.

:func:`hub_takes_arms` mends them on that floor, before its other mends: where the hub is
circulation (a corridor, an entrance hall), each strip of a narrow region that those squares
leave and that lies beside the hub becomes the hub's (the corridor 3 m wide along the facade
where the flat's arm was), so that the floors above repeat a region their rooms fit. A strip
moves only when the hub stays in one piece at most :data:`mansion.building.recut.MAX_GROWTH`
times its planned area and gains no realism defect nor a part no 1 m square covers; every room
that gives cells stays in one piece, at its minimum area (or what it had) and with no defect it
lacked, or, when all its cells go, is a room the program can spare with no room cut from it
(left out and recorded in the floor's ``relaxations``); and every relation of the rooms kept
keeps its wall, a door's where it had one. The region must come out no longer narrow, else
nothing moves.

The floors above follow: where the hub took an arm (``Floor.held_regions``, passed up), the
solver holds the regions of their first round, not only their rooms, off the walls carried from
below (``SolverSettings.hold_regions``; ``walled`` in crates/mansion-core/src/cut.rs), so the flat
above cannot run its region round the new wall into the arm, which only the hub beside it can
then take. Elsewhere the regions above may still straddle a carried wall where their rooms part
along it (an office floor above a lobby floor of other regions): held everywhere, those floors
lost rooms (office 159 of the second hundred seven).
"""

from __future__ import annotations

import numpy as np

from mansion.building.dissolve import _dissolved_graph, _dissolved_layout
from mansion.building.load_bearing import cut_parents, first_round_groups
from mansion.building.merge import mask_defects, may_spare, square_cover
from mansion.building.recut import MAX_GROWTH, _connected, _kept_walls, _least, _passable, _pieces, _redrawn, _walls
from mansion.models.graph import RoomGraph, RoomNode
from mansion.models.layout import FloorLayout
from mansion.models.room_design import needed_width, room_design
from mansion.models.room_shape import EPS, SHARE_EPS, TOLERANCE

__all__ = ["hub_takes_arms", "narrow_regions"]


def narrow_regions(layout: FloorLayout, graph: RoomGraph, building_type: str | None) -> list[str]:
    """The first-round regions of ``layout`` (by the first-round room's id, in id order; not the
    hub's, not a core's) more than :data:`TOLERANCE` of whose cells lie in parts narrower than the
    widest clear width any of its rooms needs."""
    return [group for group, (mask, keep) in _regions(layout, graph, building_type).items() if _narrow(mask, keep)]


def _narrow(mask: np.ndarray, keep: np.ndarray) -> bool:
    """Whether more than :data:`TOLERANCE` of ``mask``'s cells lie outside ``keep``."""
    cells = int(mask.sum())
    return cells > 0 and (cells - int((mask & keep).sum())) / cells > TOLERANCE + SHARE_EPS


def _regions(
    layout: FloorLayout, graph: RoomGraph, building_type: str | None,
) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Each first-round region of ``layout`` but the hub's and the cores' (by its first-round
    room, in id order): (its cells, the cells squares of the widest clear width its rooms need
    cover)."""
    groups = first_round_groups(graph)
    hub = graph.hub.id
    cores = {n.id for n in graph.nodes if n.is_core}
    labels = layout.grid.array()
    cell = layout.grid.cell_size
    ids = list(layout.grid.ids)
    types = {r.id: r.room_type for r in layout.rooms}
    members: dict[str, list[int]] = {}
    for k, rid in enumerate(ids):
        group = groups.get(rid)
        if group is None or group == hub or group in cores or rid not in types:
            continue
        members.setdefault(group, []).append(k)
    regions: dict[str, tuple[np.ndarray, np.ndarray]] = {}
    for group in sorted(members):
        keys = members[group]
        mask = np.isin(labels, keys)
        width = max(needed_width(types[ids[k]], building_type) for k in keys)
        # a part exactly the width wide is wide enough, as the realism measure has it
        regions[group] = (mask, square_cover(mask, width - 2 * EPS, cell))
    return regions


def hub_takes_arms(
    layout: FloorLayout, graph: RoomGraph, building_type: str | None, min_contact: float = 1.0,
    keep: frozenset[str] = frozenset(),
) -> tuple[FloorLayout, RoomGraph, list[str]]:
    """``layout`` and ``graph`` with the strips of the narrow first-round regions
    (:func:`narrow_regions`) that lie beside the hub made the hub's, under the module's rules,
    and a relaxation note per room left out so; unchanged where the hub is no circulation or no
    region comes out sound. ``keep``: rooms the description asked for, never left out."""
    hub = graph.hub.id
    rooms = {r.id: r for r in layout.rooms}
    if hub not in rooms or not room_design(rooms[hub].room_type).circulation:
        return layout, graph, []
    nodes = {n.id: n for n in graph.nodes}
    parent = cut_parents(graph)
    ids = list(layout.grid.ids)
    h = ids.index(hub)
    labels = start = layout.grid.array().astype(np.int32)
    gone: list[str] = []
    for group, (mask, cover) in _regions(layout, graph, building_type).items():
        if not _narrow(mask, cover):
            continue
        new, lost = labels, list(gone)
        # the largest strip first: it decides most of the region's share below its width
        for strip in sorted(_pieces(mask & ~cover), key=lambda p: (-len(p), p)):
            rows, cols = zip(*strip)
            trial = new.copy()
            trial[rows, cols] = h
            spent = _takes(layout, graph, nodes, parent, new, trial, hub, building_type, min_contact, keep, lost)
            if spent is not None:
                new, lost = trial, [*lost, *spent]
        if new is not labels and not _narrow(mask & (new != h), cover):
            labels, gone = new, lost
    if labels is start:
        return layout, graph, []
    if not gone:
        return _redrawn(layout, labels), graph, []
    area = {rid: float(rooms[rid].area) for rid in gone}
    notes = [
        f"{rid} left out: its floor, an arm of its region narrower than the region's rooms need, "
        f"given to {hub} (the floors above repeat the region)"
        for rid in gone
    ]
    took = {hub: sum(area.values())}
    return _dissolved_layout(layout, labels, gone, took), _dissolved_graph(graph, gone, took, {}), notes


def _takes(
    layout: FloorLayout, graph: RoomGraph, nodes: dict[str, RoomNode], parent: dict[str, str], was: np.ndarray,
    trial: np.ndarray, hub: str, building_type: str | None, min_contact: float, keep: frozenset[str],
    gone: list[str],
) -> list[str] | None:
    """The rooms left out when the hub takes the cells ``trial`` gives it over ``was``
    (:func:`hub_takes_arms`), or None when it may not: a room all of whose cells go must be one
    the program can spare (:func:`mansion.building.merge.may_spare`) with no room cut from it.
    ``gone``: the rooms already left out."""
    rooms = {r.id: r for r in layout.rooms}
    cell = layout.grid.cell_size
    ids = list(layout.grid.ids)
    h = ids.index(hub)
    hub_now, hub_was = trial == h, was == h
    cap = max(rooms[hub].target_area, _least(nodes[hub])) * MAX_GROWTH
    kind = rooms[hub].room_type
    if (
        hub_now.sum() * cell * cell > cap + EPS or not _connected(hub_now)
        or not mask_defects(hub_now, kind, building_type, cell) <= mask_defects(hub_was, kind, building_type, cell)
        or any(a > b for a, b in zip(_passable(hub_now), _passable(hub_was)))
    ):
        return None
    givers = {ids[k] for k in np.unique(was[hub_now & ~hub_was])}
    spent: list[str] = []
    for room in sorted(givers):
        k = ids.index(room)
        now, before = trial == k, was == k
        if not now.any():
            left = RoomGraph(
                nodes=[n for n in graph.nodes if n.id not in gone],
                edges=[e for e in graph.edges if e.source not in gone and e.target not in gone],
            )
            if room in parent.values() or not may_spare(nodes[room], left, parent, keep):
                return None
            spent.append(room)
            continue
        rt = rooms[room].room_type
        if (
            not _connected(now)
            or now.sum() * cell * cell + EPS < min(_least(nodes[room]), before.sum() * cell * cell)
            or not mask_defects(now, rt, building_type, cell) <= mask_defects(before, rt, building_type, cell)
        ):
            return None
    out = {*gone, *spent}
    held = [w for w in _kept_walls(layout, graph, {hub, *givers} - out) if w[0] not in out and w[1] not in out]
    return spent if _walls(trial, ids, cell, held, min_contact) is not None else None
