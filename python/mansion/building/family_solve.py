"""Families laid out again by the solver on their own cells, where no row of rectangles mends a
room of them below its clear width (issue 14).

:mod:`mansion.building.families` redraws a family (a head, not the hub, and the rooms cut from it)
as rows of rectangles along the sides of the cells it holds. That cannot lay out every region: a
hotel's dining zone is an L round the lobby's corner, 3 m wide in its foot, and its kitchen (which
needs 3.6 m) can only be 4 m wide where the restaurant gives up a strip, while the dining hall
(the head) takes the foot by the lobby; no band along one side holds that.

The solver can: its cut grows each room from a seed inside whatever region it is given, under the
rooms' width rules. :func:`solved_family` gives it the family alone: the family's cells as the
footprint (no cores, no carried walls: they lie on the family's border, which stays where it is),
the head as the hub, the rooms cut from it as its rooms with their design minimums and widths,
the relations between them, each room's target scaled so that the family fills its cells (its
minimum, and a share of the rest by what its planned area asks beyond that, as the rectangle
re-layouts share a band). It is solved under :data:`SOLVE_SEEDS` random seeds (fixed, so the
building is the same every run), and each layout is judged by the rules of a family
re-laid (:func:`mansion.building.recut.judged_score`): every room in one piece at its minimum
area with a usable square, no new part one cell wide, every relation keeping its wall (those with
rooms outside the family too: the dining hall keeps its door to the lobby), no room gaining a
defect of ``mansion eval realism`` it lacked and fewer in the family, and here every room of the
family at its width: a layout that mends one room and leaves another narrow would keep the mends
after this one (a bay dropping a room and laid out again without it) from mending the family
whole. Of those that pass, the fewest defects, then the rooms closest to their planned areas.
Nothing of the program changes; the floor's relaxations name the family cut again.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from mansion import _core
from mansion.building.merge import mask_defects
from mansion.building.recut import _box_round, _redrawn, area_shares, cluster_cells, family_rules, judged_score
from mansion.exceptions import MansionError
from mansion.floorplan.solve import solve_floor
from mansion.models.footprint import Footprint
from mansion.models.graph import RoomGraph
from mansion.models.layout import FloorLayout
from mansion.models.room_shape import EPS

__all__ = ["SOLVE_SEEDS", "solved_family"]

#: Random seeds of the solver a family is laid out under, each its own layout. On the offline
#: hundreds (seeds 0-199) one, two and four seeds make the same buildings: the family's seeds come
#: from the solver's own heuristic, and the small region's candidates converge; one costs the
#: hundred 0.6 s of process time in 65 families, four 2.6 s.
SOLVE_SEEDS = 1


def solved_family(
    layout: FloorLayout,
    graph: RoomGraph,
    head: str,
    members: list[str],
    building_type: str | None,
    min_contact: float,
    solver: dict[str, Any],
    seeds: int = SOLVE_SEEDS,
) -> tuple[float, FloorLayout] | None:
    """(its score: defects, then the rooms' miss from their planned areas; the layout) of the best
    layout of ``head``'s family (``members``: the rooms cut from it) that the solver finds on the
    family's cells and that passes the rules of a family re-laid, or None. ``solver``: the keyword
    arguments of :func:`mansion.solve_floor` the floor was laid out with; ``seeds``: the solver's
    random seeds tried, 0 to ``seeds`` - 1."""
    family = [head, *members]
    labels, cell, keys, region, keep, passable = cluster_cells(layout, graph, family)
    rooms = {r.id: r for r in layout.rooms}
    nodes = {n.id: n for n in graph.nodes}
    before, least, targets = family_rules(layout, graph, family, building_type, labels, keys)
    # each room's target scaled to fill the family's cells (the solver refuses a program larger
    # than its region)
    shares = area_shares(float(region.sum()) * cell * cell, family, least, targets)
    if shares is None:
        return None
    sub = RoomGraph(
        nodes=[
            nodes[rid].model_copy(update={
                "type": "main" if rid == head else "Entities" if nodes[rid].type == "main" else nodes[rid].type,
                # a hair under the share, for the sum's rounding
                "area": shares[rid] * (1.0 - 1e-6),
            })
            for rid in family
        ],
        edges=[e for e in graph.edges if e.source in keys and e.target in keys],
    )
    ox, oy = layout.grid.origin
    outer, holes = _core.mask_outline(region.astype(np.uint8))

    def ring(vertices: list[tuple[int, int]]) -> list[tuple[float, float]]:
        return [(ox + c * cell, oy + r * cell) for c, r in vertices]

    footprint = Footprint(polygon=ring(outer), holes=[ring(h) for h in holes])
    settings = solver.get("settings")
    if settings is not None:
        # a region of its own: no first round of the floor's to keep, no carried walls inside it
        settings = settings.model_copy(update={"keep_first_round": False, "hold_regions": False})
    around = _box_round(region)
    best: tuple[float, np.ndarray] | None = None
    tried: set[bytes] = set()
    for seed in range(seeds):
        try:
            solved = solve_floor(
                sub, footprint, weights=solver.get("weights"), cell_size=cell,
                retries=solver.get("retries", 10), batch=solver.get("batch", 100), min_contact=min_contact,
                rng_seed=seed, settings=settings,
            )
        except MansionError:
            continue
        new = _placed(labels, region, keys, solved, layout)
        if new is None:
            continue
        seen = new[around].tobytes()
        if seen in tried:
            continue
        tried.add(seen)
        # every room at its width: a layout that mends one room and leaves another narrow would
        # stop the mends after this one (a bay's drop of a room) from mending the family whole
        if any("narrow" in mask_defects(new == keys[rid], rooms[rid].room_type, building_type, cell) for rid in family):
            continue
        score = judged_score(
            layout, new, family, keep, before, least, targets, passable, building_type, min_contact, own=True,
        )
        if score is not None and (best is None or score < best[0] - EPS):
            best = (score, new)
    return None if best is None else (best[0], _redrawn(layout, best[1]))


def _placed(
    labels: np.ndarray, region: np.ndarray, keys: dict[str, int], solved: FloorLayout, layout: FloorLayout,
) -> np.ndarray | None:
    """The floor's labels with the family's cells those of ``solved`` (laid out on them alone),
    or None when its grid does not cover exactly those cells."""
    cell = layout.grid.cell_size
    sub = solved.grid.array()
    sub_ids = list(solved.grid.ids)
    # the solver's grid starts at the family's box, on the floor's grid lines
    dc = int(round((solved.grid.origin[0] - layout.grid.origin[0]) / cell))
    dr = int(round((solved.grid.origin[1] - layout.grid.origin[1]) / cell))
    new = labels.copy()
    covered = np.zeros_like(region)
    for k, rid in enumerate(sub_ids):
        if rid not in keys:
            return None
        rr, cc = np.nonzero(sub == k)
        rr, cc = rr + dr, cc + dc
        if rr.size and (rr.min() < 0 or cc.min() < 0 or rr.max() >= new.shape[0] or cc.max() >= new.shape[1]):
            return None
        new[rr, cc] = keys[rid]
        covered[rr, cc] = True
    if not np.array_equal(covered, region):
        return None
    return new.astype(np.int32)
