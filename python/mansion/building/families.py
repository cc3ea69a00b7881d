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
nor a core) and the one to :data:`MAX_FAMILY` rooms cut from it, none with rooms of its own (a
larger family, below). In the cells they hold, the rooms cut from the head are laid side by side
in a band along one side (each a run of whole columns with its minimum area and a share of the
rest by its planned area), a band as deep as their planned areas or their minimums need or as the
widest of their widths asks, and the head takes the rest. Every side, depth and order of the
rooms (their order along the side as they lie now, and every order of up to :data:`ALL_ORDERS`
rooms) is tried. So are a band short of the side, the head keeping one end of it (where it meets
a core or a room it keeps a wall with), and two bands along opposite sides with the head between
them, the rooms split between them where they lie now (the ones nearer a side in its band): a bay
6 m wide holds a meeting room and two private offices at its two ends where a row of the three
along either side leaves one too narrow or the open office too narrow. A re-layout is kept under
the rules of a cluster re-laid in :mod:`mansion.building.recut` (every room in one piece, at its
minimum area, with a usable square, no new part one cell wide, every relation keeping its wall)
and only when no room gains a defect of ``mansion eval realism``'s that it lacked and the family
has fewer in total; of those, the fewest defects, then the rooms closest to their planned areas.
The family's cells stay its own, so no wall between first-round regions moves (floors that carry
walls keep them). Nothing of the program changes.

A head whose family is too large to lay out so (the hub, whose family is the floor; more than
:data:`MAX_FAMILY` rooms; rooms with rooms of their own) still moves its islands, the rooms cut
from it that touch nothing but it and each other, to a side the same way: a reading hall 8 m
wide with two study rooms in its middle, 2.5 m wide on either side of them, gets them along one
wall.

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
from typing import Any

import numpy as np

from mansion.building.family_solve import SOLVE_SEEDS, solved_family
from mansion.building.load_bearing import cut_parents
from mansion.building.merge import _may_drop, _merged_graph, _merged_layout, mask_defects
from mansion.building.outlines import shape_measure
from mansion.building.recut import (
    _box_round, _least, _redrawn, _wide_rectangle, area_shares, band_columns, band_shares, cluster_cells,
    edge_grown, family_rules, in_a_row, judged_score,
)
from mansion.models.graph import RoomGraph
from mansion.models.layout import FloorLayout
from mansion.models.room_design import needed_width
from mansion.models.room_shape import EPS

__all__ = ["ALL_ORDERS", "MAX_FAMILY", "SOLVED_FAMILIES", "relay_families", "touching"]

#: Rooms cut from a head, at most, for its family to be laid out again.
MAX_FAMILY = 6
#: Up to this many rooms cut from the head, every order of them along the band is tried; more
#: keep the order they lie in now (and its reverse). Four cost the hundred 1.9 s more of its
#: 41 s for one room fewer below its width (80 against 81).
ALL_ORDERS = 3


#: Whether a family that no rows of rectangles mend is cut again by the solver on the cells it
#: holds (:func:`mansion.building.family_solve.solved_family`): a hotel's dining zone, an L round
#: the lobby's corner, whose kitchen no band along a side makes 3.6 m wide.
SOLVED_FAMILIES = True

#: How the rooms cut from the head lie after a re-layout, in its note, by their rows.
ROWS = {1: "in a row along it", 2: "in two rows, along opposite sides of it"}
#: Why a family is laid out again, in its note.
WHY = "a room of it laid out narrower than its clear width"


