"""Rooms merged into a neighbour: the last step for a floor still too tight for a room (issue 14).

A floor whose layout leaves a room below its minimum area or without a usable square is first
laid out again without the rooms it can spare (:func:`mansion.building.steps.leave_out`). What
that cannot mend (floors that carry walls are never laid out again; a layout laid out again may be
refused; the rooms may be ones a floor cannot leave out) an architect mends by merging: the room
becomes part of the room next to it (a program that does not fit "drops, merges or moves rooms,
never shrinks a room below its minimum", issue 14). Examples from the offline hundred: a toilet
lobby of 2.2 m² becomes part of the concourse its WCs now open onto; a 6 m² private office
becomes part of the open office it was cut from; two small wards become one ward; a WC becomes
part of the accessible toilet beside it, which then holds a usable square.

Two rooms merge only when

- one of them (the room that goes) can go: it is neither the floor's hub nor a core; circulation
  merges only with circulation (a toilet lobby becomes part of a corridor, a ward never does);
  of two rooms of different types, the one that goes is the smaller or has the smaller minimum
  area in the design table (a WC goes into an accessible toilet, a ward never into a nurse
  station), both are sanitary or neither is (a bathroom never becomes part of a bedroom), and
  unless both are circulation the one that goes is not the last of its type in the region it
  was cut from (a flat keeps its bathroom where the floor has one per flat), except a home's
  dining room, which opens into its kitchen or living room, the merged room serving as both
  (:data:`OPEN_PLAN`: a townhouse's dining room 2 m wide becomes a kitchen-diner); a room that
  comes with a bathroom of its own (a ward, a guest room) keeps it; a room the description asked
  for never goes;
- they are close in the cut tree: siblings cut from one region, or a room and the region it was
  cut from, which then takes it (never a region into a room cut from it, a ward into its
  ensuite, but for a dining room into the kitchen cut from it, its only room), so a merge never
  joins two flats or two wings; on a floor whose walls carry the floor
  above (or stand on the floor below) both sit in one first-round region, so no carried wall
  moves;
- they share a door's width of wall, and the merged room, judged as the room that stays, is no
  worse than the better of the two: it has none of ``mansion eval realism``'s defects (elongated,
  a sliver, below its clear width, no usable square) that either of them lacked.

Of the merges allowed, a room of the same type is preferred (two small wards become one), then
the region the room was cut from (a private office into its open office), then any sibling, and
among those the smallest merged room.

The room that stays keeps its id and type; the other's doors and rooms (a lobby's WCs) pass to
it, so every door of the floor still has its wall. A room with a bathroom of its own takes it
along (a ward merged into the ward beside it: its ensuite becomes part of the room too, and the
merged ward keeps one ensuite, its own). Each merge is recorded in the floor's ``relaxations``.

A room no merge takes is dropped where the program can do without it (:func:`_may_drop`): its floor
goes to a neighbour, which keeps its own type (a 7 m² meeting room, the last of its bay but not
of the floor, becomes part of its open office: "meeting_room_3 dropped, its floor given to
bay_3"; a flat's 4 m² second bedroom becomes part of its living room). A room a home needs goes
only where its flat keeps another of its kind, never its only bedroom, kitchen or bathroom; the
floor never goes to circulation (a corridor is planned, not what is left over) nor to a smaller
kind of room (a meeting room never makes a phone booth its size). The same cut-tree, region and
shape rules hold as for a merge.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable

import numpy as np
from shapely.geometry import Polygon
from shapely.ops import unary_union

from mansion import _core
from mansion.building.load_bearing import cut_parents, first_round_groups
from mansion.models.graph import RoomEdge, RoomGraph, RoomNode
from mansion.models.layout import Adjacency, FloorLayout, LabelGrid, LayoutRoom
from mansion.models.room_design import ELONGATED_ASPECT, SANITARY_TYPES, design_key, needed_width, room_design
from mansion.models.room_shape import EPS, SHARE_EPS, TOLERANCE, box_aspect, fits_square, mostly_narrower

__all__ = [
    "DOOR_WIDTH", "USABLE_SIDE", "block_side", "grid_adjacencies", "mask_defects", "merge_unfit_rooms",
    "rooms_from_grid", "shape_defects", "square_cover",
]

#: Shared wall (m) two rooms need to be merged: a door's width, as ``mansion eval realism`` asks
#: of two rooms it counts as connected.
DOOR_WIDTH = 0.9
#: Side of the square a usable room holds, metres: ``mansion eval realism``'s "no 1 m square"
#: (a square a hair over 1 m, three cells of the 0.5 m grid).
USABLE_SIDE = 1.0


def grid_adjacencies(labels: np.ndarray, ids: list[str], cell: float) -> list[Adjacency]:
    """Every pair of rooms of a label grid (row 0 at the bottom, negative: no room) sharing wall:
    total and longest straight contact in metres, measured by the core as it measures a solved
    layout's, in its order."""
    return [
        Adjacency(a=ids[a], b=ids[b], contact=t * cell, longest=m * cell)
        for a, b, t, m in _core.adjacencies(labels.astype(np.int32))
    ]


