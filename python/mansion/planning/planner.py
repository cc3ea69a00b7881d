"""The planner interface of the building pipeline, and the offline planner behind it.

A :class:`BuildingPlanner` answers the paper's two planning questions: the whole-building program
(``plan_program``) and one floor's topology (``plan_topology``). The offline planner answers from
rules of thumb and the seed; an LLM planner (Claude with the paper's prompt templates) answers
the same two calls (:class:`mansion.planning.llm.AnthropicBuildingPlanner`), so the pipeline in
:mod:`mansion.building` does not change with the planner. Choosing a planner by name is
:mod:`mansion.planning.planners`' job, so this module never imports the LLM planner (which
imports :func:`read_brief` from here).
"""

from __future__ import annotations

import random
from dataclasses import dataclass
from typing import Protocol, runtime_checkable

from mansion.exceptions import PlannerError
from mansion.models.building import BuildingProgram, FloorProgram, Palette
from mansion.models.graph import RoomGraph
from mansion.planning.description import Request, parse_description
from mansion.planning.footprints import Outline
from mansion.planning.palette import choose_palette
from mansion.planning.program import ProgramOptions, plan_program, typology
from mansion.planning.topology import floor_graph
from mansion.planning.typologies import TYPOLOGIES, Typology

__all__ = [
    "Brief",
    "BuildingPlanner",
    "Constraints",
    "OfflinePlanner",
    "read_brief",
]

#: Used when the description names no known building type.
DEFAULT_BUILDING_TYPE = "office"


@dataclass(frozen=True)
class Constraints:
    """The numeric constraints the caller gave (None: the planner resolves them)."""

    floors: int | None = None
    area: float | None = None
    outline: Outline | None = None
    max_floor_area: float = 500.0
    building_type: str | None = None
    load_bearing: bool | None = None
    #: How far to relax the program (0: not at all; see ProgramOptions.relax).
    relax: int = 0


@dataclass(frozen=True)
class Brief:
    """What every planner starts from: the parsed description, the building type (key and rules
    of thumb), the chief designer's palette and the caller's constraints as program options."""

    request: Request
    key: str
    typology: Typology
    palette: Palette
    options: ProgramOptions


def read_brief(description: str, constraints: Constraints, rng: random.Random) -> Brief:
    """Parse the description, settle the building type and choose the palette (from ``rng``)."""
    request = parse_description(description)
    key = constraints.building_type or request.building_type or DEFAULT_BUILDING_TYPE
    typ = typology(key)
    palette = choose_palette(typ.family, rng)
    options = ProgramOptions(
        floors=constraints.floors, area=constraints.area, outline=constraints.outline,
        max_floor_area=constraints.max_floor_area, load_bearing=constraints.load_bearing,
        relax=constraints.relax,
    )
    return Brief(request, key, typ, palette, options)


@runtime_checkable
class BuildingPlanner(Protocol):
    """The building planner and floor planner of the paper, behind one interface."""

    name: str

    def plan_program(
        self, description: str, constraints: Constraints, rng: random.Random
    ) -> tuple[BuildingProgram, Palette]:
        """The building program and the building-wide palette (the chief designer's choice)."""
        ...

    def plan_topology(self, program: BuildingProgram, index: int) -> RoomGraph:
        """The room graph of floor ``index`` (not a copy), with every core on it as a node."""
        ...


class OfflinePlanner:
    """Rules of thumb, no network: see :mod:`mansion.planning.program`."""

    name = "offline"

    def plan_program(
        self, description: str, constraints: Constraints, rng: random.Random
    ) -> tuple[BuildingProgram, Palette]:
        brief = read_brief(description, constraints, rng)
        return plan_program(brief.request, brief.key, brief.options, brief.palette, rng), brief.palette

    def plan_topology(self, program: BuildingProgram, index: int) -> RoomGraph:
        floor = program.floors[index]
        if not isinstance(floor, FloorProgram):
            raise PlannerError(f"floor {index} is a copy of floor {floor.copy_of}; it has no topology of its own")
        typ = TYPOLOGIES.get(program.building_type)
        adjacent = typ.ground.adjacent if typ is not None and index == 0 else ()
        if typ is not None and index > 0:
            template = typ.top if index == program.floor_count - 1 and typ.top else typ.upper
            adjacent = template.adjacent if template is not None else typ.ground.adjacent
        return floor_graph(floor, program.cores, adjacent, program.building_type)
