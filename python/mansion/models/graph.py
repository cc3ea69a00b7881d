"""The per-floor room graph (the paper's bubble graph): rooms as nodes, required relations as edges.

Areas are in square metres. Node ``type`` is the node's structural role in the solver:

- ``main``: the circulation hub; the cut rounds start from it (exactly one per floor);
- ``Entities`` / ``area``: ordinary rooms;
- ``stair`` / ``elevator``: vertical cores, fixed in place by the footprint (their ids match
  :class:`mansion.models.Core` ids), so their area is ignored and may be 0.

``room_type`` is the open-vocabulary function of the room ("kitchen", "classroom", ...).

Validation problems are raised as :class:`mansion.exceptions.InvalidInputError`. When a model is
built directly (``RoomGraph(...)`` or ``RoomGraph.model_validate``) pydantic wraps that error in a
``pydantic.ValidationError`` (which is also a ``ValueError``); :meth:`RoomGraph.parse`,
:meth:`RoomGraph.load` and :func:`mansion.solve_floor` unwrap it into a single
``InvalidInputError`` with a readable message.
"""

from __future__ import annotations

import os
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

from mansion.exceptions import InvalidInputError
from mansion.models._validation import load_input, validate_input

__all__ = ["CORE_TYPES", "EdgeKind", "NodeType", "OpenRelation", "RoomEdge", "RoomGraph", "RoomNode"]

NodeType = Literal["main", "Entities", "area", "elevator", "stair"]
EdgeKind = Literal["access", "adjacent"]
OpenRelation = Literal["open", "door"]

#: Node types that are vertical cores: placed by the footprint, not grown by the solver.
CORE_TYPES: frozenset[str] = frozenset({"stair", "elevator"})


class RoomNode(BaseModel):
    """One room of the program (or one vertical core)."""

    model_config = ConfigDict(allow_inf_nan=False)

    id: str = Field(min_length=1)
    type: NodeType
    area: float = Field(ge=0.0, description="Target area in m²; > 0 except for cores.")
    room_type: str = Field(min_length=1, description="Function of the room; defaults to the id.")
    floor_material: str | None = None
    wall_material: str | None = None
    open_relation: OpenRelation = "door"
    min_width: float | None = Field(
        default=None,
        gt=0.0,
        description=(
            "Minimum clear width in metres: no part of the laid-out room may be narrower "
            "(None: no limit of its own). Planners fill it from the room design table."
        ),
    )
    min_area: float | None = Field(
        default=None,
        gt=0.0,
        description=(
            "The design table's minimum area in m²: with the solver's ``repair`` setting, a room "
            "left below it takes cells from a neighbour that can spare them (None: no minimum)."
        ),
    )
    clear_width: float | None = Field(
        default=None,
        gt=0.0,
        description=(
            "The design table's clear width in metres, which nine tenths of the room should have "
            "(``repair`` widens a room below it; ``min_width`` is the rule every candidate must meet)."
        ),
    )
    max_aspect: float | None = Field(
        default=None,
        gt=0.0,
        description="Longest side of the room's bounding box over its shortest (``repair``; None: any).",
    )

    @model_validator(mode="before")
    @classmethod
    def _default_room_type(cls, data: Any) -> Any:
        if isinstance(data, dict) and data.get("room_type") is None and "id" in data:
            data = {**data, "room_type": data["id"]}
        return data

    @model_validator(mode="after")
    def _check_area(self) -> RoomNode:
        if self.type not in CORE_TYPES and self.area <= 0.0:
            raise InvalidInputError(
                f"room {self.id!r} has area {self.area:g} m²; every non-core room needs an area > 0"
            )
        return self

    @property
    def is_core(self) -> bool:
        """True for stair and elevator nodes."""
        return self.type in CORE_TYPES


class RoomEdge(BaseModel):
    """A required relation between two rooms.

    ``access``: the rooms share a wall with a door or an opening (per the nodes' ``open_relation``);
    ``adjacent``: the rooms share a wall, no passage implied.
    """

    source: str = Field(min_length=1)
    target: str = Field(min_length=1)
    kind: EdgeKind = "access"


class RoomGraph(BaseModel):
    """The rooms of one floor and the relations the layout must realise.

    Edges are undirected for the layout: ``a -> b`` and ``b -> a`` name the same relation.
    """

    nodes: list[RoomNode]
    edges: list[RoomEdge] = Field(default_factory=list)

    @model_validator(mode="after")
    def _check_structure(self) -> RoomGraph:
        self.check()
        return self

    def check(self) -> None:
        """Raise :class:`InvalidInputError` unless ids are unique, every edge joins two distinct
        known nodes, no relation is given twice, and there is exactly one ``main`` node."""
        seen: set[str] = set()
        for node in self.nodes:
            if node.id in seen:
                raise InvalidInputError(f"duplicate room id {node.id!r} in the room graph")
            seen.add(node.id)

        pairs: dict[frozenset[str], int] = {}
        for i, edge in enumerate(self.edges):
            label = f"edge {i} ({edge.source!r} -> {edge.target!r})"
            for end in (edge.source, edge.target):
                if end not in seen:
                    raise InvalidInputError(f"{label} references unknown room {end!r}")
            if edge.source == edge.target:
                raise InvalidInputError(f"{label} is a self-loop on room {edge.source!r}")
            key = frozenset((edge.source, edge.target))
            if key in pairs:
                raise InvalidInputError(
                    f"{label} duplicates edge {pairs[key]} between {edge.source!r} and "
                    f"{edge.target!r}; give each relation once"
                )
            pairs[key] = i

        mains = [n.id for n in self.nodes if n.type == "main"]
        if not mains:
            raise InvalidInputError(
                "the room graph has no 'main' (hub) node; exactly one is required"
            )
        if len(mains) > 1:
            names = ", ".join(repr(m) for m in mains)
            raise InvalidInputError(
                f"the room graph has {len(mains)} 'main' (hub) nodes ({names}); "
                "exactly one is required"
            )

    # -- construction helpers ------------------------------------------------------------------

    @classmethod
    def parse(cls, data: RoomGraph | dict[str, Any]) -> RoomGraph:
        """Validate a RoomGraph or a plain dict; every problem is an :class:`InvalidInputError`."""
        return validate_input(cls, data, "room graph")

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> RoomGraph:
        """Read a room graph from a JSON file; every problem is an :class:`InvalidInputError`."""
        return load_input(cls, path, "room graph")

    # -- queries -------------------------------------------------------------------------------

    @property
    def hub(self) -> RoomNode:
        """The ``main`` node, where the cut rounds start."""
        for node in self.nodes:
            if node.type == "main":
                return node
        raise InvalidInputError("the room graph has no 'main' (hub) node")

    def node(self, id: str) -> RoomNode:
        """The node with this id; ``KeyError`` if there is none."""
        for node in self.nodes:
            if node.id == id:
                return node
        raise KeyError(f"no room {id!r} in the room graph")

    def neighbours(self, id: str) -> list[str]:
        """Ids of the rooms joined to ``id`` by an edge of either direction, in edge order."""
        self.node(id)
        out: list[str] = []
        for edge in self.edges:
            other = edge.target if edge.source == id else edge.source if edge.target == id else None
            if other is not None and other not in out:
                out.append(other)
        return out
