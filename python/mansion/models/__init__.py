"""Pydantic data models shared by every stage: the room graph, the footprint, the solved layout and
the whole building.

Every model round-trips through JSON exactly: ``M.model_validate_json(m.model_dump_json()) == m``.
"""

from mansion.models.building import (
    BUILDING_SCHEMA_VERSION,
    Building,
    BuildingCore,
    BuildingProgram,
    Floor,
    FloorCopy,
    FloorProgram,
    Palette,
    ProgramRoom,
    RoomCard,
    RoomRequest,
)
from mansion.models.footprint import Core, Footprint, Point, Ring
from mansion.models.graph import CORE_TYPES, EdgeKind, NodeType, OpenRelation, RoomEdge, RoomGraph, RoomNode
from mansion.models.layout import (
    Adjacency,
    Diagnostics,
    FloorLayout,
    LabelGrid,
    LayoutRoom,
    RoomEnergy,
    RoundDiagnostics,
    RoundEnergy,
)

__all__ = [
    "BUILDING_SCHEMA_VERSION",
    "CORE_TYPES",
    "Building",
    "BuildingCore",
    "BuildingProgram",
    "Floor",
    "FloorCopy",
    "FloorProgram",
    "Palette",
    "ProgramRoom",
    "RoomCard",
    "RoomRequest",
    "Adjacency",
    "Core",
    "Diagnostics",
    "EdgeKind",
    "FloorLayout",
    "Footprint",
    "LabelGrid",
    "LayoutRoom",
    "NodeType",
    "OpenRelation",
    "Point",
    "Ring",
    "RoomEdge",
    "RoomEnergy",
    "RoomGraph",
    "RoomNode",
    "RoundDiagnostics",
    "RoundEnergy",
]
