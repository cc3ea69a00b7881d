"""The steps of the paper's global multi-floor generation that both drivers share: the offline
loop of :func:`mansion.building.generate.generate_building` and the LangGraph pipeline of
:mod:`mansion.building.graph` (SolveFloorLayout with its retry ladder, floor copies, the
final checks, per-purpose seeds). Neither driver is imported here, so the two never import each
other.

A floor whose solve fails is retried with other solver seeds, then with its ``adjacent`` edges
dropped, then (only for carried walls) without the carried walls, then with every width rule
lowered to :data:`RELAXED_CLEAR_WIDTH` (:data:`RELAXED_ATTEMPTS` seeds), then without any width
rule; each relaxation is recorded on the floor. The first attempt keeps every width rule; from the
second on, a cut round that no candidate passes under width rules wider than 1.0 m is cut again,
by the solver, with that round's rules lowered (recorded on the floor). When every attempt fails,
:class:`InfeasibleLayoutError` names the floor.

A floor laid out with rooms below their minimum area or without a usable 1 m square is too tight
for them: rooms it can do without (one of several wards, with its ensuite) are left out and the
floor is laid out again (:func:`leave_out`), and with them, of each type, the smallest room the
layout left below its clear width (:data:`SPARE_NARROW`; never a room the description asked for);
a floor with rooms below their clear width alone is laid out again without the smallest of each
type of them, under one seed (:data:`RESOLVE_NARROW`); a floor with rooms too small for it that
it can spare none of is laid out again with all of them under seeds of its own
(:data:`RESOLVE_SAME_SEEDS`). The new layout is kept when it leaves no
more rooms unfit (nor without a usable square), fewer
unfit or below their width in all, and no more elongated rooms or slivers (up to
:data:`RESOLVE_SEEDS` layouts, each under its own seed, until one is), and each room left out is
recorded on the
floor ("ward_5 left out (with ward_5_ensuite): laid out at 7.5 m², below its 14.5 m² minimum";
issue 14). What that cannot mend (floors that carry walls, layouts refused, rooms the floor
cannot spare) is first cut again as a rectangle inside the region it was cut from
(:mod:`mansion.building.recut`: a 2.2 m² bathroom inside its flat), then pushes its walls out
into its neighbours as far as its minimum needs (:func:`mansion.building.sides.enlarge_rooms`,
again once the width mends are done), then merged into a neighbour
where an architect would, or dropped where the program can do without it
(:mod:`mansion.building.merge`: a toilet lobby into its corridor, a small ward into the ward
beside it, a flat's second bedroom into its living room), each recorded. Then rooms below their
clear width are cut again as rectangles where a neighbour can give them floor
(:func:`mansion.building.recut.recut_narrow_rooms`), the strips of those still below it are
handed to the rooms beside them (:func:`mansion.building.recut.hand_off_strips`); then, in the
order of :data:`NARROW_MENDS`, a room still below its width pushes its walls out into the rooms
beside it or slides them over (:mod:`mansion.building.sides`), a region and the rooms cut from
it, one of them still below its width, are laid out again in a row along one side or in two
along opposite sides (:mod:`mansion.building.families`: an open office curled round its meeting
room; a hub moves the rooms it closes round to a side), a room below its width only by a pocket beside a core
keeps it as a store (:mod:`mansion.building.stores`), a room below its width by arms that carry
its doors keeps them as halls (:mod:`mansion.building.halls`: a play hall's arm to its sleep
room becomes a corridor), what is still below its width merges like a room too small where the
merged room comes out at its width (:data:`MERGE_NARROW`: two wards 2.5 m wide become one), and
a region too tight for its rooms is laid out as a row without the smallest it can drop; each
recorded. Then parts of rooms one cell wide are widened from a neighbour
(:func:`mansion.building.recut.widen_passages`). Last, a room still below its minimums is
dissolved where the program can spare it (:mod:`mansion.building.dissolve`), one still below its
width is cut again with a room beside it by any split (:data:`LAST_PAIRS`), and a spare room no
neighbour takes becomes a store (:data:`SPARE_STORES`), each program change recorded.
"""

from __future__ import annotations

import hashlib
import math
from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Any

from mansion.building.banks import bank_graph, bank_layout
from mansion.building.checks import check_building
from mansion.building.load_bearing import (
    SkeletonSeedPlanner,
    carry_walls,
    cut_parents,
    first_round_groups,
    first_round_regions,
    first_round_walls,
    retarget_first_round,
)
from mansion.building.dissolve import dissolve_unfit_rooms
from mansion.building.families import relay_families
from mansion.building.halls import hall_arms
from mansion.building.merge import USABLE_SIDE, merge_unfit_rooms
from mansion.building.outlines import outline, shape_measure
from mansion.building.pairs import recut_pairs
from mansion.building.recut import (
    _least, hand_off_strips, recut_narrow_rooms, recut_unfit_rooms, relay_narrow_clusters, widen_passages,
)
from mansion.building.regions import hub_takes_arms
from mansion.building.sides import enlarge_rooms, widen_sides
from mansion.building.stores import store_pockets, store_spare_rooms
from mansion.exceptions import InfeasibleLayoutError, InvalidInputError
from mansion.floorplan import EnergyWeights, SeedPlanner, SolverSettings, solve_floor
from mansion.models import Core, FloorLayout, Footprint, RoomGraph
from mansion.models.layout import LayoutRoom
from mansion.models.building import Building, BuildingProgram, Floor, Palette, PositionWord, RoomCard
from mansion.models.room_design import ELONGATED_ASPECT, needed_width, room_design
from mansion.models.room_shape import box_aspect, mostly_narrower
from mansion.planning.program import floor_template

if TYPE_CHECKING:
    from mansion.floorplan.text_seeds import TextSeedPlanner

__all__ = [
    "ATTEMPTS",
    "MIN_CLEAR_WIDTH",
    "RELAXED_ATTEMPTS",
    "RELAXED_CLEAR_WIDTH",
    "RESEEDS",
    "Progress",
    "copy_floor",
    "derived_seed",
    "finish_building",
    "floor_footprint",
    "floor_settings",
    "generated_weights",
    "solve_building_floor",
    "solver_options",
    "leave_out",
    "mend_narrow",
    "misshapen",
    "narrow_rooms",
    "smallest_narrow",
    "unfit_rooms",
]

#: Solver attempts per floor: two plain seeds, then without adjacent edges, then without walls,
#: then :data:`RELAXED_ATTEMPTS` seeds with the widths lowered to :data:`RELAXED_CLEAR_WIDTH`,
#: then without width rules.
ATTEMPTS = 10
#: Seeds tried at :data:`RELAXED_CLEAR_WIDTH` before width rules are dropped: a floor laid out
#: without any rule may keep a one-cell (0.5 m) neck no agent passes, so the rule the agent needs
#: is given up only after several seeds. Each 1,000-building dataset run had one such failure:
#: an apartment block's entrance hall cut the ground floor's cores off (three seeds fixed it),
#: then another's first floor needed a fifth seed at 1.0 m (building 654 of seed 0).
RELAXED_ATTEMPTS = 5

#: Narrowest part any room (corridors and the hub included) may have, in metres: three cells of
#: the 0.5 m grid. Two cells (1.0 m) let an agent of radius 0.25–0.3 m through, but a room 1.0 m
#: wide holds no usable 1 m square and counts as a sliver (issue 14); measured on seeds 0–27 with
#: the planners' room widths capped here: slivers 24.7 % at 1.0 m, 2.1 % at 1.5 m.
MIN_CLEAR_WIDTH = 1.5

#: The width every rule falls to when a floor cannot be laid out at :data:`MIN_CLEAR_WIDTH`: still
#: wide enough for the agent.
RELAXED_CLEAR_WIDTH = 1.0

#: Re-seedings per cut round of a generated floor (``SolverSettings.reseeds``): a child that a
#: round leaves below 80 % of its target, while the parent keeps a piece of leftover where no
#: child was seeded, is grown again from that piece. The offline planner's seeds crowd some
#: children among others that reach their targets first (a ward wing laid at 65 % of its target
#: beside a corridor at three times its own); see the README's realism section for the figures.
RESEEDS = 2

#: Lay out a round whose parent keeps the leftover (a corridor, a ward wing, a hall) as the
#: corridor typology too (``SolverSettings.slabs``): the parent one straight corridor, or two
#: joined at one end, across its region, its rooms rectangles side by side along them, competing
#: with the grown candidates by energy. Measured on the offline hundred (seeds 0–99): rooms below
#: their type's minimum width 15.4 % -> 12.7 %, below their minimum area 2.2 % -> 2.0 % (seeds
#: 100–199: 14.9 -> 13.8 %, 2.8 -> 2.5 %); see the README's realism section for the time.
SLABS = True

#: Retries each cut round of a generated floor first spends with its rooms held to their full
#: clear widths and its zones to the widest of their rooms' (``SolverSettings.wide_retries``): a
#: classroom 5.4 m, a ward 3.2 m, a hospital corridor 2.4 m, where the rules kept otherwise stop
#: at 1.5-2.0 m. Measured on the offline hundreds, each seed laid out with and without, process
#: time (seeds 0-99 / 100-199): rooms below their width 273 -> 253 / 290 -> 235, below their area
#: 15 -> 16 / 30 -> 26, slivers 4 -> 3 / 6 -> 3, elongated 43 -> 44 / 43 -> 33, time 0.92x /
#: 0.97x. Two such retries: 253 / 229 rooms below their width, but 19 below area on the first
#: hundred; see the README's realism section.
WIDE_RETRIES = 1