def relay_families(
    layout: FloorLayout,
    graph: RoomGraph,
    building_type: str | None,
    min_contact: float = 1.0,
    keep: Iterable[str] = (),
    drop: bool = False,
    solver: dict[str, Any] | None = None,
    seeds: int = SOLVE_SEEDS,
) -> tuple[FloorLayout, RoomGraph, list[str]]:
    """``layout`` and ``graph`` with each family holding a room below its clear width laid out
    again where the module's rules allow, heads in the order of their ids. With ``drop`` (a
    second pass, for the families the first could not mend), a family too tight for its rooms
    is laid out again without one of them instead, the smallest that lets it be, dropped with its
    floor given to the head where :mod:`mansion.building.merge` would drop it (never one of
    ``keep``, the rooms the description asked for). ``solver``: the floor's keyword arguments of
    :func:`mansion.solve_floor`; with them (and :data:`SOLVED_FAMILIES`), a family no rows of
    rectangles mend is cut again by the solver on its own cells, under ``seeds`` of its random
    seeds. With a relaxation note per family."""
    notes: list[str] = []
    kept = frozenset(keep)
    parent = cut_parents(graph)
    heads: set[str] = set()
    for room in layout.rooms:
        if (room.id not in parent and room.id != graph.hub.id) or _wide_rectangle(room, building_type):
            continue
        # room_shape's measure, cached for the outlines the earlier mends measured already
        if shape_measure(room, ("narrow", needed_width(room.room_type, building_type))):
            heads.update((room.id, parent.get(room.id, room.id)))
    read = None
    for head in sorted(heads):
        # the cut tree as it stands: a family laid out without a room has one room fewer (read
        # again only then: only a drop changes the graph)
        if graph is not read:
            parent, nodes, read = cut_parents(graph), {n.id: n for n in graph.nodes}, graph
        if head not in nodes or nodes[head].is_core:
            continue
        members = sorted(r for r, up in parent.items() if up == head)
        if (
            head == graph.hub.id or not 1 <= len(members) <= MAX_FAMILY
            or any(up in members for up in parent.values()) or any(nodes[m].is_core for m in members)
        ):
            # a head whose family is too large to lay out again (the hub: the floor) still
            # moves the rooms it closes round to its sides: a reading hall 8 m wide with two
            # study rooms in its middle, 2.5 m wide on either side of them
            members = [] if drop else _islands(layout, head, members, parent)
            if not 1 <= len(members) <= MAX_FAMILY:
                continue
        if not drop:
            found = _relaid_family(layout, graph, head, members, building_type, min_contact)
            if found is not None:
                layout = found[1]
                notes.append(f"{head} laid out again with {', '.join(members)} {ROWS[found[2]]} ({WHY})")
            elif SOLVED_FAMILIES and solver is not None:
                # no rows of rectangles pass: the solver cuts the family's cells again
                # (mansion.building.family_solve)
                solved = solved_family(layout, graph, head, members, building_type, min_contact, solver, seeds)
                if solved is not None:
                    layout = solved[1]
                    notes.append(f"{head} cut again with {', '.join(members)} on their own floor ({WHY})")
            continue
        # too tight for all its rooms (the pass without drops found no re-layout): without the
        # smallest room whose going lets it be laid out, dropped as mansion.building.merge drops
        # a room
        rooms = {r.id: r for r in layout.rooms}
        for gone in sorted(members, key=lambda m: (rooms[m].area, m)) if len(members) > 1 else []:
            if not _may_drop(nodes[gone], nodes[head], graph, parent, kept):
                continue
            fewer = _merged_graph(graph, gone, head)
            merged = _merged_layout(layout, gone, head)
            rest = [m for m in members if m != gone]
            found = _relaid_family(merged, fewer, head, rest, building_type, min_contact)
            relaid, how = (None, "") if found is None else (found[1], f"laid out again with {', '.join(rest)} {ROWS[found[2]]}")
            if relaid is None and SOLVED_FAMILIES and solver is not None:
                # or cut again by the solver without it (mansion.building.family_solve)
                solved = solved_family(merged, fewer, head, rest, building_type, min_contact, solver, seeds)
                if solved is not None:
                    relaid, how = solved[1], f"cut again with {', '.join(rest)} on their own floor"
            if relaid is not None:
                layout, graph = relaid, fewer
                notes.append(f"{gone} dropped, its floor given to {head}; {head} {how} ({WHY})")
                break
    return layout, graph, notes


def touching(layout: FloorLayout, room: str) -> set[str | None]:
    """The rooms (cores too) with a cell beside one of ``room``'s, None for the outline."""
    labels = np.pad(layout.grid.array(), 1, constant_values=-1)
    ids = list(layout.grid.ids)
    mask = labels == ids.index(room)
    return {ids[v] if v >= 0 else None for v in np.unique(labels[edge_grown(mask) & ~mask]).tolist()}


def _islands(layout: FloorLayout, head: str, members: list[str], parent: dict[str, str]) -> list[str]:
    """The rooms of ``members`` (cut from ``head``) with no rooms of their own that touch only
    ``head`` and each other: no other room, no core, not the outline."""
    ids = set(layout.grid.ids)
    cores = {r.id for r in layout.rooms if r.is_core}
    heads = set(parent.values())
    found = {m for m in members if m not in heads and m not in cores and m in ids}
    touches = {m: touching(layout, m) for m in found}
    while True:
        # a room beside one that is not an island is not one either
        gone = {m for m in found if not touches[m] <= {head, *found}}
        if not gone:
            return sorted(found)
        found -= gone


