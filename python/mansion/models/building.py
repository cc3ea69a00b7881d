"""The whole building: its program, every floor's room graph, footprint and solved layout.

This is the format ``mansion generate`` writes as ``building.json`` and the one users keep, so it
carries a ``schema_version`` and round-trips through JSON exactly
(``Building.model_validate_json(b.model_dump_json()) == b``).

Vocabulary follows the paper: the *building program* (floors, outlines, vertical cores, per-floor
room programs whose first room is the circulation hub, ``{"index": k, "copy": j}`` floor copies),
the *palette* chosen once for the whole building by the chief designer, and a *room card* per room
(materials, openness, notes) that the later scene stages realise.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

from mansion._io import atomic_write_text
from mansion.exceptions import InvalidInputError
from mansion.models._validation import load_written
from mansion.models.footprint import Footprint, Point, Ring
from mansion.models.graph import OpenRelation, RoomGraph
from mansion.models.layout import FloorLayout

__all__ = [
    "BUILDING_SCHEMA_VERSION",
    "Building",
    "BuildingCore",
    "BuildingProgram",
    "ConnectivityMethod",
    "Floor",
    "FloorCopy",
    "FloorProgram",
    "Palette",
    "PositionWord",
    "ProgramRoom",
    "RoomCard",
    "RoomRequest",
]

#: Bumped on any change that an older reader could misread; readers refuse other major versions.
BUILDING_SCHEMA_VERSION = "1.0"

ConnectivityMethod = Literal["stair", "elevator", "stair_and_elevator"]


class ProgramRoom(BaseModel):
    """One room of a floor's program (the paper's program prompt: id, area estimate, materials).

    ``room_type`` is the function ("classroom", "ward"); ``zone`` groups rooms that the topology
    puts off one sub-hub (a wing, a unit, a department), ``None`` for rooms off the floor's hub.
    ``parent`` names the room this one is entered from instead (an ensuite from its guest room).
    """

    model_config = ConfigDict(allow_inf_nan=False)

    id: str = Field(min_length=1)
    room_type: str = Field(min_length=1)
    area: float = Field(gt=0.0, description="Area estimate in m².")
    zone: str | None = None
    parent: str | None = Field(
        default=None, description="The room it is entered from (None: its zone's sub-hub or the hub)."
    )
    floor_material: str = ""
    wall_material: str = ""
    notes: str = ""


class FloorProgram(BaseModel):
    """The program of one floor; its first room is the circulation hub."""

    model_config = ConfigDict(allow_inf_nan=False)

    index: int = Field(ge=0)
    requirement: str = ""
    outline: Ring = Field(description="The floor's outer outline in metres (x right, y up).")
    holes: list[Ring] = Field(default_factory=list, description="Courtyards inside the outline.")
    gross_floor_area: float = Field(gt=0.0)
    rooms: list[ProgramRoom] = Field(min_length=1)
    reserve_ratio: float = Field(
        ge=0.0, le=1.0, description="Share of the free area left to circulation (hub, sub-hubs)."
    )
    relaxations: list[str] = Field(
        default_factory=list,
        description="What the planner gave up to fit the floor (rooms dropped at their minimum size).",
    )


class FloorCopy(BaseModel):
    """The paper's shorthand for a floor identical to floor ``copy``."""

    index: int = Field(ge=0)
    copy_of: int = Field(ge=0, alias="copy")

    model_config = ConfigDict(populate_by_name=True, serialize_by_alias=True)


class BuildingCore(BaseModel):
    """A vertical core: the same box on every floor in ``floors``."""

    model_config = ConfigDict(allow_inf_nan=False)

    id: str = Field(min_length=1)
    type: Literal["stair", "elevator"]
    x: tuple[float, float]
    y: tuple[float, float]
    floors: list[int] = Field(min_length=1)


class RoomRequest(BaseModel):
    """A room the description asked for, and whether the building has it where it was asked.

    ``floors`` are the 0-based floors it was asked on (several for "on every floor"; empty for
    "anywhere"), ``built_on`` the floors that have it, ``room_ids`` its rooms there. When
    ``honoured`` is false, ``reason`` says why (a basement the planner does not build, a floor the
    building lacks, a floor too small to hold it at its minimum area).
    """

    phrase: str = Field(description="The words of the description, e.g. 'a nap room on the first floor'.")
    name: str = Field(description="The room as asked, e.g. 'nap room'.")
    room_type: str = Field(description="The room type built for it, e.g. 'sleep_room'.")
    how: str = Field(default="", description="How the name was read: synonym, spelling, head noun, named.")
    count: int = Field(ge=1)
    where: str = Field(default="", description="How the floor was read, e.g. 'ground floor'.")
    floors: list[int] = Field(default_factory=list)
    built_on: list[int] = Field(default_factory=list)
    room_ids: list[str] = Field(default_factory=list)
    honoured: bool = True
    reason: str = ""