Progress = Callable[[str, int, int], None]


def derived_seed(seed: int, *parts: object) -> int:
    """A u64 seed for one purpose, stable across Python versions and runs (unlike hash())."""
    text = ":".join(str(p) for p in (seed, *parts)).encode()
    return int.from_bytes(hashlib.blake2b(text, digest_size=8).digest(), "little")


def _room_cards(graph: RoomGraph, notes: dict[str, str]) -> list[RoomCard]:
    return [
        RoomCard(
            id=n.id, room_type=n.room_type, floor_material=n.floor_material or "",
            wall_material=n.wall_material or "", open_relation=n.open_relation,
            notes=notes.get(n.id, ""),
        )
        for n in graph.nodes
    ]


def generated_weights() -> EnergyWeights:
    """The energy of generated floors: :meth:`EnergyWeights.paper` with the aspect term at 10.

    Measured over the offline hundred (seeds 0–99; rooms other than cores, hubs, corridors, halls,
    lobbies and balconies): rooms whose bounding box is longer than 3 : 1 fall from 10.9 % (no
    shape term) to 8.2 % (aspect 2), 6.0 % (aspect 10) and 5.1 % (aspect 30), while the mean area
    error rises from 18.2 % to 18.3, 18.8 and 19.1 %; the rect term added nothing (rect 3 with
    aspect 10: 6.5 %).
    """
    return EnergyWeights.paper().model_copy(update={"aspect": 10.0})


def solver_options(
    cell_size: float = 0.5,
    retries: int = 10,
    batch: int = 100,
    min_contact: float = 1.0,
    weights: EnergyWeights | None = None,
    min_width: float | None = MIN_CLEAR_WIDTH,
) -> dict[str, Any]:
    """The keyword arguments of :func:`mansion.solve_floor` for a generated building's floors
    (``min_width``: the floor-wide minimum clear width in metres; None: no width rule at all,
    the rooms' own dropped too)."""
    return {
        "cell_size": cell_size, "retries": retries, "batch": batch, "min_contact": min_contact,
        "weights": weights if weights is not None else generated_weights(),
        "settings": floor_settings(cell_size, min_width) if min_width is not None else None,
    }


def _without_adjacent(graph: RoomGraph) -> RoomGraph:
    return RoomGraph(nodes=graph.nodes, edges=[e for e in graph.edges if e.kind == "access"])


def _widths_at_most(graph: RoomGraph, width: float | None) -> RoomGraph:
    """``graph`` with every room's own minimum width lowered to ``width`` (None: removed)."""
    nodes = [
        n if n.min_width is None or (width is not None and n.min_width <= width)
        else n.model_copy(update={"min_width": width})
        for n in graph.nodes
    ]
    return RoomGraph(nodes=nodes, edges=graph.edges)


def floor_settings(cell_size: float, width: float = MIN_CLEAR_WIDTH) -> SolverSettings:
    """The solver settings of generated floors: the floor-wide minimum width (``width`` m,
    :data:`MIN_CLEAR_WIDTH` by default) in cells of ``cell_size``, :data:`RESEEDS`, each round
    but the first rebalanced toward its targets (:data:`REBALANCE_LATER_ONLY`), the corridor
    typology's layouts (:data:`SLABS`), each round's first retry at its rooms' full clear widths
    (:data:`WIDE_RETRIES`) and the repair of rooms left below their design minimums."""
    return SolverSettings(
        min_width=max(1, math.ceil(width / cell_size - 1e-6)), reseeds=RESEEDS, repair=True,
        rebalance=True, rebalance_later_only=REBALANCE_LATER_ONLY, slabs=SLABS,
        wide_retries=WIDE_RETRIES,
    )


def _solve(
    index: int,
    graph: RoomGraph,
    footprint: Footprint,
    planner: SeedPlanner | None,
    seed: int,
    solver: dict[str, Any],
    drop_widths: bool = True,
    only: int | None = None,
    start: int = 0,
) -> tuple[FloorLayout, RoomGraph, Footprint, int, int, list[str]]:
    """The ladder of attempts (the module doc); ``only``: just that rung (0-based); ``start``: the
    rung to climb from."""
    errors = []
    if solver.get("settings") is None:
        graph = _widths_at_most(graph, None)  # no width rules asked for
    # without ``drop_widths`` the rung without width rules is left to a re-planned program
    attempts = ATTEMPTS if drop_widths or solver.get("settings") is None else 4 + RELAXED_ATTEMPTS
    for attempt in range(start, attempts) if only is None else [only]:
        relax: list[str] = []
        g, fp, sp = graph, footprint, planner
        if attempt >= 2 and any(e.kind == "adjacent" for e in graph.edges):
            g = _without_adjacent(g)
            relax.append("adjacent edges dropped")
        if attempt >= 2 and getattr(sp, "reading", None) is not None:
            sp = None  # the description's position words (floorplan.text_seeds) could not be met
            relax.append("position words of the description dropped")
        if attempt >= 3 and footprint.fixed_walls:
            fp = footprint.model_copy(update={"fixed_walls": []})
            sp = None
            relax.append("carried walls dropped")
        options = solver
        if solver.get("settings") is not None and attempt == 0:
            # the first attempt keeps every width rule: a round that cannot meet them fails the
            # attempt, and a new seed often can; later attempts lower a failing round's rules
            options = {**solver, "settings": solver["settings"].model_copy(update={"relax_widths": False})}
        if 4 <= attempt < 4 + RELAXED_ATTEMPTS and solver.get("settings") is not None:
            g = _widths_at_most(g, RELAXED_CLEAR_WIDTH)
            cells = floor_settings(solver.get("cell_size", 0.5), RELAXED_CLEAR_WIDTH).min_width
            options = {**solver, "settings": solver["settings"].model_copy(update={"min_width": cells})}
            relax.append(f"minimum clear widths lowered to {RELAXED_CLEAR_WIDTH:g} m")
        if attempt >= 4 + RELAXED_ATTEMPTS and solver.get("settings") is not None:
            g = _widths_at_most(g, None)
            options = {**solver, "settings": solver["settings"].model_copy(update={"min_width": None})}
            relax.append("minimum clear widths dropped")
        rng_seed = derived_seed(seed, "floor", index, attempt)
        try:
            layout = solve_floor(g, fp, seed_planner=sp, rng_seed=rng_seed, **options)
        except InfeasibleLayoutError as exc:
            errors.append(f"attempt {attempt + 1}: {exc}")
            continue
        relax += [
            f"minimum clear widths lowered to {r.relaxed_width or RELAXED_CLEAR_WIDTH:g} m while cutting {r.parent!r}"
            for r in layout.diagnostics.rounds if r.widths_relaxed
        ]
        return layout, g, fp, rng_seed, attempt + 1, relax
    raise InfeasibleLayoutError(
        f"floor {index} could not be laid out in {attempts} attempts; " + " | ".join(errors[-2:])
    )


#: Whether generated floors leave their first round as cut by the rebalance (``SolverSettings.
#: rebalance_later_only``): the zones keep what the cut gave them, the rooms cut from them are
#: still brought toward their targets. The first round's rebalance moved a zone's rows from the
#: hub one at a time, a sixth of the generation time; without it, on the offline hundreds (seeds
#: 0-99 / 100-199), below width 138 / 116 -> 117 / 91, below area 7 / 14 -> 8 / 4, elongated
#: 27 / 15 -> 22 / 10, for 45 / 65 rooms fewer (left out or merged, recorded) in 0.87 times the
#: process time.
REBALANCE_LATER_ONLY = True

#: A floor laid out again without the rooms it could not fit draws this many times fewer
#: candidates per retry than the first layout. Three until the floors with rooms below their
#: width alone were laid out again too (:data:`RESOLVE_NARROW`); six costs 0.95 times the
#: generation time for the same figures within a few rooms (seeds 0-99 / 100-199: below width
#: 128 -> 130 / 119 -> 113, below area 7 / 13 -> 7 / 14, slivers 1 / 4 -> 2 / 4).
RESOLVE_DIVISOR = 6

#: Layouts tried, each under its own seed, for a floor laid out again without the rooms it could
#: not fit, until one leaves fewer rooms unfit and no more elongated or slivers: the first is
#: often refused for one elongated room (hospital 34: four of its nine floors). Seeds 0-99, one
#: layout -> three: below area 82 -> 73 rooms, below width 12.52 -> 12.39 %; seeds 100-199:
#: below area 106 -> 82, no 1 m square 31 -> 22, slivers 38 -> 29 (README, "Room widths").
RESOLVE_SEEDS = 3


#: Whether a floor laid out again for rooms too small for it also spares, of each type, its
#: smallest room below its clear width (:func:`smallest_narrow`). Measured on the offline
#: hundreds (``mansion eval realism --generate 100``), no slower (0.99 times the process time):
#: seeds 0-99, rooms below their width 280 -> 273, below their area 21 -> 15, slivers 5 -> 4,
#: for 39 rooms fewer (4,406 -> 4,367); seeds 100-199, 299 -> 290, 31 -> 30, slivers 5 -> 6,
#: for 32 fewer.
SPARE_NARROW = True