#: :func:`shape_defects` of the shapes measured, by the shape object (kept with the entry, so its
#: id is not reused while the entry stands), at most this many (then the cache starts afresh):
#: the recuts measure the same room and the room that gives for each donor and each room
#: beside, most of them drawn once (:func:`mansion.building.outlines.outline`).
DEFECTS_CACHE = 1 << 12
_DEFECTS: dict[tuple[int, str, str | None], tuple[Polygon, frozenset[str]]] = {}


def shape_defects(shape: Polygon, room_type: str, building_type: str | None) -> set[str]:
    """``mansion eval realism``'s defects of one room's shape: "elongated" (not circulation),
    "sliver", "narrow" (below its clear width: circulation's its building's corridor width, else
    the design table's, :func:`~mansion.models.room_design.needed_width`) and "unusable" (no
    usable square). Shapely's shapes do not change, so each is measured once (a new set each
    call: callers may change theirs)."""
    key = (id(shape), room_type, building_type)
    found = _DEFECTS.get(key)
    if found is None or found[0] is not shape:
        if len(_DEFECTS) >= DEFECTS_CACHE:
            _DEFECTS.clear()
        found = _DEFECTS[key] = (shape, frozenset(_shape_defects(shape, room_type, building_type)))
    return set(found[1])


def _shape_defects(shape: Polygon, room_type: str, building_type: str | None) -> set[str]:
    """:func:`shape_defects`, measured."""
    design = room_design(room_type)
    out: set[str] = set()
    if not design.circulation and box_aspect(shape) > ELONGATED_ASPECT:
        out.add("elongated")
    if mostly_narrower(shape, USABLE_SIDE, inclusive=True):
        out.add("sliver")
    need = needed_width(room_type, building_type)
    if mostly_narrower(shape, need):
        out.add("narrow")
    if not fits_square(shape, USABLE_SIDE, inclusive=True):
        out.add("unusable")
    return out


def mask_defects(mask: np.ndarray, room_type: str, building_type: str | None, cell: float) -> set[str]:
    """:func:`shape_defects` of the room whose cells ``mask`` holds (one piece; a grid of
    ``cell``-metre cells), counted on the grid: the same sets, many times faster than buffering
    its outline (each share is of cells, see :func:`square_cover`, and the elongation is the
    cells' box). Counted by the core in one pass (the mends judge tens of thousands of
    candidates' cells on the hundred; a cache of the counts by the cells' shape cost more than
    the core's count)."""
    need = needed_width(room_type, building_type)
    h, w, total, (usable, clear) = _core.box_cover(
        mask, [block_side(USABLE_SIDE + 2 * EPS, cell), block_side(need - 2 * EPS, cell)],
    )
    out: set[str] = set()
    if not room_design(room_type).circulation and max(h, w) > ELONGATED_ASPECT * min(h, w):
        out.add("elongated")
    # inclusive: parts exactly 1 m wide are slivers
    if total - usable > TOLERANCE * total + SHARE_EPS * total:
        out.add("sliver")
    if total - clear > TOLERANCE * total + SHARE_EPS * total:
        out.add("narrow")
    if usable == 0:
        out.add("unusable")
    return out