def _relaid_family(
    layout: FloorLayout,
    graph: RoomGraph,
    head: str,
    members: list[str],
    building_type: str | None,
    min_contact: float,
) -> tuple[float, FloorLayout, int] | None:
    """(its score: defects, then the rooms' miss from their planned areas; the layout; the rows
    of rooms along the head, 1 or 2) of the best re-layout of ``head``'s family that passes, or
    None."""
    family = [head, *members]
    labels, cell, keys, region, keep, passable = cluster_cells(layout, graph, family)
    rooms = {r.id: r for r in layout.rooms}
    before, least, targets = family_rules(layout, graph, family, building_type, labels, keys)
    width = {m: needed_width(rooms[m].room_type, building_type) for m in members}
    head_width = needed_width(rooms[head].room_type, building_type)
    # the widths the rooms at their width now must keep (0 for those below it): the bands too
    # shallow or short for them are skipped, and the rows that leave them narrower refused
    firm = {m: 0.0 if "narrow" in before[m] else width[m] for m in members}
    best: tuple[float, np.ndarray, int] | None = None
    tried: set[bytes] = set()
    # the rows are laid out in the family's box, not the floor's grid (a tenth of the cells)
    rr, cc = np.nonzero(region)
    box = (slice(int(rr.min()), int(rr.max()) + 1), slice(int(cc.min()), int(cc.max()) + 1))
    # and judged on that box and the cells round it (every wall of the family's rooms lies there,
    # so judged_score finds what it would on the floor's grid): ``inner`` is the box within it
    around = _box_round(region)
    inner = tuple(slice(b.start - a.start, b.stop - a.start) for a, b in zip(around, box))
    for turn in range(4):
        view = np.rot90(region[box], turn)
        rows = np.nonzero(view.any(axis=1))[0]
        span = int(view.any(axis=0).sum()) * cell
        turned_labels = np.rot90(labels[box], turn)
        # the members' centroids along the band's side and across it, as they lie now
        along = {m: float(np.nonzero(turned_labels == keys[m])[1].mean()) for m in members}
        across = {m: float(np.nonzero(turned_labels == keys[m])[0].mean()) for m in members}
        groupings: list[list[list[str]]] = [[members]]
        if turn < 2 and len(members) > 1:
            # or in two rows, along this side and the opposite one, the head between them (a
            # bay 5 m wide with its meeting room at one end and its private offices at the
            # other): the members split where they lie now, the nearer this side in its row
            by_across = sorted(members, key=lambda m: (across[m], m))
            groupings += [[by_across[:k], by_across[k:]] for k in range(1, len(members))]
        for groups in groupings:
            for parts, orders in _bands(view, rows, groups, along, least, targets, width, firm, span, cell):
                band = np.logical_or.reduce(parts)
                shares: dict[str, float] | None = {}
                for part, group in zip(parts, groups):
                    got = band_shares(part, group, least, targets, cell)
                    shares = None if got is None or shares is None else {**shares, **got}
                # the head keeps what the bands leave, which must hold its minimum
                head_cells = view & ~band
                if shares is None or float(head_cells.sum()) * cell * cell + EPS < least[head]:
                    continue
                variants = [(order, shares) for order in orders]
                if len(groups) == 1:
                    variants += _short_rows(band, head, members, orders, least, targets, head_width, cell)
                columns = [band_columns(part) for part in parts]
                for order, sizes in variants:
                    turned = turned_labels.copy()
                    turned[head_cells] = keys[head]
                    if not all(
                        in_a_row(turned, part, row, sizes, keys, cell, cols)
                        for part, row, cols in zip(parts, order, columns)
                    ):
                        continue
                    # a room that was at its width must be as wide and as deep as it (fewer
                    # columns or rows of the band hold no square of it): a quick refusal
                    # before the measures
                    if any(
                        min(int(own.any(axis=1).sum()), int(own.any(axis=0).sum())) * cell + EPS < firm[m]
                        for m in members if firm[m] for own in [turned == keys[m]]
                    ):
                        continue
                    laid = np.rot90(turned, -turn)
                    seen = laid.tobytes()
                    if seen in tried:
                        continue
                    tried.add(seen)
                    new = labels[around].astype(np.int32)
                    new[inner] = laid
                    score = judged_score(
                        layout, new, family, keep, before, least, targets, passable, building_type, min_contact,
                        own=True,
                    )
                    if score is not None and (best is None or score < best[0] - EPS):
                        best = (score, new, len(groups))
    if best is None:
        return None
    # only the kept re-layout is drawn
    whole = labels.astype(np.int32)
    whole[around] = best[1]
    return best[0], _redrawn(layout, whole), best[2]