#: Whether a floor whose layout leaves rooms below their clear width (and none too small) is
#: laid out again too, without the smallest of each type of them that it can spare
#: (:func:`leave_out`), under :data:`RESOLVE_NARROW_SEEDS` seeds, kept by the same rule
#: (:func:`_fits_better`). Measured on the offline hundreds: below width 162 -> 128 for 40 rooms
#: fewer, second hundred 133 -> 119 for 31 fewer; three seeds instead of one: 125 / 114, but
#: 1.21 times the process time, where one costs 1.05.
RESOLVE_NARROW = True
RESOLVE_NARROW_SEEDS = 1
#: Layouts tried, each under a seed of its own and with a sixth of the candidates, for a floor
#: that left rooms below their minimum area or without a usable square and can spare none of them
#: (:func:`leave_out`): laid out again with all its rooms, kept by the same rule
#: (:func:`_fits_better`). Measured on the offline hundreds: rooms below their area 13 / 4 -> 10 / 3,
#: without a usable square 1 / 0 -> 0 / 0, below their width 81 / 57 -> 81 / 56, for 0.6 s of the
#: hundred's 34 s with every pass on (three seeds and six, the same figures; one, 12 below area;
#: the full batch, none mended; every floor with rooms below their width too, 78 / 54 below
#: width but 1.53 times the time with every pass off).
RESOLVE_SAME_SEEDS = 2

#: Whether a room still below its clear width after every other mend is merged into a neighbour
#: (or dropped, its floor given to one) by the rules rooms too small merge by
#: (:mod:`mansion.building.merge`), where the merged room comes out at its width: two wards
#: 2.5 m wide become one 5 m wide, a 2 m meeting room becomes part of its open office. Measured
#: on the offline hundreds: seeds 0-99, below width 205 -> 176 for 36 rooms fewer
#: (4,375 -> 4,339); seeds 100-199, 167 -> 134 for 38 fewer; 1.10 / 1.07 times the process time.
MERGE_NARROW = True
#: Whether a room below its width only by a pocket (the end of a shop's floor past a stair, a
#: food court's bay beside a lift) keeps the pocket as a store of its own
#: (:func:`mansion.building.stores.store_pockets`). Measured on the offline hundreds: below width
#: 176 -> 162 (25 stores; malls 97 and 55 hold 22 of them), second hundred 134 -> 133.
STORE_POCKETS = True
#: The mends of rooms still below their width, in order: "sides" (a room's walls pushed out into
#: the rooms beside it, :func:`mansion.building.sides.widen_sides`; first, below width 75 / 56 ->
#: 75 / 51 on the offline hundreds), "families" (a region and the rooms cut from it laid out again
#: as a row, :func:`mansion.building.families.relay_families`), "pairs" (a room and a room beside
#: it cut again together by one straight or corner cut, :func:`mansion.building.pairs.recut_pairs`;
#: below width 45 / 27 -> 41 / 26 on the offline hundreds, 6 / 6 rooms more kept; with the
#: libraries' and supermarkets' corridor hubs 36 / 20 -> 32 / 19), "stores"
#: (:data:`STORE_POCKETS`), "halls" (a room's arms that carry its doors made halls off it,
#: :func:`mansion.building.halls.hall_arms`; measured alone on the offline hundreds, below width
#: 101 / 66 -> 90 / 60 with 14 / 11 halls), "merges" (:data:`MERGE_NARROW`), "drops" (a family
#: too tight for its rooms laid out again without one). Those that keep every room come first:
#: with the merges before the stores and halls, the same rooms are left below their width on the
#: offline hundreds (80 / 57) for 10 / 10 rooms fewer. A mend left out of the tuple is off.
NARROW_MENDS = ("sides", "families", "pairs", "stores", "halls", "merges", "drops")
#: Why such a room is named in the floor's relaxations.
NARROW_WHY = "laid out narrower than its clear width"

#: A floor about to be laid out again without the rooms it can spare is first laid out without
#: only as many of them as its shortfall needs (:func:`_fewest_left_out`): left out, most squeezed
#: first, until their planned area covers this many times what the rooms kept lack of their
#: minimum areas, each cover in turn; kept when its mends leave no room below its minimums.
#: Seeds 0-99 / 100-199: rooms 4,362 / 4,281 -> 4,371 / 4,326, below width 45 / 28 -> 45 / 27,
#: the other counts unchanged, for 1.435 times the time of the passes off against 1.373
#: (``benches/python/bench_passes.py``); covers 2 then 4: 65 rooms more than without on the two
#: hundreds, 3 alone 54, for 4.9 and 3.1 % more time; () lays the floor out without all it can
#: spare at once, as before.
DEFICIT_COVERS: tuple[float, ...] = (3.0,)

#: Whether a room the mends leave below its clear width or minimum area is, last, left out where
#: the program can spare it, its floor shared by the rooms beside it (:mod:`mansion.building.dissolve`).
DISSOLVE = True

#: Whether a room the mends and the dissolve leave below its clear width is, last, cut again
#: with each room beside it by every straight or corner cut of their cells
#: (:func:`mansion.building.pairs.recut_pairs` with no cap on the splits judged; the pairs mend of
#: :data:`NARROW_MENDS` judges the 60 keeping most of the room's cells, as more there leave the
#: later mends worse rooms), the room beside coming out with no defect at all. An office's board
#: room of 41 m^2 whose arm is 3.5 m wide (3.6 m asked) keeps its body, 4.5 m wide, and gives the
#: arm to the private office beside it, a split that keeps 70 % of its cells.
LAST_PAIRS = True

#: Whether, after the dissolve, a room still below its clear width with two to
#: :data:`mansion.building.recut.MAX_CLUSTER` rooms cut from it is laid out again with them, its
#: strip as deep as it takes (:func:`mansion.building.recut.relay_narrow_clusters`): the dissolve
#: gives rooms' floors to such a room (office 61's open-office bay took a meeting room's) after
#: the width mends had their turn.
LATE_CLUSTERS = True

#: Whether a floor that every mend and relayout still leaves with a room below its clear width
#: has the families holding such rooms cut again by the solver under :data:`LAST_FAMILY_SEEDS`
#: seeds, then laid out again without one of their rooms (the smallest that lets the family be,
#: as the "drops" of :data:`NARROW_MENDS`), by rows of rectangles or by the solver
#: (:func:`_families_last`, :func:`mansion.building.families.relay_families` with the floor's
#: solver). Last, so that no relayout that keeps every room is passed over for a room dropped, and
#: after the dissolve: office 47's third floor has two bays below their width and one meeting room
#: to spare between them; the dissolve gives the second bay the meeting room's floor, and the
#: first, after it, drops a private office and is cut again.
LAST_FAMILIES = True
#: The solver's random seeds a family is cut again under by :data:`LAST_FAMILIES` (the few
#: families still below their width by then; ``families.relay_families``' own default is one):
#: office 47's first bay without its private office passes under the sixth.
LAST_FAMILY_SEEDS = 8

#: Whether a room the program can spare that every mend, the dissolve and :data:`LAST_PAIRS` leave
#: below its minimum area or clear width, and that no room beside it may take, is made a store
#: where it is a sound one (:func:`mansion.building.stores.store_spare_rooms`): an office's third
#: meeting room of 6.2 m^2 between a stair, the corridor and a store.
SPARE_STORES = True

#: Whether the last steps (the dissolve, :data:`SPARE_STORES`) may spare a room whose type the
#: floor's template plans only where it fits (``Rm(..., optional=True)``: a school's art room, a
#: kindergarten's staff office) though it is the floor's last of its type, as the banks leave
#: such rooms out where no bay is left for them.
SPARE_OPTIONAL = True

#: Whether a floor its relayouts (:func:`solve_building_floor`) still leave with rooms below
#: their minimums is, last, laid out again whole without such of them as its template plans only
#: where they fit (:func:`_without_optional`: a school's art room wrapped round a stair), though
#: the last of their type; kept as a relayout is, each room left out recorded.
LEAVE_OPTIONAL = True

#: Whether a floor about to be laid out again without rooms it could not fit (``RESOLVE_*``) is
#: first mended as it is, and kept with all its rooms when the mends leave none below its
#: minimum area or width, or when the layout without rooms, mended too, leaves no fewer. The
#: second layouts judge the layout before any mend, and left out rooms the mends would have
#: brought to their minimums (kindergarten 22's group room at 27.5 m² of 30; hotel 12's three
#: guest rooms a floor). Measured on the offline hundreds (seeds 0-99 / 100-199): rooms left out
#: 116 / 173 -> 92 / 128, rooms 4,335 / 4,250 -> 4,362 / 4,281, below width 46 / 29 -> 45 / 28,
#: the hubs' area over plan 4,391 -> 4,138 m² on the first, for 1.39 times the time of the
#: passes off against 1.34 (``benches/python/bench_passes.py``, one run each, the same hour).
MEND_FIRST = True