def square_cover(mask: np.ndarray, width: float, cell: float) -> np.ndarray:
    """The cells of ``mask`` (a grid of ``cell``-metre cells) that some square ``width`` metres
    wide lying inside it covers. A square a hair narrower (or wider) than a width fits wherever an
    aligned block of that many cells, rounded up, fits, and the squares of a union of cells cover
    exactly the blocks that do (a square off the grid spans whole cells of the shape on every row
    and column it touches)."""
    h, w = mask.shape
    m = block_side(width, cell)
    if m <= 1:
        return mask.copy()
    if m > h or m > w:
        return np.zeros_like(mask)
    # prefix sums of the cells: a block of m × m lies inside when it holds m * m of them
    inside = np.zeros((h + 1, w + 1), dtype=np.int64)
    inside[1:, 1:] = np.cumsum(np.cumsum(mask, axis=0), axis=1)
    fits = (inside[m:, m:] - inside[:-m, m:] - inside[m:, :-m] + inside[:-m, :-m]) == m * m
    # each fitting block stamped onto a difference array: its prefix sums count the blocks
    # covering each cell
    stamp = np.zeros((h + 1, w + 1), dtype=np.int64)
    bh, bw = fits.shape
    stamp[:bh, :bw] += fits
    stamp[m:m + bh, :bw] -= fits
    stamp[:bh, m:m + bw] -= fits
    stamp[m:m + bh, m:m + bw] += fits
    return np.cumsum(np.cumsum(stamp, axis=0), axis=1)[:h, :w] > 0


def block_side(width: float, cell: float) -> int:
    """Cells a side of the block a square ``width`` metres wide needs (:func:`square_cover`)."""
    return int(np.ceil(width / cell - 1e-9))


def rooms_from_grid(
    labels: np.ndarray, grid: LabelGrid, old: dict[str, LayoutRoom], targets: dict[str, float]
) -> list[LayoutRoom]:
    """The layout's rooms drawn again from ``labels``, as the core draws them (the largest piece
    of each label, its area from its cells, its centroid the mean of its cells' centres)."""
    (ox, oy), s = grid.origin, grid.cell_size
    pieces: dict[int, tuple[float, list, list]] = {}
    for k, ring, holes in _core.vectorise(labels.astype(np.int32)):
        area = abs(Polygon(ring).area)
        if k not in pieces or area > pieces[k][0]:
            pieces[k] = (area, ring, holes)
    # the cells' centres summed in the core's order (row by row, left to right) so a room the
    # merge leaves alone keeps its centroid to the last bit
    # (by the core, which adds them in the same order)
    count: dict[int, int] = {}
    sums: dict[int, tuple[float, float]] = {}
    for k, n, sx, sy in _core.cell_sums(labels.astype(np.int32), float(ox), float(oy), float(s)):
        count[k], sums[k] = n, (sx, sy)
    rooms: list[LayoutRoom] = []
    for k, rid in enumerate(grid.ids):
        if k not in pieces:
            continue
        n = count[k]
        _, ring, holes = pieces[k]
        cx, cy = sums[k][0] / n, sums[k][1] / n
        room = old[rid]
        rooms.append(room.model_copy(update={
            "polygon": [(ox + x * s, oy + y * s) for x, y in ring],
            "holes": [[(ox + x * s, oy + y * s) for x, y in h] for h in holes],
            "area": n * s * s,
            "target_area": targets.get(rid, room.target_area),
            "centroid": (cx, cy),
        }))
    return rooms


def _merged_graph(graph: RoomGraph, gone: str, stays: str) -> RoomGraph:
    """``graph`` with room ``gone`` merged into ``stays``: its relations pass to ``stays`` (an
    access relation wins over an adjacency to the same room)."""
    edges: dict[frozenset[str], RoomEdge] = {}
    for e in graph.edges:
        a, b = (stays if e.source == gone else e.source), (stays if e.target == gone else e.target)
        key = frozenset((a, b))
        if a == b or (key in edges and edges[key].kind == "access"):
            continue
        edges[key] = RoomEdge(source=a, target=b, kind=e.kind)
    nodes: list[RoomNode] = []
    for n in graph.nodes:
        if n.id == gone:
            continue
        if n.id == stays:
            n = n.model_copy(update={"area": n.area + next(m.area for m in graph.nodes if m.id == gone)})
        nodes.append(n)
    return RoomGraph(
        nodes=nodes,
        edges=list(edges.values()),
    )


