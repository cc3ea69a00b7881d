"""The LLM building planner: Claude answering the paper's program, topology and seed prompts.

:class:`AnthropicBuildingPlanner` implements :class:`~mansion.planning.planner.BuildingPlanner`
with the same models the offline planner produces, so the rest of the pipeline cannot tell them
apart, plus :meth:`~AnthropicBuildingPlanner.seed_planner`, which gives the cutting node of each
floor an :class:`~mansion.planning.llm_seeds.AnthropicSeedPlanner`. What each answer must satisfy
and what our code decides instead of the model is in :mod:`~mansion.planning.llm_program`,
:mod:`~mansion.planning.llm_topology` and :mod:`~mansion.planning.llm_seeds`.
"""

from __future__ import annotations

import random
from typing import TYPE_CHECKING

from mansion.agents.llm import LLMClient, image_block
from mansion.agents.prompts import load_prompt
from mansion.exceptions import PlannerError
from mansion.models.building import BuildingProgram, FloorCopy, Palette
from mansion.models.footprint import Footprint
from mansion.models.graph import RoomGraph
from mansion.planning.llm_program import Frame, ProgramAnswer, palette_text, program_from_answer
from mansion.planning.llm_program import prompt_values as program_values
from mansion.planning.llm_seeds import AnthropicSeedPlanner
from mansion.planning.llm_topology import TopologyAnswer, graph_from_answer
from mansion.planning.llm_topology import prompt_values as topology_values
from mansion.planning.preview import outline_png
from mansion.planning.planner import read_brief

if TYPE_CHECKING:
    from mansion.planning.planner import Constraints

__all__ = ["AnthropicBuildingPlanner"]

class AnthropicBuildingPlanner:
    """Claude as the building planner, floor planner and seed planner.

    ``llm`` defaults to an :class:`LLMClient` built from the environment (``ANTHROPIC_API_KEY``,
    ``MANSION_MODEL``); ``seed_planning=False`` leaves the cutting node to the offline heuristic
    (fewer calls: one per cut round is the bulk of a building's cost).
    """

    name = "anthropic"

    def __init__(self, llm: LLMClient | None = None, *, seed_planning: bool = True) -> None:
        self.llm = llm if llm is not None else LLMClient()
        self.seed_planning = seed_planning
        self._palette: Palette | None = None

    def plan_program(
        self, description: str, constraints: Constraints, rng: random.Random
    ) -> tuple[BuildingProgram, Palette]:
        brief = read_brief(description, constraints, rng)
        frame = Frame.resolve(brief.request, brief.key, brief.typology, brief.options, brief.palette, rng)
        values = program_values(frame, description, brief.key)
        system, user = load_prompt("building_program").render(**values)
        ground = frame.outlines[0]
        content = [image_block(outline_png(ground[0], ground[1])), {"type": "text", "text": user}]
        program = self.llm.ask(
            "building_program", system, content, ProgramAnswer,
            lambda answer: program_from_answer(answer, frame, rng),
        )
        assert isinstance(program, BuildingProgram)
        self._palette = brief.palette
        return program, brief.palette

    def plan_topology(self, program: BuildingProgram, index: int) -> RoomGraph:
        if isinstance(program.floors[index], FloorCopy):
            raise PlannerError(f"floor {index} is a copy; it has no topology of its own")
        hints = palette_text(self._palette) if self._palette is not None else (
            "use the materials the program gives each room"
        )
        system, user = load_prompt("floor_topology").render(**topology_values(program, index, hints))
        graph = self.llm.ask(
            "floor_topology", system, [{"type": "text", "text": user}], TopologyAnswer,
            lambda answer: graph_from_answer(answer, program, index),
        )
        assert isinstance(graph, RoomGraph)
        return graph

    def seed_planner(
        self, program: BuildingProgram, index: int, graph: RoomGraph, footprint: Footprint
    ) -> AnthropicSeedPlanner | None:
        """The cutting node's planner for floor ``index`` (None: the offline heuristic)."""
        if not self.seed_planning:
            return None
        return AnthropicSeedPlanner(
            self.llm, footprint=footprint, graph=graph,
            requirement=program.floor_program(index).requirement,
        )