def _fits_better(
    layout: FloorLayout, graph: RoomGraph, unfit: dict[str, str], narrow: int, shape: tuple[int, int],
    program: BuildingProgram,
) -> bool:
    """Whether a floor laid out again without rooms it spared is kept: no more rooms ``unfit``
    than before and no more of them without a usable square, fewer unfit or below their clear
    width (``narrow``) in all, and no more elongated rooms or slivers (``shape``,
    :func:`misshapen`)."""
    now = unfit_rooms(layout.rooms, graph)
    if len(now) > len(unfit) or _unusable(now) > _unusable(unfit):
        return False
    if not all(a <= b for a, b in zip(misshapen(layout.rooms), shape)):
        return False
    thin = len(narrow_rooms(layout.rooms, program.building_type)) if SPARE_NARROW else 0
    return len(now) + thin < len(unfit) + (narrow if SPARE_NARROW else 0)


def _fewest_left_out(
    index: int, planned: RoomGraph, footprint: Footprint, first: FloorLayout, unfit: dict[str, str],
    dropped: list[str], shape: tuple[int, int], seed: int, quick: dict[str, Any], drop_widths: bool,
    only: int, program: BuildingProgram, asked: set[str], solver: dict[str, Any],
) -> tuple[tuple[Any, ...], tuple[FloorLayout, RoomGraph, list[str]]] | None:
    """A floor whose ``first`` layout left ``unfit`` rooms, laid out again without as few of
    them as its shortfall needs (:func:`_deficit_spare`, each of :data:`DEFICIT_COVERS` in
    turn, fewer than the ``dropped`` of all it can spare) and mended: the first whose mends leave
    no room below its minimum area or width, unusable, and no more elongated rooms or slivers
    than ``shape``, as (the solve's layout, graph, footprint, seed, attempts, relaxations and the
    notes of the rooms left out; the mended layout, graph and notes); else None."""
    tried: set[frozenset[str]] = set()
    for cover in DEFICIT_COVERS:
        least, notes = _deficit_spare(first, planned, unfit, cover, keep=asked)
        gone = frozenset(n.id for n in planned.nodes) - {n.id for n in least.nodes}
        if not 0 < len(notes) < len(dropped) or gone in tried:
            continue
        tried.add(gone)
        try:
            again = _solve(index, least, footprint, None, seed, quick, drop_widths, only=only)
        except InfeasibleLayoutError:
            continue
        if unfit_rooms(again[0].rooms, again[1]):
            # measured on the second hundred: none of the 10 such layouts (of 26 mended) came out
            # of its mends without a room below its minimums, so they are not mended
            continue
        fixed = _mended_floor(again[0], again[1], program, asked, solver, index)
        bad = _bad_counts(fixed[0], fixed[1], program.building_type)
        if not any(bad) and all(a <= b for a, b in zip(misshapen(fixed[0].rooms), shape)):
            return (*again, notes), fixed
    return None


def _deficit_spare(
    layout: FloorLayout, graph: RoomGraph, unfit: dict[str, str], cover: float = 1.0, keep: Iterable[str] = (),
) -> tuple[RoomGraph, list[str]]:
    """``graph`` without the fewest of the ``unfit`` rooms of a floor's first ``layout`` (id ->
    why) whose planned area, left out with the rooms cut from them (:func:`leave_out`, which
    never leaves out ``keep``), covers ``cover`` times what the others lack of their minimum
    areas, the most squeezed first; with :func:`leave_out`'s notes. A room at its minimum area
    but with no usable square counts a quarter of its minimum as lacking. Nine wards laid out at
    4 to 14 m² of their 14.5 m² lack 45 m² in all: leaving three out covers it once, where
    leaving eight out (every ward but the one a floor keeps of its type) gave the floor to their
    two ward corridors."""
    nodes = {n.id: n for n in graph.nodes}
    areas = {room.id: room.area for room in layout.rooms}

    def lacks(room: str) -> float:
        least = _least(nodes[room])
        return max(least - areas.get(room, 0.0), 0.25 * least)

    order = sorted((r for r in unfit if r in nodes), key=lambda r: (-lacks(r), r))
    spare: dict[str, str] = {}
    fewer, notes = graph, []
    for room in order:
        spare[room] = unfit[room]
        fewer, notes = leave_out(graph, spare, keep=keep)
        kept = {n.id for n in fewer.nodes}
        freed = sum(n.area for n in graph.nodes if n.id not in kept)
        if freed >= cover * sum(lacks(r) for r in order if r in kept):
            break
    return fewer, notes


def _unusable(unfit: dict[str, str]) -> int:
    """How many of ``unfit`` (:func:`unfit_rooms`) hold no usable square."""
    return sum(why.endswith(f"no usable {USABLE_SIDE:g} m square") for why in unfit.values())


def unfit_rooms(rooms: Iterable[LayoutRoom], graph: RoomGraph) -> dict[str, str]:
    """The laid-out ``rooms`` (a layout's; cores left out) below their node's ``min_area``, or
    with no usable square (:data:`USABLE_SIDE`), each with why."""
    nodes = {n.id: n for n in graph.nodes}
    out: dict[str, str] = {}
    for room in rooms:
        node = nodes.get(room.id)
        if room.is_core or node is None:
            continue
        why = shape_measure(room, ("unfit", node.min_area))
        if why:
            out[room.id] = why
    return out


def narrow_rooms(rooms: Iterable[LayoutRoom], building_type: str | None) -> set[str]:
    """The laid-out ``rooms`` (cores left out) below their clear width: ``mansion eval realism``'s
    "below its width", more than a tenth of the room narrower than its type's width (a corridor's,
    its building type's corridor width)."""
    return {
        room.id for room in rooms
        if not room.is_core and shape_measure(room, ("narrow", needed_width(room.room_type, building_type)))
    }


def smallest_narrow(rooms: Iterable[LayoutRoom], narrow: set[str]) -> dict[str, str]:
    """Of each room type, the smallest of the ``narrow`` rooms (ties by id), with why: what a
    floor laid out again may also spare (:func:`leave_out` decides whether it can)."""
    out: dict[str, str] = {}
    kinds: set[str] = set()
    for room in sorted((r for r in rooms if r.id in narrow), key=lambda r: (r.area, r.id)):
        if room.room_type not in kinds:
            kinds.add(room.room_type)
            out[room.id] = NARROW_WHY
    return out


def misshapen(rooms: Iterable[LayoutRoom]) -> tuple[int, int]:
    """(elongated, slivers) as ``mansion eval realism`` counts them, cores left out: rooms other
    than circulation whose box is longer than :data:`ELONGATED_ASPECT` times its width, and rooms
    with more than a tenth of their area in parts :data:`USABLE_SIDE` wide or narrower."""
    elongated = slivers = 0
    for room in rooms:
        if room.is_core:
            continue
        shape = outline(room)
        if not room_design(room.room_type).circulation:
            elongated += box_aspect(shape) > ELONGATED_ASPECT
        slivers += mostly_narrower(shape, USABLE_SIDE, inclusive=True)
    return elongated, slivers


def leave_out(
    graph: RoomGraph, unfit: dict[str, str], keep: Iterable[str] = (), optional: Iterable[str] = (),
) -> tuple[RoomGraph, list[str]]:
    """``graph`` without the ``unfit`` rooms (id → why) an architect would leave out of a floor
    too tight for them, each with the rooms cut from it (a ward with its ensuite), and a
    relaxation note per room: only a room of a type the floor has more of (a ward, a guest room,
    a toilet of a block; one of each type stays) or one of ``optional`` (rooms the floor's
    template plans only where they fit, :data:`LEAVE_OPTIONAL`), that is neither the hub, a core nor
    circulation, and whose rooms are at most three, none of them in ``keep`` (the rooms the
    description asked for: "two operating theatres" keeps both). A wing's corridor whose rooms
    all go goes too, with a note: it would serve nothing (six floors of the offline hundreds had
    kept one, 11-29 m²)."""
    kept = set(keep)
    parent = cut_parents(graph)
    children: dict[str, list[str]] = {}
    for room, up in parent.items():
        children.setdefault(up, []).append(room)

    def subtree(room: str) -> list[str]:
        out, stack = [], [room]
        while stack:
            r = stack.pop()
            out.append(r)
            stack.extend(children.get(r, []))
        return out

    nodes = {n.id: n for n in graph.nodes}
    extra = frozenset(optional)
    left: dict[str, int] = {}
    for n in graph.nodes:
        left[n.room_type or n.id] = left.get(n.room_type or n.id, 0) + 1
    dropped: list[str] = []
    notes: list[str] = []
    for room in sorted(unfit):
        node = nodes.get(room)
        if node is None:
            continue
        kind = node.room_type or room
        if (
            room == graph.hub.id or node.is_core or room not in parent
            or room_design(node.room_type).circulation or (left[kind] < 2 and room not in extra)
            or any(r in dropped or r in kept for r in subtree(room))
        ):
            continue
        rooms = subtree(room)
        if len(rooms) > 3:
            continue
        left[kind] -= 1
        dropped += rooms
        also = f" (with {', '.join(rooms[1:])})" if len(rooms) > 1 else ""
        notes.append(f"{room} left out{also}: {unfit[room]}")
    if not dropped:
        return graph, []
    gone = set(dropped)
    # a wing's corridor every room of which is left out serves nothing: it goes too, its floor
    # to the rest (a corridor is planned for the rooms it serves, never left over)
    emptied = True
    while emptied:
        emptied = False
        for up, rooms in sorted(children.items()):
            node = nodes[up]
            if (
                up not in gone and up != graph.hub.id and up in parent and not node.is_core
                and up not in kept and room_design(node.room_type).circulation
                and all(r in gone for r in rooms)
            ):
                gone.add(up)
                notes.append(f"{up} left out: every room it served was left out")
                emptied = True
    return RoomGraph(
        nodes=[n for n in graph.nodes if n.id not in gone],
        edges=[e for e in graph.edges if e.source not in gone and e.target not in gone],
    ), notes