def _may_go(
    gone: RoomNode,
    stays: RoomNode,
    graph: RoomGraph,
    parent: dict[str, str],
    count: dict[tuple[str | None, str], int],
    rooms: dict[str, LayoutRoom],
    keep: frozenset[str],
) -> bool:
    """Whether ``gone`` may become part of ``stays`` (the rules of the module's docstring that
    concern the two rooms' kinds)."""
    if gone.id == graph.hub.id or gone.is_core or stays.is_core:
        return False
    circulation = room_design(gone.room_type).circulation
    if circulation != room_design(stays.room_type).circulation:
        return False
    if parent.get(gone.id) == stays.id and room_design(stays.room_type).own_bathroom:
        return False
    if gone.id in keep:
        return False
    if gone.room_type == stays.room_type or open_plan(gone, stays):
        return True
    if (design_key(gone.room_type) in SANITARY_TYPES) != (design_key(stays.room_type) in SANITARY_TYPES):
        return False
    # of two types, the room that goes is the smaller or the less demanding one (a WC into the
    # accessible toilet beside it; never a ward into a nurse station too small for its minimum)
    smaller = rooms[gone.id].area <= rooms[stays.id].area
    if not smaller and room_design(gone.room_type).min_area > room_design(stays.room_type).min_area:
        return False
    # circulation taken into circulation still serves: nothing of the program is lost
    return circulation or count.get((parent.get(gone.id), gone.room_type), 0) >= 2


#: A home's rooms that may open into another, the merged room serving as both: a dining room
#: into its kitchen (a kitchen-diner) or its living room (a living-dining room). Nothing of the
#: program is lost, so the only dining room of a flat may merge so where no other room may.
OPEN_PLAN: dict[str, frozenset[str]] = {"dining_room": frozenset({"kitchen", "living_room"})}


def open_plan(gone: RoomNode, stays: RoomNode) -> bool:
    """Whether ``gone`` may open into ``stays`` (:data:`OPEN_PLAN`)."""
    return design_key(stays.room_type) in OPEN_PLAN.get(design_key(gone.room_type) or "", frozenset())


#: Kinds of room a home cannot do without: a room of one of these is dropped only where the
#: region it was cut from (a flat) keeps another of its kind (a flat with two bedrooms may lose
#: its second; a sanitary room's kind is its own type: the only accessible toilet stays).
HOME_KINDS: dict[str, str] = {
    **{t: "sleeping" for t in (
        "master_bedroom", "master_room", "bedroom", "common_room", "children_room", "guest_bedroom",
    )},
    **{t: "kitchen" for t in ("kitchen", "kitchenette")},
    **{t: "living" for t in ("living_room", "studio_room", "unit_living", "family_room")},
    **{t: t for t in SANITARY_TYPES},
}


def home_kind(room_type: str) -> str | None:
    """The kind of room a home cannot do without that ``room_type`` is (:data:`HOME_KINDS`), or
    None."""
    key = design_key(room_type)
    return None if key is None else HOME_KINDS.get(key)


def _may_drop(
    gone: RoomNode,
    stays: RoomNode,
    graph: RoomGraph,
    parent: dict[str, str],
    keep: frozenset[str],
) -> bool:
    """Whether ``gone``, which no merge takes, may be dropped from the floor and its floor given
    to ``stays``, which keeps its own type: a program that does not fit "drops, merges or moves
    rooms" (issue 14). Only a room that is neither the hub, a core, circulation nor a room the
    description asked for; a room a home needs (:data:`HOME_KINDS`) only where its region (its
    flat) keeps another of its kind, any other only where the floor keeps another of its type
    (as :func:`mansion.building.steps.leave_out` asks); and its floor never goes to a core, to
    circulation (a corridor is planned, not what is left over), to a smaller kind of room (the
    table's minimum area: a meeting room's floor never makes a phone booth its size) nor across
    the sanitary line (a dropped bedroom never enlarges a bathroom)."""
    return may_spare(gone, graph, parent, keep) and may_receive(gone, stays)


