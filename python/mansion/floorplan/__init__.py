"""The single-floor solver stage: cut rounds driven by seed planners, energy weights, solve_floor."""

from mansion.models.seeds import (
    ChildSeed,
    FixedSeedPlanner,
    PlacedRoom,
    SeedBox,
    SeedChild,
    SeedDescendant,
    SeedPlan,
    SeedPlanner,
    SeedRegion,
    SeedRequest,
    SeedRequestLayout,
    planner_callback,
)
from mansion.floorplan.solve import build_options, solve_floor
from mansion.floorplan.weights import EnergyWeights, SolverSettings

__all__ = [
    "ChildSeed",
    "EnergyWeights",
    "FixedSeedPlanner",
    "PlacedRoom",
    "SeedBox",
    "SeedChild",
    "SeedDescendant",
    "SeedPlan",
    "SeedPlanner",
    "SeedRegion",
    "SeedRequest",
    "SeedRequestLayout",
    "SolverSettings",
    "build_options",
    "planner_callback",
    "solve_floor",
]