class BuildingProgram(BaseModel):
    """The building planner's answer: floors, vertical connectivity, cores, per-floor programs."""

    model_config = ConfigDict(allow_inf_nan=False)

    building_type: str
    reasoning: str = ""
    floor_count: int = Field(ge=1)
    area_per_floor: float = Field(gt=0.0, description="Target gross area of the largest floor, m².")
    method: ConnectivityMethod | None = Field(
        default=None, description="Vertical connectivity; None for a single floor."
    )
    cores: list[BuildingCore] = Field(default_factory=list)
    floors: list[FloorProgram | FloorCopy]
    load_bearing_walls: bool = Field(
        default=False,
        description="Carry the walls of each floor's first cut round up as fixed walls.",
    )
    requests: list[RoomRequest] = Field(
        default_factory=list,
        description="The rooms the description asked for and whether each was honoured.",
    )

    @model_validator(mode="after")
    def _check_floors(self) -> BuildingProgram:
        if len(self.floors) != self.floor_count:
            raise InvalidInputError(
                f"the program lists {len(self.floors)} floors but floor_count = {self.floor_count}"
            )
        for i, floor in enumerate(self.floors):
            if floor.index != i:
                raise InvalidInputError(f"floor {i} of the program has index {floor.index}")
            if isinstance(floor, FloorCopy):
                if floor.copy_of >= i:
                    raise InvalidInputError(
                        f"floor {i} copies floor {floor.copy_of}; a copy must name a floor below it"
                    )
                if isinstance(self.floors[floor.copy_of], FloorCopy):
                    raise InvalidInputError(
                        f"floor {i} copies floor {floor.copy_of}, itself a copy; name the original"
                    )
        for core in self.cores:
            bad = [f for f in core.floors if not 0 <= f < self.floor_count]
            if bad:
                raise InvalidInputError(f"core {core.id!r} serves floors {bad} the building lacks")
        return self

    def floor_program(self, index: int) -> FloorProgram:
        """The program of floor ``index``, following a copy to its original."""
        floor = self.floors[index]
        if isinstance(floor, FloorCopy):
            floor = self.floors[floor.copy_of]
        assert isinstance(floor, FloorProgram)
        return floor


class Palette(BaseModel):
    """The building-wide style chosen once (the paper's chief designer).

    ``materials`` maps a material role ("living", "wet", "service", "circulation", ...) to a
    (floor, wall) description pair; room cards draw from it so every floor matches.
    """

    name: str
    style: str
    colour_scheme: str
    materials: dict[str, tuple[str, str]]


class RoomCard(BaseModel):
    """What the scene stages need to know about one room beyond its polygon."""

    id: str
    room_type: str
    floor_material: str
    wall_material: str
    open_relation: OpenRelation
    notes: str = ""


class PositionWord(BaseModel):
    """A statement of the description placing a room ("the kitchen in the north-east corner"):
    the room it is about, the statement, and whether the solved floor honours it."""

    room: str
    statement: str
    honoured: bool


class Floor(BaseModel):
    """One solved floor of the building."""

    index: int = Field(ge=0)
    copy_of: int | None = Field(default=None, description="The floor this one repeats, if any.")
    graph: RoomGraph
    footprint: Footprint
    layout: FloorLayout
    room_cards: list[RoomCard]
    rng_seed: int = Field(ge=0, description="The solver seed that produced the layout.")
    attempts: int = Field(ge=1, description="Solver attempts this floor took.")
    relaxations: list[str] = Field(
        default_factory=list, description="What was relaxed to solve this floor, if anything."
    )
    carried_walls: list[tuple[Point, Point]] = Field(
        default_factory=list,
        description="The load-bearing walls this floor passes to the floor above.",
    )
    held_regions: bool = Field(
        default=False,
        description=(
            "Whether the floors above hold their first-round regions, not only their rooms, off the walls this "
            "floor passes up: its hub took the arm of a region too narrow for its rooms, or the floor below's did."
        ),
    )
    position_words: list[PositionWord] = Field(
        default_factory=list,
        description="What the description said about where this floor's rooms go, and whether the layout honours it.",
    )


class Building(BaseModel):
    """A generated building: the description, the program and every floor, solved."""

    schema_version: str = BUILDING_SCHEMA_VERSION
    description: str
    seed: int = Field(ge=0)
    planner: str
    program: BuildingProgram
    palette: Palette
    floors: list[Floor]

    @model_validator(mode="after")
    def _check_version(self) -> Building:
        major = self.schema_version.split(".", 1)[0]
        if major != BUILDING_SCHEMA_VERSION.split(".", 1)[0]:
            raise InvalidInputError(
                f"building schema version {self.schema_version} is not readable by this mansion "
                f"(it reads {BUILDING_SCHEMA_VERSION})"
            )
        return self

    def to_json(self, path: str | os.PathLike[str], *, indent: int | None = 2) -> Path:
        """Write the building as JSON, atomically (temporary file + rename). Returns the path."""
        return atomic_write_text(path, self.model_dump_json(indent=indent) + "\n")

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> Building:
        """Read a building written by :meth:`to_json`; problems are :class:`InvalidInputError`."""
        return load_written(cls, path, "building file")