def may_receive(gone: RoomNode, stays: RoomNode) -> bool:
    """Whether ``stays`` may take floor of a dropped room ``gone`` (:func:`_may_drop`'s rules on
    the room that takes it): not a core nor circulation, on the same side of the sanitary line,
    and at least as large a kind of room."""
    if stays.is_core:
        return False
    # a corridor is planned, never what is left over (issue 14)
    if room_design(stays.room_type).circulation:
        return False
    if (design_key(gone.room_type) in SANITARY_TYPES) != (design_key(stays.room_type) in SANITARY_TYPES):
        return False
    # to a room at least as large a kind: a meeting room's floor to the open office, never to a
    # phone booth that would become a room of its size
    return room_design(stays.room_type).min_area >= room_design(gone.room_type).min_area


def may_spare(
    gone: RoomNode,
    graph: RoomGraph,
    parent: dict[str, str],
    keep: frozenset[str],
    optional: frozenset[str] = frozenset(),
) -> bool:
    """Whether the program can do without ``gone`` (:func:`_may_drop`'s rules on the room that
    goes): not the hub, a core, circulation nor a room the description asked for; a room a home
    needs only where its flat keeps another of its kind, any other only where the floor keeps
    another of its type, but for the rooms of ``optional`` (ids of rooms the floor's template
    plans only where they fit: a school's art room, a kindergarten's staff office), which the
    program can always do without."""
    if gone.id == graph.hub.id or gone.is_core or gone.id in keep:
        return False
    if room_design(gone.room_type).circulation:
        return False
    if gone.id in optional:
        return True
    kind = home_kind(gone.room_type)
    if kind is None:
        return sum(n.room_type == gone.room_type for n in graph.nodes) >= 2
    up = parent.get(gone.id)
    return sum(
        home_kind(n.room_type) == kind for n in graph.nodes if n.id != gone.id and parent.get(n.id) == up
    ) >= 1


def merge_unfit_rooms(
    layout: FloorLayout,
    graph: RoomGraph,
    unfit: Callable[[FloorLayout, RoomGraph], dict[str, str]],
    building_type: str | None = None,
    same_region: bool = False,
    keep: Iterable[str] = (),
    cure: str | None = None,
) -> tuple[FloorLayout, RoomGraph, list[str]]:
    """Merge each room ``unfit`` names (id → why) into a neighbour, or a neighbour into it, where
    the module's rules allow; the smallest unfit room first, each time the merge whose merged room
    is smallest. ``same_region``: only rooms of one first-round region merge (floors that carry
    walls). ``keep``: rooms that may take others in but never go (the rooms a description asked
    for). Returns the layout, the graph and a relaxation note per merge."""
    kept = frozenset(keep)
    notes: list[str] = []
    tried: set[str] = set()
    while True:
        bad = {r: why for r, why in unfit(layout, graph).items() if r not in tried}
        if not bad:
            return layout, graph, notes
        rooms = {r.id: r for r in layout.rooms}
        room = min(bad, key=lambda r: (rooms[r].area, r))
        tried.add(room)
        found = _best_merge(layout, graph, room, building_type, same_region, kept, cure=cure)
        dropped = found is None
        if dropped:
            found = _best_merge(layout, graph, room, building_type, same_region, kept, drop=True, cure=cure)
        if found is None:
            continue
        gone, stays = found
        for rid in gone:
            layout = _merged_layout(layout, rid, stays)
            graph = _merged_graph(graph, rid, stays)
        also = f" with {', '.join(gone[1:])}" if len(gone) > 1 else ""
        if dropped:
            notes.append(f"{gone[0]} dropped{also}, its floor given to {stays} ({room} {bad[room]})")
        else:
            notes.append(f"{gone[0]} merged into {stays}{also} ({room} {bad[room]})")
        tried.discard(stays)


