"""The planning stage: description → building program → per-floor room graphs.

:class:`BuildingPlanner` is the interface; :class:`OfflinePlanner` answers it from rules of thumb
(:mod:`~mansion.planning.typologies`, :mod:`~mansion.planning.bays`) with no API key.
"""

from mansion.planning.description import Placement, Request, parse_description
from mansion.planning.planner import BuildingPlanner, Constraints, OfflinePlanner
from mansion.planning.planners import PLANNERS, get_planner
from mansion.planning.program import DEFAULT_MAX_FLOOR_AREA, MAX_FLOORS

__all__ = [
    "DEFAULT_MAX_FLOOR_AREA",
    "MAX_FLOORS",
    "PLANNERS",
    "BuildingPlanner",
    "Constraints",
    "OfflinePlanner",
    "Placement",
    "Request",
    "get_planner",
    "parse_description",
]