def _short_rows(
    band: np.ndarray, head: str, members: list[str], orders: list[tuple[tuple[str, ...], ...]],
    least: dict[str, float], targets: dict[str, float], head_width: float, cell: float,
) -> list[tuple[tuple[tuple[str, ...], ...], dict[str, float]]]:
    """A row short of its side, the head keeping an end of the band (where it meets a core, or a
    room it must keep a wall with): (the order with the head first or last, the shares) with the
    rooms at their planned areas, and with the head's end as long as its width (a square of it
    then reaches into the band)."""
    area = float(band.sum()) * cell * cell
    depth = int(band.any(axis=1).sum()) * cell
    out: list[tuple[tuple[tuple[str, ...], ...], dict[str, float]]] = []
    for end in sorted({area - sum(targets[m] for m in members), head_width * depth}):
        shares = area_shares(area - end, members, least, targets) if end > EPS else None
        if shares is not None:
            shares[head] = end
            out += [(((head, *order[0]),), shares) for order in orders]
            out += [(((*order[0], head),), shares) for order in orders]
    return out


def _orders(group: list[str], along: dict[str, float], every: int) -> list[tuple[str, ...]]:
    """The orders of ``group`` along its band tried: every order of up to ``every`` rooms, else
    the order they lie in now and its reverse."""
    if len(group) <= every:
        return list(itertools.permutations(group))
    natural = sorted(group, key=lambda m: (along[m], m))
    return [tuple(natural), tuple(reversed(natural))]


def _bands(
    view: np.ndarray, rows: np.ndarray, groups: list[list[str]], along: dict[str, float],
    least: dict[str, float], targets: dict[str, float], width: dict[str, float], firm: dict[str, float],
    span: float, cell: float,
) -> Iterable[tuple[list[np.ndarray], list[tuple[tuple[str, ...], ...]]]]:
    """(the cells of each group's band, the orders of the rooms in them to try) of each choice
    of depths for ``groups``' rows: the first along the top rows of ``view``, the second (if any)
    along its bottom rows. A band is as deep as its rooms' planned areas or their minimums need
    over ``span`` (or a row more) or as its widest room's width asks; bands that meet or leave
    the head no row are skipped, and so are bands too shallow or too short for the ``firm``
    widths of their rooms (those at their width now, which must stay so): the rows they would
    lay out are refused anyway, and most of the bands tried are such."""
    options = []
    for group in groups:
        need = int(np.ceil(sum(targets[m] for m in group) / span / cell - 1e-6))
        # or as their minimums need (and a row more: whole columns round a room's share down),
        # where the head needs the rest for its own minimum
        tight = int(np.ceil(sum(least[m] for m in group) / span / cell - 1e-6))
        deep = int(np.ceil(max(width[m] for m in group) / cell - 1e-6))
        options.append(sorted({need, need + 1, tight, tight + 1, deep}))
    # two rows of rooms keep the orders few: both sides' orders are tried together
    every = ALL_ORDERS if len(groups) == 1 else 2
    orders = list(itertools.product(*(_orders(g, along, every) for g in groups)))
    # cells across and along that each group's rooms must have: every room a column at least
    deepest = [int(np.ceil(max(firm[m] for m in g) / cell - 1e-6)) for g in groups]
    columns = [sum(max(1, int(np.ceil(firm[m] / cell - 1e-6))) for m in g) for g in groups]
    for depths in itertools.product(*options):
        if any(d < max(1, low) for d, low in zip(depths, deepest)) or sum(depths) >= len(rows):
            continue
        top = np.zeros_like(view)
        top[rows[0]:rows[0] + depths[0]] = view[rows[0]:rows[0] + depths[0]]
        parts = [top]
        if len(depths) > 1:
            bottom = np.zeros_like(view)
            bottom[rows[-1] + 1 - depths[1]:rows[-1] + 1] = view[rows[-1] + 1 - depths[1]:rows[-1] + 1]
            parts.append(bottom)
        if any(int(part.any(axis=0).sum()) < need for part, need in zip(parts, columns)):
            continue
        yield parts, orders
