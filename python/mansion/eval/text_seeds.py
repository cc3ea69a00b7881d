"""The paper's end-to-end T2D setting: Claude reads a plan's written description and places each
room's seed, instead of the protocol's ground-truth centroids.

The model sees what the protocol gives the solver (the free mask, each room's type and target
area, the adjacency pairs) plus the description text (``text/<id>.txt``), and answers one centre
per room in the mask's frame (x right, y down, 64 × 64 cells). Answers are validated: every room
exactly once, every centre on a free cell; a bad answer goes back to the model with the problems
(:class:`mansion.agents.llm.LLMClient`). The points then seed the solver through
:class:`mansion.FixedSeedPlanner`, exactly like the ground-truth seeds.
"""

from __future__ import annotations

import json
from typing import TYPE_CHECKING

from pydantic import BaseModel, Field

from mansion.agents.llm import AnswerRejected, LLMClient
from mansion.agents.prompts import load_prompt
from mansion.eval.t2d import CELL_SIZE, GRID, T2DPlan, node_id, protocol_inputs

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

__all__ = ["RoomCentre", "TextSeedAnswer", "plan_text_seeds"]


class RoomCentre(BaseModel):
    id: str
    x: float
    y: float
    reason: str = ""


class TextSeedAnswer(BaseModel):
    rooms: list[RoomCentre] = Field(min_length=1)


def _mask_rows(mask: npt.NDArray[np.bool_]) -> tuple[str, tuple[int, int, int, int]]:
    """The mask cropped to its bounding box as '#'/'.' rows, and the box (x0, x1, y0, y1)."""
    import numpy as np

    rows = np.nonzero(mask.any(axis=1))[0]
    cols = np.nonzero(mask.any(axis=0))[0]
    y0, y1, x0, x1 = int(rows[0]), int(rows[-1]), int(cols[0]), int(cols[-1])
    lines = ["".join("#" if v else "." for v in mask[y, x0 : x1 + 1]) for y in range(y0, y1 + 1)]
    return "\n".join(lines), (x0, x1, y0, y1)


def plan_text_seeds(client: LLMClient, plan: T2DPlan, description: str) -> dict[str, tuple[float, float]]:
    """Seeds of every room of ``plan`` (node id → point in the solver's y-up frame) from Claude's
    reading of ``description``. Raises :class:`mansion.PlannerError` when no valid answer comes."""
    mask = plan.label_array() != 0
    inputs = protocol_inputs(plan)
    picture, (x0, x1, y0, y1) = _mask_rows(mask)
    nodes = {n.id: n for n in inputs.graph.nodes}
    rooms = "\n".join(f"- {nid}: {n.room_type}, {n.area:.0f} cells" for nid, n in nodes.items())
    adjacency = ", ".join(f"{e.source}–{e.target}" for e in inputs.graph.edges) or "none given"
    system, user = load_prompt("t2d_seeds").render(
        description=description.strip(), mask=picture, x0=x0, x1=x1 + 1, y0=y0, y1=y1 + 1,
        rooms=rooms, adjacency=adjacency,
    )

    def check(answer: TextSeedAnswer) -> dict[str, tuple[float, float]]:
        problems: list[str] = []
        ids = [r.id for r in answer.rooms]
        for nid in nodes:
            if ids.count(nid) != 1:
                problems.append(f"room {nid!r} must appear exactly once (found {ids.count(nid)} times)")
        for extra in sorted(set(ids) - nodes.keys()):
            problems.append(f"{extra!r} is not a room of this apartment; use ids from the list")
        for r in answer.rooms:
            c, row = int(r.x), int(r.y)
            if not (0 <= row < GRID and 0 <= c < GRID and mask[row, c]):
                problems.append(f"the centre of {r.id!r} at ({r.x:g}, {r.y:g}) is not on a '#' cell")
        if problems:
            raise AnswerRejected(problems)
        # mask frame (y down) → solver frame (y up), as protocol_inputs does for centroids
        return {r.id: (r.x * CELL_SIZE, (GRID - r.y) * CELL_SIZE) for r in answer.rooms}

    return client.ask("t2d_seeds", system, [{"type": "text", "text": user}], TextSeedAnswer, check)


def expected_ids(plan: T2DPlan) -> list[str]:
    """The room ids the model must answer for, in plan order (for tests and fixtures)."""
    return [node_id(r) for r in plan.rooms]


def answer_json(points: dict[str, tuple[float, float]]) -> str:
    """An answer in the model's format from mask-frame points (for tests and fixtures)."""
    return json.dumps({"rooms": [{"id": k, "x": x, "y": y, "reason": ""} for k, (x, y) in points.items()]})
