"""The cutting node's LLM seed planner: the paper's hierarchical seed-planning prompt.

For each cut round the solver sends a :class:`SeedRequest`; :class:`AnthropicSeedPlanner` draws
the floor (rooms placed so far, the cores, the parent region in blue), sends the picture with the
paper's prompt, and reads back one box ``x=[xmin,xmax], y=[ymin,ymax]`` and an area fraction per
child. The answer is checked (:func:`plan_from_answer`): every child exactly once and nothing else,
each box overlapping the parent region, the fractions adding up to at most 1. Problems go back to
the model. Boxes are clipped to the parent region's bounding box before the solver sees them.

Answers are remembered per request: the solver re-asks for a round when it retries a floor or
backtracks, and the same question deserves the same (already paid for) answer.
"""

from __future__ import annotations

import json
import threading
from typing import TYPE_CHECKING

from pydantic import BaseModel, Field
from shapely.geometry import Polygon, box

from mansion.agents.llm import AnswerRejected, image_block
from mansion.agents.prompts import load_prompt
from mansion.models.seeds import ChildSeed, SeedBox, SeedPlan, SeedRequest
from mansion.models.footprint import Footprint
from mansion.models.graph import RoomGraph
from mansion.planning.preview import region_png

if TYPE_CHECKING:
    from mansion.agents.llm import LLMClient

__all__ = ["AnthropicSeedPlanner", "SeedAnswer", "plan_from_answer"]

#: Fractions may add up to this much over 1 (rounding in the model's arithmetic) before refusal.
FRACTION_SLACK = 1.02


class SeedBoxAnswer(BaseModel):
    room_id: str = Field(min_length=1)
    x: list[float] = Field(min_length=2, max_length=2)
    y: list[float] = Field(min_length=2, max_length=2)
    area: float | None = None
    reason: str = ""


class SeedAnswer(BaseModel):
    seeds: list[SeedBoxAnswer]


def plan_from_answer(answer: SeedAnswer, request: SeedRequest) -> SeedPlan:
    """The checked seed plan; :class:`AnswerRejected` lists what the model must fix."""
    wanted = [c.id for c in request.children]
    given = [s.room_id for s in answer.seeds]
    problems: list[str] = []
    unknown = sorted(set(given) - set(wanted))
    if unknown:
        problems.append(f"{unknown} are not target rooms of this round; the targets are {wanted}")
    missing = [w for w in wanted if w not in given]
    if missing:
        problems.append(f"no box for {missing}; give exactly one box per target room")
    twice = sorted({g for g in given if given.count(g) > 1})
    if twice:
        problems.append(f"{twice} have more than one box; give exactly one per room")
    region = Polygon(request.region.polygon, request.region.holes)
    x0, y0, x1, y1 = region.bounds
    seeds: dict[str, ChildSeed] = {}
    total = 0.0
    for s in answer.seeds:
        if s.room_id not in wanted:
            continue
        bx, by = sorted(s.x), sorted(s.y)
        if s.x[0] > s.x[1] or s.y[0] > s.y[1]:
            problems.append(f"{s.room_id}: x=[xmin,xmax] and y=[ymin,ymax] need min <= max, got x={s.x}, y={s.y}")
            continue
        # A zero-width box is a point; give it a cell so it can touch the region.
        pad = request.cell_size / 2
        probe = box(bx[0] - pad, by[0] - pad, bx[1] + pad, by[1] + pad)
        if not probe.intersects(region) or probe.intersection(region).area <= 0:
            problems.append(
                f"{s.room_id}: box x={s.x}, y={s.y} lies outside the parent region "
                f"(x in [{x0:g}, {x1:g}], y in [{y0:g}, {y1:g}])"
            )
            continue
        if s.area is not None and not 0.0 < s.area <= 1.0:
            problems.append(f"{s.room_id}: area {s.area:g} must be a fraction of the parent area in (0, 1]")
            continue
        total += s.area or 0.0
        clipped = SeedBox(
            x=(min(max(bx[0], x0), x1), max(min(bx[1], x1), x0)),
            y=(min(max(by[0], y0), y1), max(min(by[1], y1), y0)),
        )
        seeds[s.room_id] = ChildSeed(box=clipped, fraction=s.area)
    if total > FRACTION_SLACK:
        problems.append(f"the area fractions add up to {total:.2f}; they must add up to at most 1")
    if problems:
        raise AnswerRejected(problems)
    return SeedPlan(seeds=seeds)