def copy_floor(source: Floor, index: int) -> Floor:
    """Floor ``index`` as the paper's copy of ``source``: the same graph and layout."""
    return source.model_copy(update={"index": index, "copy_of": source.index})


def floor_footprint(program: BuildingProgram, index: int) -> Footprint:
    """Floor ``index``'s outline, courtyards and the cores that serve it."""
    floor_program = program.floor_program(index)
    return Footprint(
        polygon=floor_program.outline, holes=floor_program.holes,
        cores=[Core(id=c.id, type=c.type, x=c.x, y=c.y) for c in program.cores if index in c.floors],
    )


def solve_building_floor(
    program: BuildingProgram,
    index: int,
    graph: RoomGraph,
    below: Floor | None,
    seed: int,
    solver: dict[str, Any],
    seed_planner: SeedPlanner | None = None,
    description: str | None = None,
    drop_widths: bool = True,
    relayouts: int = 0,
) -> Floor:
    """SolveFloorLayout for floor ``index`` (not a copy) of ``program``.

    ``drop_widths``: whether the last rung of the ladder, without width rules, may lay the floor
    out. The offline driver allows it only to its last program: a layout without rules may keep
    a 0.5 m neck no agent passes, where a program re-planned with fewer or smaller rooms keeps
    the rules (building 804 of the seed-0 dataset: a hotel floor laid out without rules, its
    guest rooms cut off, where the re-planned program lays it out at the first attempt).

    ``below`` is the solved floor underneath (None on the ground floor): its load-bearing walls
    become fixed walls here when the program keeps them. ``seed_planner`` is the cutting node's
    planner (None: the solver's offline heuristic); on a floor whose first round must follow the
    walls below, the first round is seeded from the floor below and the other rounds go to it.

    ``relayouts``: times a floor the mends leave with rooms below their minimum area or clear
    width is laid out again whole, mends and all, under a seed of its own with a sixth of the
    candidates (and of its fallback, no backtracks: :func:`_relayout_options`), from the rung of
    the ladder that laid the floor out; the layout with fewer such rooms is kept where it also
    leaves fewer rooms bad, elongated or slivers in all (:data:`RELAYOUT_SHAPES`; offline seeds;
    a floor that carries walls too, before the floors above follow it). Buildings are generated
    with one (:data:`mansion.building.generate.RELAYOUTS`): it cuts the offline hundred's rooms
    below their width from 22 to 15 for 1.38-1.46 times the generation time of the passes off
    (the issue's bound is 1.5).
    """
    floor, again = _solve_building_floor(
        program, index, graph, below, seed, solver, seed_planner, description, drop_widths,
    )
    if not again or not relayouts:
        return _families_last(program, floor, solver, graph, description)
    left = _bad_counts(floor.layout, floor.graph, program.building_type)
    quick = _relayout_options(solver)
    more = SMALL_FLOOR_RELAYOUTS if floor.footprint.area <= SMALL_FLOOR_AREA + 1e-9 else 0
    for k in range(relayouts + more):
        if left == (0, 0):
            break
        try:
            other, _ = _solve_building_floor(
                program, index, graph, below, derived_seed(seed, "whole", index, k), quick,
                seed_planner, description, drop_widths, start=floor.attempts - 1 if RELAYOUT_FROM_RUNG else 0,
            )
        except InfeasibleLayoutError:
            continue
        found = _bad_counts(other.layout, other.graph, program.building_type)
        if _better_relayout(other, found, floor, left):
            floor, left = other, found
    if LEAVE_OPTIONAL and left != (0, 0):
        floor = _without_optional(program, index, graph, below, seed, quick, seed_planner, description,
                                  drop_widths, floor, left)
    return _families_last(program, floor, solver, graph, description)


def _families_last(
    program: BuildingProgram, floor: Floor, solver: dict[str, Any], planned: RoomGraph, description: str | None,
) -> Floor:
    """``floor`` with the families that hold a room still below its clear width cut again by the
    solver, or laid out again without one of their rooms (:data:`LAST_FAMILIES`), each recorded;
    ``floor`` itself when there are none or none passes (or the floor's solve has no repair).
    The description's position words the floor records are checked again on the rooms as they
    now lie (``planned``: the graph the floor was planned with, which they were read against)."""
    settings = solver.get("settings")
    kind = program.building_type
    if not LAST_FAMILIES or settings is None or not settings.repair or not narrow_rooms(floor.layout.rooms, kind):
        return floor
    layout, graph, notes = floor.layout, floor.graph, []
    for drop in (False, True):
        layout, graph, done = relay_families(
            layout, graph, kind, min_contact=solver.get("min_contact", 1.0), keep=_asked(program), drop=drop,
            solver=solver, seeds=LAST_FAMILY_SEEDS,
        )
        notes += done
    if not notes:
        return floor
    kept = {n.id for n in graph.nodes}
    words = floor.position_words
    if words and description:
        from mansion.floorplan.text_seeds import text_seed_planner

        text_planner = text_seed_planner(description, planned, floor.footprint, solver.get("cell_size", 0.5))
        if text_planner is not None:
            words = _position_words(text_planner, layout)
    return floor.model_copy(update={
        "layout": layout, "graph": graph, "relaxations": [*floor.relaxations, *notes],
        "room_cards": [card for card in floor.room_cards if card.id in kept],
        "carried_walls": first_round_walls(layout, graph) if program.load_bearing_walls else [],
        "position_words": words,
    })


def _position_words(text_planner: TextSeedPlanner, layout: FloorLayout) -> list[PositionWord]:
    """The description's statements placing rooms of the floor (read by ``text_planner``), each
    with whether ``layout``'s rooms (their centroids) honour it."""
    from mansion.floorplan.text_seeds import position_checks

    centroids = {room.id: (room.centroid[0], room.centroid[1]) for room in layout.rooms}
    return [PositionWord(room=c.room, statement=c.text, honoured=c.honoured) for c in position_checks(text_planner, centroids)]


def _without_optional(
    program: BuildingProgram, index: int, graph: RoomGraph, below: Floor | None, seed: int,
    quick: dict[str, Any], seed_planner: SeedPlanner | None, description: str | None, drop_widths: bool,
    floor: Floor, left: tuple[int, int],
) -> Floor:
    """``floor``, or the floor laid out again whole without the optional rooms of its template
    that its relayouts still leave below their minimums (:data:`LEAVE_OPTIONAL`), or, when none of
    the rooms left so is optional, without one of its optional rooms, the largest first, up to
    :data:`MAKE_ROOM_TRIES` tries (:data:`MAKE_ROOM_OPTIONAL`): the best of them where it leaves
    fewer rooms bad, as a relayout is kept; each room left out recorded."""
    kind = program.building_type
    asked = _asked(program)
    optional = _optional_rooms(program, index, graph, asked)
    bad = _bad_rooms(floor.layout, floor.graph, kind)
    spare = {room: why for room, why in bad.items() if room in optional}
    tries = [spare] if spare else []
    if MAKE_ROOM_OPTIONAL and not spare:
        # no optional room is bad: one of them, the largest first, makes room for those that are
        sizes = {n.id: n.area for n in graph.nodes}
        first = min(bad, key=lambda r: (r not in sizes, r))
        why = f"room made for {first} ({bad[first]})"
        tries = [{room: why} for room in sorted(optional, key=lambda r: (-sizes.get(r, 0.0), r))][:MAKE_ROOM_TRIES]
    best: tuple[Floor, tuple[int, int], list[str]] | None = None
    for k, out in enumerate(tries):
        fewer, notes = leave_out(graph, out, keep=asked, optional=optional)
        if not notes:
            continue
        try:
            other, _ = _solve_building_floor(
                program, index, fewer, below, derived_seed(seed, "optional", index, *([k] if k else [])), quick,
                seed_planner, description, drop_widths, start=floor.attempts - 1 if RELAYOUT_FROM_RUNG else 0,
            )
        except InfeasibleLayoutError:
            continue
        found = _bad_counts(other.layout, other.graph, kind)
        if _better_relayout(other, found, *(best[:2] if best else (floor, left))):
            best = (other, found, notes)
    if best is None:
        return floor
    return best[0].model_copy(update={"relaxations": [*best[2], *best[0].relaxations]})


def _better_relayout(other: Floor, found: tuple[int, int], floor: Floor, left: tuple[int, int]) -> bool:
    """Whether a floor laid out again (``other``, its :func:`_bad_counts` ``found``) replaces
    ``floor`` (``left``): fewer rooms bad, and with :data:`RELAYOUT_SHAPES` fewer rooms bad,
    elongated or slivers in all."""
    return found < left and (
        not RELAYOUT_SHAPES
        or found[1] + sum(misshapen(other.layout.rooms)) < left[1] + sum(misshapen(floor.layout.rooms))
    )