def _best_merge(
    layout: FloorLayout,
    graph: RoomGraph,
    room: str,
    building_type: str | None,
    same_region: bool,
    keep: frozenset[str],
    drop: bool = False,
    cure: str | None = None,
) -> tuple[list[str], str] | None:
    """(the rooms that go, the room that stays) of the best merge for ``room``, or None when no
    merge passes the rules. A room with a bathroom of its own takes it along: the merged room
    keeps one bathroom, its own. ``drop``: ``room`` is dropped instead (:func:`_may_drop`), its
    floor given to a neighbour of any kind that keeps its own."""
    nodes = {n.id: n for n in graph.nodes}
    parent = cut_parents(graph)
    region = first_round_groups(graph) if same_region else {}
    # rooms of each type per region they were cut from: a flat keeps its only bathroom even
    # where the floor has one per flat
    count: dict[tuple[str | None, str], int] = {}
    for n in graph.nodes:
        group = (parent.get(n.id), n.room_type)
        count[group] = count.get(group, 0) + 1
    children: dict[str, list[str]] = {}
    for kid, up in parent.items():
        children.setdefault(up, []).append(kid)
    rooms = {r.id: r for r in layout.rooms}
    best: tuple[int, float, bool, list[str], str] | None = None
    for adj in layout.adjacencies:
        if room not in (adj.a, adj.b) or adj.longest < DOOR_WIDTH - EPS:
            continue
        other = adj.b if adj.a == room else adj.a
        if room not in nodes or other not in nodes:
            continue
        if same_region and region.get(room) != region.get(other):
            continue
        for gone, stays in ((room, other),) if drop else ((room, other), (other, room)):
            # siblings cut from one region, or a room into the region it was cut from (never a
            # region into a room cut from it: a ward into its ensuite; but a dining room into
            # the kitchen cut from it, its only room, opens into it)
            if parent.get(gone) not in (parent.get(stays), stays) and not (
                open_plan(nodes[gone], nodes[stays]) and children.get(gone) == [stays]
            ):
                continue
            if drop:
                if not _may_drop(nodes[gone], nodes[stays], graph, parent, keep):
                    continue
            elif not _may_go(nodes[gone], nodes[stays], graph, parent, count, rooms, keep):
                continue
            held, lost = rooms[stays], rooms[gone]
            own = children.get(gone, []) if room_design(nodes[gone].room_type).own_bathroom else []
            if any(r not in rooms or children.get(r) or r in keep for r in own):
                continue
            # a dropped room takes no region with it (a lobby's WCs, a flat's rooms)
            if drop and any(r not in own for r in children.get(gone, [])):
                continue
            union = unary_union([Polygon(r.polygon, r.holes) for r in (held, lost, *(rooms[o] for o in own))])
            if union.geom_type != "Polygon":
                continue
            # judged as the room that stays, against the better of the two: a defect both had
            # may remain, none either lacked may appear
            kind = held.room_type
            after = shape_defects(union, kind, building_type)
            if cure is not None and cure in after:
                continue
            if after and not after <= (
                shape_defects(Polygon(held.polygon, held.holes), kind, building_type)
                & shape_defects(Polygon(lost.polygon, lost.holes), kind, building_type)
            ):
                continue
            # a room of the same type first (two small wards become one), then the region it
            # was cut from (a private office into its open office), then any sibling; the
            # smallest merged room; the unfit room the one that goes, where both ways pass
            rank = 0 if nodes[gone].room_type == kind else 1 if parent.get(gone) == stays else 2
            key = (rank, union.area, gone != room, [gone, *own], stays)
            if best is None or key < best:
                best = key
    if best is None:
        return None
    return best[3], best[4]


def _merged_layout(layout: FloorLayout, gone: str, stays: str) -> FloorLayout:
    """``layout`` with room ``gone``'s cells given to ``stays``, drawn again."""
    rooms = {r.id: r for r in layout.rooms}
    ids = [rid for rid in layout.grid.ids if rid != gone]
    # every label after the room that goes moves down by one; its cells take the other's label
    labels = layout.grid.array()
    k_gone, k_stays = layout.grid.ids.index(gone), layout.grid.ids.index(stays)
    relabelled = np.where(labels == k_gone, k_stays, labels)
    relabelled = np.where(relabelled > k_gone, relabelled - 1, relabelled).astype(np.int32)
    grid = layout.grid.relabelled(relabelled, ids=ids)
    targets = {stays: rooms[stays].target_area + rooms[gone].target_area}
    return layout.model_copy(update={
        "rooms": rooms_from_grid(relabelled, grid, rooms, targets),
        "grid": grid,
        "adjacencies": grid_adjacencies(relabelled, ids, grid.cell_size),
    })