class AnthropicSeedPlanner:
    """A :class:`~mansion.models.seeds.SeedPlanner` asking Claude, one call per cut round.

    ``footprint`` (outline and cores) and ``graph`` (room types, areas and relations) give the
    model the whole floor around the round; ``requirement`` is the floor's brief.
    """

    def __init__(
        self,
        llm: LLMClient,
        *,
        footprint: Footprint | None = None,
        graph: RoomGraph | None = None,
        requirement: str = "",
    ) -> None:
        self.llm = llm
        self.footprint = footprint
        self.graph = graph
        self.requirement = requirement
        self._answers: dict[str, SeedPlan] = {}
        self._lock = threading.Lock()

    def _parent_type(self, parent: str) -> str:
        if self.graph is not None:
            try:
                node = self.graph.node(parent)
            except KeyError:
                return "room"
            return f"{node.type} ({node.room_type})"
        return "room"

    def _picture(self, request: SeedRequest) -> bytes:
        region = request.region
        if self.footprint is not None:
            outline, holes = self.footprint.polygon, self.footprint.holes
            cores = [(c.id, c.type, c.x, c.y) for c in self.footprint.cores]
        else:
            outline, holes, cores = region.polygon, region.holes, []
        core_ids = {c[0] for c in cores}
        placed = [(r.id, r.polygon, r.holes) for r in request.layout.rooms if r.id not in core_ids]
        return region_png(outline, holes, cores, placed, region.polygon, region.holes, request.parent)

    def prompt_values(self, request: SeedRequest) -> dict[str, object]:
        region = Polygon(request.region.polygon, request.region.holes)
        x0, y0, x1, y1 = region.bounds
        topology = {
            "parent": request.parent,
            "targets": [
                {"id": c.id, "room_type": c.room_type, "target_area_m2": round(c.target_area, 1),
                 "own_area_m2": round(c.own_area, 1), "neighbours": c.neighbours,
                 "later_cut_out_of_it": [d.id for d in c.descendants]}
                for c in request.children
            ],
        }
        if self.graph is not None:
            topology["edges"] = [e.model_dump() for e in self.graph.edges]
        return {
            "target_ids_text": ", ".join(c.id for c in request.children),
            "parent_id": request.parent,
            "parent_type": self._parent_type(request.parent),
            "parent_area": f"{request.region.area:.1f}",
            "neighbor_ids_text": ", ".join(request.parent_neighbours) or "none",
            "requirement": self.requirement or "(none given)",
            "topology_json": json.dumps(topology),
            "special_instruction": (
                "The parent keeps whatever the targets leave; rooms that must touch a placed "
                "neighbour or a core should sit on that side of the parent region."
            ),
            "minx": f"{x0:g}", "maxx": f"{x1:g}", "miny": f"{y0:g}", "maxy": f"{y1:g}",
        }

    def plan(self, request: SeedRequest) -> SeedPlan:
        key = request.model_dump_json()
        with self._lock:
            if key in self._answers:
                return self._answers[key]
        system, user = load_prompt("seed_planner").render(**self.prompt_values(request))
        content = [image_block(self._picture(request)), {"type": "text", "text": user}]
        plan = self.llm.ask(
            "seed_planner", system, content, SeedAnswer, lambda a: plan_from_answer(a, request)
        )
        assert isinstance(plan, SeedPlan)
        with self._lock:
            self._answers[key] = plan
        return plan
