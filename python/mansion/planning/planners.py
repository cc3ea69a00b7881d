"""The planners by name, as ``--planner`` offers them.

A registry of its own: :mod:`mansion.planning.llm` builds on :mod:`mansion.planning.planner`
(the brief every planner reads), so the choice between the two lives above both and neither
imports the other back.
"""

from __future__ import annotations

from collections.abc import Callable

from mansion.exceptions import PlannerError
from mansion.planning.planner import BuildingPlanner, OfflinePlanner

__all__ = ["PLANNERS", "get_planner"]


def _anthropic() -> BuildingPlanner:
    # Imported here: the offline path never pays for the LLM modules.
    from mansion.planning.llm import AnthropicBuildingPlanner

    return AnthropicBuildingPlanner()


#: Planner factories by name.
PLANNERS: dict[str, Callable[[], BuildingPlanner]] = {"offline": OfflinePlanner, "anthropic": _anthropic}


def get_planner(name: str | BuildingPlanner) -> BuildingPlanner:
    """The planner called ``name`` (or ``name`` itself when it already is a planner)."""
    if isinstance(name, BuildingPlanner):
        return name
    if name not in PLANNERS:
        raise PlannerError(f"unknown planner {name!r}; choose from {', '.join(PLANNERS)}")
    return PLANNERS[name]()
