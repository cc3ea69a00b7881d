"""Families laid out again: a region and the rooms cut from it redrawn as one row along a side,
for a room of them below its clear width (issue 14).

The cut grows the rooms of a region (an office bay: its open office and the meeting room,
private office and print room cut from it; a flat's living room and its bedrooms) from seeds,
and a tight region can come out as rooms wrapped around each other: an open office 1.5-3 m wide
curled round a meeting room and a private office in a bay 5 m wide, where an architect draws the
cellular rooms in a row along one end of the bay and gives the open office the rest. One room at
a time cannot mend that (:mod:`mansion.building.recut` finds no rectangle that leaves the open
office whole); the family together can.

:func:`relay_families` takes each family with a room below its clear width: a head (not the hub,
nor a core) and the one to :data:`MAX_FAMILY` rooms cut from it, none with rooms of its own. In
the cells they hold, the rooms cut from the head are laid side by side in a band along one side
(each a run of whole columns with its minimum area and a share of the rest by its planned area),
a band as deep as their areas need or as the widest of their widths asks, and the head takes the
rest. Every side, depth and order of the rooms (their order along the side as they lie now, and
every order of up to :data:`ALL_ORDERS` rooms) is tried. A re-layout is kept under the rules of
a cluster re-laid in :mod:`mansion.building.recut` (every room in one piece, at its minimum area,
with a usable square, no new part one cell wide, every relation keeping its wall) and only when
no room gains a defect of ``mansion eval realism``'s that it lacked and the family has fewer in
total; of those, the fewest defects, then the rooms closest to their planned areas. The family's
cells stay its own, so no wall between first-round regions moves (floors that carry walls keep
them). Nothing of the program changes.

A family no re-layout mends is often one its region cannot hold at the rooms' minimums (a bay
5 m × 15 m asked for an open office of 30 m² and five cellular rooms). A second pass, after the
other mends, lays it out again without one of its rooms, the smallest whose going lets it be
laid out, dropped as :mod:`mansion.building.merge` drops a room (its floor given to the head;
never a room a home needs most, nor the last of its type on the floor, nor one the description
asked for): "a program that does not fit drops, merges or moves rooms" (issue 14). Each
re-layout is recorded in the floor's ``relaxations``.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterable

import numpy as np
from shapely.geometry import Polygon

from mansion.building.load_bearing import cut_parents
from mansion.building.merge import _may_drop, _merged_graph, _merged_layout, mask_defects
from mansion.building.recut import (
    _judged, _least, _wide_rectangle, band_shares, cluster_cells, in_a_row,
)
from mansion.models.graph import RoomGraph
from mansion.models.layout import FloorLayout
from mansion.models.room_design import needed_width
from mansion.models.room_shape import EPS, mostly_narrower

__all__ = ["ALL_ORDERS", "MAX_FAMILY", "relay_families"]

#: Rooms cut from a head, at most, for its family to be laid out again.
MAX_FAMILY = 6
#: Up to this many rooms cut from the head, every order of them along the band is tried; more
#: keep the order they lie in now (and its reverse). Four cost the hundred 1.9 s more of its
#: 41 s for one room fewer below its width (80 against 81).
ALL_ORDERS = 3


#: Why a family is laid out again, in its note.
WHY = "a room of it laid out narrower than its clear width"


def relay_families(
    layout: FloorLayout,
    graph: RoomGraph,
    building_type: str | None,
    min_contact: float = 1.0,
    keep: Iterable[str] = (),
    drop: bool = False,
) -> tuple[FloorLayout, RoomGraph, list[str]]:
    """``layout`` and ``graph`` with each family holding a room below its clear width laid out
    again where the module's rules allow, heads in the order of their ids. With ``drop`` (a
    second pass, for the families the first could not mend), a family too tight for its rooms
    is laid out again without one of them instead, the smallest that lets it be, dropped with its
    floor given to the head where :mod:`mansion.building.merge` would drop it (never one of
    ``keep``, the rooms the description asked for). With a relaxation note per family."""
    notes: list[str] = []
    kept = frozenset(keep)
    parent = cut_parents(graph)
    heads: set[str] = set()
    for room in layout.rooms:
        if room.id not in parent or _wide_rectangle(room, building_type):
            continue
        # room_shape's measure, cached for the outlines the earlier mends measured already
        if mostly_narrower(Polygon(room.polygon, room.holes), needed_width(room.room_type, building_type)):
            heads.update((room.id, parent[room.id]))
    for head in sorted(heads):
        # the cut tree as it stands: a family laid out without a room has one room fewer
        parent = cut_parents(graph)
        nodes = {n.id: n for n in graph.nodes}
        members = sorted(r for r, up in parent.items() if up == head)
        if (
            head not in nodes or head == graph.hub.id or nodes[head].is_core
            or not 1 <= len(members) <= MAX_FAMILY
            or any(up in members for up in parent.values()) or any(nodes[m].is_core for m in members)
        ):
            continue
        if not drop:
            found = _relaid_family(layout, graph, head, members, building_type, min_contact)
            if found is not None:
                layout = found[1]
                notes.append(f"{head} laid out again with {', '.join(members)} in a row along it ({WHY})")
            continue
        # too tight for all its rooms (the pass without drops found no re-layout): without the
        # smallest room whose going lets it be laid out, dropped as mansion.building.merge drops
        # a room
        rooms = {r.id: r for r in layout.rooms}
        for gone in sorted(members, key=lambda m: (rooms[m].area, m)) if len(members) > 1 else []:
            if not _may_drop(nodes[gone], nodes[head], graph, parent, kept):
                continue
            fewer = _merged_graph(graph, gone, head)
            found = _relaid_family(
                _merged_layout(layout, gone, head), fewer, head, [m for m in members if m != gone],
                building_type, min_contact,
            )
            if found is not None:
                layout, graph = found[1], fewer
                rest = ", ".join(m for m in members if m != gone)
                notes.append(
                    f"{gone} dropped, its floor given to {head}; {head} laid out again with {rest} "
                    f"in a row along it ({WHY})"
                )
                break
    return layout, graph, notes


def _relaid_family(
    layout: FloorLayout,
    graph: RoomGraph,
    head: str,
    members: list[str],
    building_type: str | None,
    min_contact: float,
) -> tuple[float, FloorLayout] | None:
    """(its score: defects, then the rooms' miss from their planned areas; the layout) of the
    best re-layout of ``head``'s family that passes, or None."""
    family = [head, *members]
    labels, cell, keys, region, keep, passable = cluster_cells(layout, graph, family)
    rooms = {r.id: r for r in layout.rooms}
    nodes = {n.id: n for n in graph.nodes}
    before = {rid: mask_defects(labels == keys[rid], rooms[rid].room_type, building_type, cell) for rid in family}
    least = {rid: _least(nodes[rid]) for rid in family}
    targets = {rid: max(rooms[rid].target_area, least[rid]) for rid in family}
    width = {m: needed_width(rooms[m].room_type, building_type) for m in members}
    deep = max(width.values())
    best: tuple[float, FloorLayout] | None = None
    tried: set[bytes] = set()
    for turn in range(4):
        view = np.rot90(region, turn)
        rows = np.nonzero(view.any(axis=1))[0]
        cols_all = np.nonzero(view.any(axis=0))[0]
        span = len(cols_all) * cell
        # the members' centroids along the band's side, as they lie now
        along = {m: float(np.nonzero(np.rot90(labels == keys[m], turn))[1].mean()) for m in members}
        natural = sorted(members, key=lambda m: (along[m], m))
        orders = (
            list(itertools.permutations(members)) if len(members) <= ALL_ORDERS
            else [tuple(natural), tuple(reversed(natural))]
        )
        need = sum(targets[m] for m in members)
        depths = sorted({
            int(np.ceil(need / span / cell - 1e-6)), int(np.ceil(need / span / cell - 1e-6)) + 1,
            int(np.ceil(deep / cell - 1e-6)),
        })
        for depth in depths:
            if not 1 <= depth < len(rows):
                continue
            band = np.zeros_like(view)
            band[rows[0]:rows[0] + depth] = view[rows[0]:rows[0] + depth]
            shares = band_shares(band, members, least, targets, cell)
            # the head keeps what the band leaves, which must hold its minimum
            if shares is None or float((view & ~band).sum()) * cell * cell + EPS < least[head]:
                continue
            for order in orders:
                turned = np.rot90(labels, turn).copy()
                turned[view & ~band] = keys[head]
                if not in_a_row(turned, band, order, shares, keys, cell):
                    continue
                # a room that was at its width must be as wide and as deep as it (fewer columns
                # or rows of the band hold no square of it): a quick refusal before the measures
                if any(
                    min(depth, int((band & (turned == keys[m])).any(axis=0).sum())) * cell + EPS < width[m]
                    for m in members if "narrow" not in before[m]
                ):
                    continue
                new = np.ascontiguousarray(np.rot90(turned, -turn)).astype(np.int32)
                seen = new.tobytes()
                if seen in tried:
                    continue
                tried.add(seen)
                found = _judged(
                    layout, new, family, keep, before, least, targets, passable, building_type, min_contact, own=True,
                )
                if found is not None and (best is None or found[0] < best[0] - EPS):
                    best = found
    return best

