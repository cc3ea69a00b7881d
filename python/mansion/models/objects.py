"""Object plans and placed objects (issue 6): what a room should hold and where it went.

An :class:`ObjectPlan` is what an object planner (offline or LLM) writes for one room: items with
the paper's three constraint kinds, a global tag (``edge`` / ``middle`` / ``unconstrained``), a
structure (``single``, ``matrix`` rows × cols, or ``paired`` with a partner) and optional
relations (``near`` / ``far`` / ``face``). A :class:`RoomPlacement` is the engine's answer, in plan
coordinates (metres, x right, y up; yaw in degrees as in AI2-THOR, 0 facing +y).
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, Field, model_validator

from mansion.exceptions import InvalidInputError

__all__ = [
    "ObjectItem",
    "ObjectPlan",
    "PlacedChild",
    "PlacedObject",
    "Relation",
    "RoomPlacement",
]

Tag = Literal["edge", "middle", "unconstrained"]
Side = Literal["front", "back", "left", "right", "sides", "around"]


class Relation(BaseModel):
    kind: Literal["near", "far", "face"]
    target: str = Field(min_length=1, description="Id of another item of the same plan.")


class ObjectItem(BaseModel):
    """One line of an object plan."""

    id: str = Field(min_length=1)
    object_type: str = Field(min_length=1, description="An AI2-THOR object type, e.g. Desk.")
    tag: Tag = "unconstrained"
    structure: Literal["single", "matrix", "paired"] = "single"
    rows: int = Field(default=1, ge=1, le=30)
    cols: int = Field(default=1, ge=1, le=30)
    row_gap: float = Field(default=0.8, ge=0.0, le=5.0, description="Aisle between matrix rows, m.")
    col_gap: float = Field(default=0.6, ge=0.0, le=5.0, description="Aisle between matrix columns, m.")
    partner: str | None = None
    side: Side | None = None
    count: int = Field(default=1, ge=1, le=12)
    tuck: float = Field(default=0.0, ge=0.0, lt=1.0)
    relations: list[Relation] = Field(default_factory=list)
    max_width: float | None = Field(default=None, gt=0.0)
    max_depth: float | None = Field(default=None, gt=0.0)
    small_objects: int = Field(default=0, ge=0, le=12, description="Small objects to try on its top.")

    @model_validator(mode="after")
    def _structure(self) -> ObjectItem:
        if self.structure == "paired" and (self.partner is None or self.side is None):
            raise InvalidInputError(f"item {self.id}: a paired item needs a partner and a side")
        if self.structure != "paired" and self.partner is not None:
            raise InvalidInputError(f"item {self.id}: only a paired item has a partner")
        return self


class ObjectPlan(BaseModel):
    room_id: str
    room_type: str
    items: list[ObjectItem]

    @model_validator(mode="after")
    def _references(self) -> ObjectPlan:
        ids = [i.id for i in self.items]
        dup = {i for i in ids if ids.count(i) > 1}
        if dup:
            raise InvalidInputError(f"room {self.room_id}: item ids {sorted(dup)} appear twice")
        by_id = {i.id: i for i in self.items}
        for it in self.items:
            if it.partner is not None:
                p = by_id.get(it.partner)
                if p is None:
                    raise InvalidInputError(f"room {self.room_id}: {it.id} is paired with unknown {it.partner}")
                if p.structure == "paired":
                    raise InvalidInputError(
                        f"room {self.room_id}: {it.id} is paired with {p.id}, which is itself paired"
                    )
            for r in it.relations:
                if r.target not in by_id or r.target == it.id:
                    raise InvalidInputError(f"room {self.room_id}: {it.id} relates to unknown {r.target}")
        return self


class PlacedChild(BaseModel):
    id: str
    object_type: str
    asset_id: str
    size: tuple[float, float, float]
    center: tuple[float, float]
    elevation: float
    yaw: float


class PlacedObject(BaseModel):
    id: str
    item: str
    object_type: str
    asset_id: str
    size: tuple[float, float, float] = Field(description="width, depth, height of the asset, m.")
    center: tuple[float, float]
    yaw: float
    has_front: bool
    group: str
    tucked_under: str | None
    interaction: tuple[float, float]
    children: list[PlacedChild]


class Dropped(BaseModel):
    item: str
    count: int
    reason: str


class MatrixOutcome(BaseModel):
    item: str
    requested: tuple[int, int]
    placed: tuple[int, int]


class PlacementStats(BaseModel):
    candidates: int
    reach_tests: int
    flood_fills: int
    seconds: float


class RoomPlacement(BaseModel):
    """The engine's result for one room, plus the room it was made for."""

    room_id: str
    polygon: list[tuple[float, float]]
    doors: list[tuple[tuple[float, float], tuple[float, float]]]
    agent_radius: float
    objects: list[PlacedObject]
    dropped: list[Dropped]
    matrices: list[MatrixOutcome]
    stats: PlacementStats

    @property
    def small_count(self) -> int:
        return sum(len(o.children) for o in self.objects)
