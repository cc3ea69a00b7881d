"""mansion: the MANSION paper's building generator, a Rust floorplan core under a Python API.

The heart of the API is :func:`solve_floor`, which partitions a footprint into the rooms of a room
graph, :func:`generate_building`, which plans and solves a whole multi-floor building from a
description, and :func:`plot_layout`, which draws a floor.
"""

from mansion.building import generate_building
from mansion.exceptions import (
    InfeasibleLayoutError,
    InvalidBuildingError,
    InvalidInputError,
    MansionError,
    PlannerError,
)
from mansion.floorplan import (
    ChildSeed,
    EnergyWeights,
    FixedSeedPlanner,
    SeedBox,
    SeedPlan,
    SeedPlanner,
    SeedRequest,
    SolverSettings,
    solve_floor,
)
from mansion.models import (
    Adjacency,
    Building,
    Core,
    Diagnostics,
    FloorLayout,
    Footprint,
    LabelGrid,
    LayoutRoom,
    RoomEdge,
    RoomGraph,
    RoomNode,
    RoundDiagnostics,
)
from mansion.plot import plot_layout


def _version() -> str:
    try:
        from mansion._core import __version__ as core_version
    except ImportError:
        # Only a source checkout without a built core gets here; solve_floor will then say how to
        # build it.
        return "0+unknown"
    return str(core_version)


__version__ = _version()

__all__ = [
    "Adjacency",
    "Building",
    "ChildSeed",
    "Core",
    "Diagnostics",
    "EnergyWeights",
    "FixedSeedPlanner",
    "FloorLayout",
    "Footprint",
    "InfeasibleLayoutError",
    "InvalidBuildingError",
    "InvalidInputError",
    "LabelGrid",
    "LayoutRoom",
    "MansionError",
    "PlannerError",
    "RoomEdge",
    "RoomGraph",
    "RoomNode",
    "RoundDiagnostics",
    "SeedBox",
    "SeedPlan",
    "SeedPlanner",
    "SeedRequest",
    "SolverSettings",
    "__version__",
    "generate_building",
    "plot_layout",
    "solve_floor",
]