#: Relayouts more than asked (``relayouts`` of :func:`solve_building_floor`, when it asks for any)
#: for a floor of at most :data:`SMALL_FLOOR_AREA` m² (``Footprint.area``: its outline less its
#: courtyards, cores included): a townhouse's floor is laid
#: out in a fraction of the time of a hospital's, and its living room, the hub, wraps round the
#: stair under one seed where another seed lays it out square.
SMALL_FLOOR_RELAYOUTS = 3

#: Whether a floor its relayouts still leave with rooms below their minimums, none of them one of
#: its template's optional rooms, is laid out again without one of those (the largest first, up
#: to :data:`MAKE_ROOM_TRIES`), kept as a relayout is: a kindergarten's staff office makes room
#: for its sleep room.
MAKE_ROOM_OPTIONAL = True
MAKE_ROOM_TRIES = 2
SMALL_FLOOR_AREA = 120.0

#: Whether, on the floor whose first-round walls go up through the building (:func:`_walls_go_up`),
#: the hub, where it is circulation, takes the arms of the first-round regions too narrow for
#: their rooms that lie beside it, before the floor's other mends
#: (:func:`mansion.building.regions.hub_takes_arms`): each floor above repeats the region, and
#: its rooms cannot leave the arm, since no mend there moves a carried wall (apartment block 88 of
#: the realism hundred: a flat's region ran 1.5 m wide for 10 m between the corridor and the
#: facade, and its living room took that arm on three floors above).
REGION_ARMS = True

#: Whether the floors above one whose hub took such an arm hold their first-round regions, not
#: only their rooms, off the walls carried from below (``SolverSettings.hold_regions``;
#: ``Floor.held_regions`` passes it up): else the flat above runs its region round the carried
#: wall into the arm, which lies against the facade, and lays a bedroom 1.5 m wide there.
HOLD_REGIONS = True

#: Whether a relayout is kept only when it also leaves fewer rooms below their area or width,
#: elongated or slivers (:func:`misshapen`) in all than the layout it replaces: not one that
#: trades a room below its width for an elongated one.
RELAYOUT_SHAPES = True


#: Whether a relayout climbs the ladder of attempts from the rung that laid the floor out (else
#: from the first): the rungs below it failed that floor under its own seed.
RELAYOUT_FROM_RUNG = True


def _bad_rooms(layout: FloorLayout, graph: RoomGraph, building_type: str | None) -> dict[str, str]:
    """The rooms of ``layout`` below their clear width, minimum area or without a usable square
    (id -> why; a room both narrow and too small says it is too small)."""
    return {
        **dict.fromkeys(narrow_rooms(layout.rooms, building_type), NARROW_WHY),
        **unfit_rooms(layout.rooms, graph),
    }


def _walls_go_up(program: BuildingProgram, index: int, footprint: Footprint) -> bool:
    """Whether the first-round walls of floor ``index`` (laid on ``footprint``) go up to a floor
    above that it does not follow itself: its first round was cut freely (no walls carried from
    below), the program keeps load-bearing walls and a floor lies above."""
    return program.load_bearing_walls and not footprint.fixed_walls and index + 1 < program.floor_count


def _bad_counts(layout: FloorLayout, graph: RoomGraph, building_type: str | None) -> tuple[int, int]:
    """(rooms of ``layout`` below their minimum area or unusable, those and the ones below their
    clear width)."""
    unfit = unfit_rooms(layout.rooms, graph)
    return len(unfit), len(set(unfit) | narrow_rooms(layout.rooms, building_type))


