"""The T2D text setting without a model: seeds read from a plan's description by
:mod:`mansion.planning.spatial_language` and placed by :mod:`mansion.planning.spatial_seeds`.

From the protocol (:func:`mansion.eval.t2d.protocol_inputs`) come the free region, each room's
type and target area, and the adjacency pairs, exactly as with ``--planner anthropic``; from the
text come the positions, relations, stated sizes and exterior walls. The ground-truth centroids
are never read.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from mansion.eval.t2d import CELL_SIZE, GRID, T2DPlan, protocol_inputs
from mansion.planning.spatial_language import KnownRoom, read_description
from mansion.planning.spatial_seeds import FreeGrid, SeedReport, SeedRoom, SeedWeights, match_rooms, place_seeds

if TYPE_CHECKING:
    pass

__all__ = ["plan_text_seeds_offline"]


def plan_text_seeds_offline(
    plan: T2DPlan, description: str, *, weights: SeedWeights | None = None
) -> tuple[dict[str, tuple[float, float]], SeedReport]:
    """Seeds of every room of ``plan`` (node id → solver-frame point) from ``description``."""
    import numpy as np

    inputs = protocol_inputs(plan)
    nodes = inputs.graph.nodes
    known = [KnownRoom(n.id, n.room_type or "room") for n in nodes]
    rooms = [SeedRoom(n.id, n.room_type or "room", n.area) for n in nodes]
    adjacency = [(e.source, e.target) for e in inputs.graph.edges]
    reading = match_rooms(read_description(description, known), rooms, adjacency)
    # the free mask with rows going up: mask row r (top) is solver row GRID - 1 - r
    free = FreeGrid(np.ascontiguousarray((plan.label_array() != 0)[::-1]), (0.0, 0.0), CELL_SIZE)
    assert free.mask.shape == (GRID, GRID)
    return place_seeds(reading, rooms, free, adjacency, weights=weights)