def _quick(solver: dict[str, Any]) -> dict[str, Any]:
    """``solver`` with a :data:`RESOLVE_DIVISOR`-th of its candidates per retry: the options of a
    floor laid out again (its second layouts, its relayouts)."""
    return {**solver, "batch": max(1, solver.get("batch", 100) // RESOLVE_DIVISOR)}


#: Backtracks a relayout's solve may spend at most (``SolverSettings.max_backtracks``; None: the
#: floor's own): a relayout is one more draw, and a layout that a round no candidate passes sends
#: back is left to the next rung of the ladder. Measured on the offline hundreds with one relayout
#: (rooms below their area or width, seeds 0-99 / 100-199; the relayouts' solver time on the
#: first): 8 backtracks 28 / 16, 1.8 s; one, 28 / 16; none, 26 / 16, 1.2 s.
RELAYOUT_BACKTRACKS: int | None = 0


def _relayout_options(solver: dict[str, Any]) -> dict[str, Any]:
    """The options of a relayout (:func:`solve_building_floor`): :func:`_quick`'s, with a
    :data:`RESOLVE_DIVISOR`-th of the Monte Carlo fallback's candidates too
    (``SolverSettings.fallback_samples``) and at most :data:`RELAYOUT_BACKTRACKS` backtracks. A
    round every retry fails draws the fallback's 400 candidates whatever the batch, in batches of
    it: on the offline hundred with one relayout (seeds 0-99) the quick layouts' solves (second
    layouts and relayouts) took 5.0 s of process time, 2.2 s of it in the 14 that failed, and
    3.9 s with a sixth of the fallback (the four rounds the fallback won there, it won within its
    first sixth; on seeds 0-199, and 0-99 with a relayout, three rounds won later than that, so
    the second layouts keep the whole fallback and the default its buildings)."""
    quick = _quick(solver)
    settings = solver.get("settings")
    if settings is not None:
        update: dict[str, Any] = {"fallback_samples": settings.fallback_samples // RESOLVE_DIVISOR}
        if RELAYOUT_BACKTRACKS is not None:
            update["max_backtracks"] = min(settings.max_backtracks, RELAYOUT_BACKTRACKS)
        quick["settings"] = settings.model_copy(update=update)
    return quick


def _solve_building_floor(
    program: BuildingProgram, index: int, graph: RoomGraph, below: Floor | None, seed: int,
    solver: dict[str, Any], seed_planner: SeedPlanner | None, description: str | None, drop_widths: bool,
    start: int = 0,
) -> tuple[Floor, bool]:
    """:func:`solve_building_floor` under one seed: the floor, and whether it may be laid out
    again whole (the offline seeds, mends on)."""
    floor_program = program.floor_program(index)
    fp = floor_footprint(program, index)
    planner = seed_planner
    text_planner = None
    left_out: list[str] = []
    if planner is None and description:
        # the description's position words ("the kitchen in the north-east corner") seed the
        # rooms they name; a floor they do not mention keeps the solver's heuristic
        from mansion.floorplan.text_seeds import text_seed_planner

        text_planner = text_seed_planner(description, graph, fp, solver.get("cell_size", 0.5))
        planner = text_planner
    if BANKS and planner is None and not program.load_bearing_walls and start == 0:
        banked = _banked_floor(program, index, graph, fp, solver, seed)
        if banked is not None:
            return banked, False
    if program.load_bearing_walls and below is not None and below.carried_walls:
        walls = carry_walls(below.carried_walls, fp)
        if walls:
            fp = fp.model_copy(update={"fixed_walls": walls})
            regions = first_round_regions(below.layout, below.graph)
            ours = {g for g in first_round_groups(graph).values()}
            # Same first round as below: match its areas and seed it in the same places.
            if ours == set(regions):
                graph, left_out = retarget_first_round(graph, {k: a for k, (a, _) in regions.items()})
                planner = SkeletonSeedPlanner(
                    graph.hub.id, {k: p for k, (_, p) in regions.items()}, rest=seed_planner
                )
    # the floors above one whose hub took a region's arm hold their regions off the carried walls
    hold = bool(
        HOLD_REGIONS and program.load_bearing_walls and below is not None and below.held_regions and fp.fixed_walls
    )
    if program.load_bearing_walls and solver.get("settings") is not None:
        # the floor above carries the walls between this floor's first-round regions: the
        # repair moves cells only within a region, so those walls stay where the cut put them
        solver = {**solver, "settings": solver["settings"].model_copy(
            update={"keep_first_round": True, "hold_regions": hold},
        )}
    planned, footprint = graph, fp
    layout, graph, fp, rng_seed, attempts, relax = _solve(
        index, planned, fp, planner, seed, solver, drop_widths, start=start,
    )
    settings = solver.get("settings")
    repairs = settings is not None and settings.repair
    asked = _asked(program)
    premended: tuple[FloorLayout, RoomGraph, list[str]] | None = None
    fewest: tuple[FloorLayout, RoomGraph, list[str]] | None = None
    relaid = False
    if repairs and planner is None and not program.load_bearing_walls:
        # Rooms the layout left below their minimum area or unusable: the floor is too tight for
        # them. Leave the ones a floor can do without out (a ward of several, with its ensuite)
        # and lay the floor out again on the rung of the ladder that laid it out; keep that
        # layout when no more rooms are left unfit, fewer unfit or below their clear width in
        # all, and none more is elongated or a sliver, else try again under another seed, up to
        # RESOLVE_SEEDS layouts.
        # Such a floor is too tight for its rooms below their clear width as well: of each type
        # it also spares the smallest of those (SPARE_NARROW). A floor with rooms below their
        # width alone is laid out again the same way under one seed (RESOLVE_NARROW): measured
        # when the mends were fewer and slower it cost 1.09 times the generation time; now 1.05.
        # Only with the offline seeds: a seed planner (Claude's, the description's position
        # words) was asked for this graph's rooms and would be asked again.
        # Not on floors that carry walls: a floor laid out again moves the walls every floor
        # above follows (measured on the hundred: the offices above such floors gained slivers,
        # 0.1 → 1.2 %, for 4.1 → 2.6 % below area).
        unfit = unfit_rooms(layout.rooms, graph)
        # a floor whose layout backtracked is laid out again for rooms too small only: its
        # layouts cost twice as much, and its rooms below their width alone gained a tenth of
        # what the step gains for a third of its time
        narrow_again = RESOLVE_NARROW and layout.diagnostics.backtracks == 0
        narrow = narrow_rooms(layout.rooms, program.building_type) if (unfit or narrow_again) else set()
        spare = {**smallest_narrow(layout.rooms, narrow - set(unfit)), **unfit} if SPARE_NARROW else unfit
        fewer, dropped = leave_out(planned, spare, keep=asked) if (unfit or narrow) else (planned, [])
        # a sixth of the candidates per retry: with rooms out the floor has area to spare, and
        # the full batch cost the hundred 1.4 times its generation time
        quick = _quick(solver)
        # a floor with rooms too small for it that it cannot spare is laid out again with all
        # its rooms, under seeds of its own
        same = bool(unfit) and not dropped
        shape = misshapen(layout.rooms) if (dropped or same) else (0, 0)  # what the new ones must match
        solved = (layout, graph, fp, rng_seed, attempts, relax, left_out)
        tries = RESOLVE_SAME_SEEDS if same else (RESOLVE_SEEDS if unfit else RESOLVE_NARROW_SEEDS) if dropped else 0
        if tries and MEND_FIRST:
            # the mends may bring every room of this layout to its minimums: then it is kept with
            # all its rooms, and nothing is left out for what the mends would have mended; else
            # it is kept if the layout without rooms, mended too, does no better (below)
            premended = _mended_floor(layout, graph, program, asked, solver, index)
            if not any(_bad_counts(premended[0], premended[1], program.building_type)):
                tries = 0
        if tries and dropped and not same and DEFICIT_COVERS:
            # as few rooms left out as the floor's shortfall needs, kept when its mends leave no
            # room below its minimums and no more elongated or slivers; else all it can spare
            found = _fewest_left_out(
                index, planned, footprint, layout, unfit, dropped, shape, seed, quick, drop_widths,
                attempts - 1, program, asked, solver,
            )
            if found is not None:
                (layout, graph, fp, rng_seed, attempts, relax, more), fewest = found
                left_out = [*left_out, *more]
                tries = 0
        for k in range(tries):
            try:
                # the floor's own seed first (fewer rooms), then others of its own
                again_seed = seed if k == 0 and not same else derived_seed(seed, "again", k)
                again = _solve(index, fewer, footprint, None, again_seed, quick, drop_widths, only=attempts - 1)
            except InfeasibleLayoutError:
                again = None
            if again is not None and _fits_better(again[0], again[1], unfit, len(narrow), shape, program):
                layout, graph, fp, rng_seed, attempts, relax = again
                left_out = [*left_out, *dropped]
                relaid = True
                break
    mended: list[str] = []
    held = hold
    if fewest is not None:
        layout, graph, mended = fewest
    elif premended is not None and not relaid:
        layout, graph, mended = premended
    elif repairs:
        arms: list[str] = []
        if REGION_ARMS and _walls_go_up(program, index, fp):
            # first, the hub takes the arms of first-round regions too narrow for their rooms:
            # every floor above repeats the regions (mansion.building.regions)
            took = hub_takes_arms(
                layout, graph, program.building_type, min_contact=solver.get("min_contact", 1.0), keep=frozenset(asked),
            )
            held = took[0] is not layout
            layout, graph, arms = took
        layout, graph, mended = _mended_floor(layout, graph, program, asked, solver, index)
        mended = [*arms, *mended]
        bt = program.building_type
        if premended is not None and _bad_counts(*premended[:2], bt) <= _bad_counts(layout, graph, bt):
            # the layout without rooms came out of its mends no better: keep every room
            layout, graph, fp, rng_seed, attempts, relax, left_out = solved
            layout, graph, mended = premended
    notes = {r.id: r.notes for r in floor_program.rooms}
    words = [] if text_planner is None else _position_words(text_planner, layout)
    floor = Floor(
        index=index, graph=graph, footprint=fp, layout=layout,
        room_cards=_room_cards(graph, notes), rng_seed=rng_seed, attempts=attempts,
        relaxations=[*floor_program.relaxations, *left_out, *relax, *mended],
        carried_walls=first_round_walls(layout, graph) if program.load_bearing_walls else [],
        held_regions=held,
        position_words=words,
    )
    # laid out again whole only with the offline seeds (a seed planner, Claude's or the
    # description's position words, was asked for this graph's rooms). A floor that carries walls
    # may be too: its first round follows the walls below either way, and the floors above are
    # solved after it, so they follow the layout kept (seeds 0-99 / 100-199 with one relayout:
    # below width 30 / 19 -> 28 / 17, below area 3 / 1 -> 2 / 1)
    return floor, repairs and seed_planner is None and text_planner is None



#: Whether floors whose template asks for it (a hotel's guest-room floors, a school's classroom
#: floors, a hospital's ward floors) are laid out whole as a double-loaded corridor (:mod:`mansion.building.banks`) where
#: the floor's shape allows, before the cut rounds. Measured on the offline hundreds (seeds 0-99
#: / 100-199): 22 of the hotels' 45 guest floors and 21 of the schools' 88 floors laid out so,
#: rooms below their width 32 / 19 -> 28 / 18 (the hotels' 6 -> 2, the schools' 8 -> 7), guest
#: rooms and suites 175 -> 180, classrooms 197 -> 209; 1.47-1.49 times the time of the passes
#: off against 1.52.
BANKS = True
#: Whether floors whose template allows it (a hospital's ward floors) may be laid out as a
#: racetrack (:mod:`mansion.building.banks`: wards along two facades, a corridor along each, the
#: rooms that need no daylight between). Measured on the offline hundreds (seeds 0-99 / 100-199):
#: the hospitals' rooms below their width 7 / 6 -> 1 / 2, their wards 264 -> 362 on the two;
#: overall below width 28 / 18 -> 22 / 14, rooms 4,366 / 4,337 -> 4,399 / 4,406; 1.391 times the
#: time of the passes off against 1.487 (the ward floors skip the solver and the mends).
RACETRACKS = True


def _asked(program: BuildingProgram) -> set[str]:
    """The rooms the description asked for and the program honoured: never left out."""
    return {i for r in program.requests if r.honoured for i in r.room_ids}


def _banked_floor(
    program: BuildingProgram, index: int, graph: RoomGraph, fp: Footprint, solver: dict[str, Any], seed: int,
) -> Floor | None:
    """Floor ``index`` laid out as a double-loaded corridor (:func:`bank_layout`) when its
    template asks for it and the floor's shape gives a sound layout, else None. The guest rooms
    and the template's optional rooms no bay is left for are left out (never the rooms the
    description asked for), and the width the bays leave takes more of the template's fill
    rooms (guest rooms), each with a relaxation note, as are the wing corridors the banks'
    corridor replaces."""
    try:
        template = floor_template(program.building_type, index, program.floor_count)
    except InvalidInputError:
        return None
    flat = bank_graph(graph) if template.banks else None
    if flat is None:
        return None
    asked = _asked(program)
    count: dict[str, int] = {}
    for n in flat.nodes:
        count[n.room_type] = count.get(n.room_type, 0) + 1
    hub = flat.hub.id
    optional = {rule.room_type for rule in template.rooms if rule.optional}
    spare = {
        n.id for n in flat.nodes
        if n.id != hub and not n.is_core and (count[n.room_type] > 1 or n.room_type in optional)
        and n.id not in asked and not room_design(n.room_type).circulation and n.type != "area"
    }
    fill = next((rule.room_type for rule in template.rooms if rule.fill), None)
    found = bank_layout(
        flat, fp, program.building_type, cell=solver.get("cell_size", 0.5),
        min_contact=solver.get("min_contact", 1.0), spare=spare, fill=fill,
        ring=RACETRACKS and template.racetrack,
    )
    if found is None:
        return None
    layout, kept, dropped, added = found
    floor_program = program.floor_program(index)
    notes = {r.id: r.notes for r in floor_program.rooms}
    folded = sorted({n.id for n in graph.nodes} - {n.id for n in flat.nodes})
    relax = [*floor_program.relaxations]
    relax += [f"{wing} merged into {hub}: one corridor serves both banks of rooms" for wing in folded]
    # the rooms left out are in the graph before, those added in the graph after
    baths = {e.source: e.target for e in (*flat.edges, *kept.edges) if e.source != hub}
    for rid in dropped:
        also = f" (with {baths[rid]})" if rid in baths else ""
        relax.append(f"{rid} left out{also}: no bay along the corridor was left for it")
    for rid in added:
        also = f" (with {baths[rid]})" if rid in baths else ""
        relax.append(f"{rid} added{also}: a bay along the corridor was left for one more")
    return Floor(
        index=index, graph=kept, footprint=fp, layout=layout, room_cards=_room_cards(kept, notes),
        rng_seed=derived_seed(seed, "banks", index), attempts=1, relaxations=relax,
    )


def _mended_floor(
    layout: FloorLayout, graph: RoomGraph, program: BuildingProgram, asked: set[str], solver: dict[str, Any],
    index: int,
) -> tuple[FloorLayout, RoomGraph, list[str]]:
    """The floor's mends, in order, on a solved ``layout`` of floor ``index``: the layout, the
    graph (rooms merged or dissolved) and a relaxation note per change of the program."""
    mended: list[str] = []
    # What laying the floor out again could not mend (floors that carry walls, layouts
    # refused, rooms a floor cannot leave out) is mended within one first-round region where
    # walls are carried

    def unfit_of(lay: FloorLayout, g: RoomGraph) -> dict[str, str]:
        return unfit_rooms(lay.rooms, g)

    # first cut such a room again inside the region it was cut from (nothing of the program
    # is lost: mansion.building.recut), then merge or drop what that cannot mend
    layout, mended = recut_unfit_rooms(
        layout, graph, unfit_of, program.building_type,
        min_contact=solver.get("min_contact", 1.0), same_region=program.load_bearing_walls,
    )
    # a room still too small pushes its walls out into the rooms beside it, as far as its
    # minimum needs, where they can give (mansion.building.sides)
    layout = enlarge_rooms(
        layout, graph, program.building_type, min_contact=solver.get("min_contact", 1.0),
        same_region=program.load_bearing_walls,
    )
    layout, graph, merged = merge_unfit_rooms(
        layout, graph, unfit_of, program.building_type,
        same_region=program.load_bearing_walls, keep=asked,
    )
    mended += merged
    # and rooms below their clear width cut again as rectangles where a neighbour can give
    layout = recut_narrow_rooms(
        layout, graph, program.building_type, min_contact=solver.get("min_contact", 1.0),
        same_region=program.load_bearing_walls,
    )
    # then the strips of rooms still below their width handed to the rooms beside them
    layout = hand_off_strips(
        layout, graph, program.building_type, min_contact=solver.get("min_contact", 1.0),
        same_region=program.load_bearing_walls,
    )
    # then, in the order of NARROW_MENDS, the mends of what is still below its width
    layout, graph, narrowed = mend_narrow(
        layout, graph, program, keep=asked, min_contact=solver.get("min_contact", 1.0), solver=solver,
    )
    mended += narrowed
    # last, passages 0.5 m wide (left by rounds laid out at 1 m rules) widened from a neighbour
    layout = widen_passages(
        layout, graph, program.building_type, min_contact=solver.get("min_contact", 1.0),
        same_region=program.load_bearing_walls,
    )
    # the width mends move walls: a room still below its minimum area may now find a
    # rectangle the first recut could not (a dishwashing room beside its kitchen)
    layout, recut_late = recut_unfit_rooms(
        layout, graph, unfit_of, program.building_type,
        min_contact=solver.get("min_contact", 1.0), same_region=program.load_bearing_walls,
    )
    mended += recut_late
    layout = enlarge_rooms(
        layout, graph, program.building_type, min_contact=solver.get("min_contact", 1.0),
        same_region=program.load_bearing_walls,
    )
    # the rooms the last steps may spare though the last of their type (the dissolve only
    # removes rooms, so the set read before it serves the stores after it too)
    optional = _optional_rooms(program, index, graph, asked) if SPARE_OPTIONAL else frozenset()
    if DISSOLVE:
        # last, a room no mend brought to its width or minimum area is left out where the
        # program can spare it, its floor shared by the rooms beside it
        # (mansion.building.dissolve)
        layout, graph, dissolved = dissolve_unfit_rooms(
            layout, graph, _bad_rooms(layout, graph, program.building_type), program.building_type,
            keep=asked, min_contact=solver.get("min_contact", 1.0), same_region=program.load_bearing_walls,
            optional=optional,
        )
        mended += dissolved
    if LATE_CLUSTERS:
        # a room the dissolve left below its width with the rooms cut from it (an office bay that
        # took a meeting room's floor) laid out again with them (mansion.building.recut)
        layout = relay_narrow_clusters(
            layout, graph, program.building_type, min_contact=solver.get("min_contact", 1.0),
        )
    if LAST_PAIRS:
        # what the dissolve could not spare, if still below its width, cut again with a room
        # beside it by any split at all (mansion.building.pairs)
        layout = recut_pairs(
            layout, graph, program.building_type, min_contact=solver.get("min_contact", 1.0),
            same_region=program.load_bearing_walls, tried=None, clean=True,
        )
    if SPARE_STORES:
        # and a room the program can spare that is still below its minimums, which no room
        # beside it may take, made a store where it is a sound one (mansion.building.stores)
        layout, graph, stored = store_spare_rooms(
            layout, graph, _bad_rooms(layout, graph, program.building_type), program.building_type,
            keep=asked, optional=optional,
        )
        mended += stored
    return layout, graph, mended


def _optional_rooms(
    program: BuildingProgram, index: int, graph: RoomGraph, asked: set[str],
) -> frozenset[str]:
    """The rooms of floor ``index`` whose type its template plans only where it fits (a school's
    art room, a kindergarten's staff office) and that the description did not ask for: the last
    steps may spare them though they are the last of their type (:data:`SPARE_OPTIONAL`); none
    where the building type has no template (a planner's own type)."""
    try:
        template = floor_template(program.building_type, index, program.floor_count)
    except InvalidInputError:
        return frozenset()
    optional = {rule.room_type for rule in template.rooms if rule.optional}
    return frozenset(n.id for n in graph.nodes if n.room_type in optional and n.id not in asked)


def mend_narrow(
    layout: FloorLayout, graph: RoomGraph, program: BuildingProgram, keep: set[str], min_contact: float,
    solver: dict[str, Any] | None = None,
) -> tuple[FloorLayout, RoomGraph, list[str]]:
    """``layout`` and ``graph`` after the mends of :data:`NARROW_MENDS`, in that order, of the
    rooms still below their clear width once they were cut again and handed their strips off
    (the merges and stores also skipped when :data:`MERGE_NARROW` or :data:`STORE_POCKETS` is
    off); with the relaxation notes they wrote. ``keep``: the rooms the description asked
    for, never dropped. ``solver``: the floor's keyword arguments of :func:`mansion.solve_floor`,
    with which a family no rows mend is cut again by the solver (``families.SOLVED_FAMILIES``)."""
    kind, carried = program.building_type, program.load_bearing_walls

    def narrow_of(lay: FloorLayout, g: RoomGraph) -> dict[str, str]:
        return dict.fromkeys(narrow_rooms(lay.rooms, kind), NARROW_WHY)

    mends: dict[str, Callable[[FloorLayout, RoomGraph], tuple[FloorLayout, RoomGraph, list[str]]]] = {
        # a room still below its width pushes its walls out into the rooms beside it, whole rows
        # or columns at a time (a play hall 3.5 m wide a metre into the group rooms beside it)
        "sides": lambda lay, g: (widen_sides(lay, g, kind, min_contact=min_contact, same_region=carried), g, []),
        # a region and the rooms cut from it, one of them still below its width, laid out
        # again as a row along one side with the region's room taking the rest
        "families": lambda lay, g: relay_families(lay, g, kind, min_contact=min_contact, keep=keep, solver=solver),
        # a room still below its width and a room beside it cut again together, the wall
        # between them drawn again straight or with one corner (mansion.building.pairs)
        "pairs": lambda lay, g: (recut_pairs(lay, g, kind, min_contact=min_contact, same_region=carried), g, []),
        # what is below its width only by a pocket (beside a core, past a stair) keeps the
        # pocket as a store of its own
        "stores": lambda lay, g: store_pockets(lay, g, kind, NARROW_WHY, min_contact=min_contact),
        # what is below its width because it is also a way through keeps its arms as halls off
        # it, with the doors they carry
        "halls": lambda lay, g: hall_arms(
            lay, g, kind, NARROW_WHY, min_contact=min_contact, same_region=carried,
        ),
        # what is still below its width merges or is dropped as a room too small is, where the
        # merged room comes out at its width (two wards 2.5 m wide become one 5 m wide); each
        # merge redraws two rooms, the others' measures come from room_shape's cache
        "merges": lambda lay, g: merge_unfit_rooms(
            lay, g, narrow_of, kind, same_region=carried, keep=keep, cure="narrow",
        ),
        # a region too tight for its rooms laid out as a row without the smallest it can drop
        "drops": lambda lay, g: relay_families(lay, g, kind, min_contact=min_contact, keep=keep, drop=True),
    }
    wanted = {"merges": MERGE_NARROW, "stores": STORE_POCKETS}
    notes: list[str] = []
    for step in NARROW_MENDS:
        if wanted.get(step, True):
            layout, graph, done = mends[step](layout, graph)
            notes += done
    return layout, graph, notes


def finish_building(
    description: str,
    seed: int,
    planner: str,
    program: BuildingProgram,
    palette: Palette,
    floors: list[Floor],
    min_contact: float,
) -> Building:
    """The building, after every check (:class:`InvalidBuildingError` on a failure)."""
    building = Building(
        description=description, seed=seed, planner=planner, program=program, palette=palette,
        floors=floors,
    )
    check_building(building, min_contact=min_contact)
    return building
