"""The exceptions mansion raises.

The Rust binding (`mansion._core`) imports this module and raises these very classes, so a caller
can catch solver failures and Python-side validation failures with the same ``except`` clauses.
Keep the names stable: they are part of the binding contract.
"""

from __future__ import annotations

__all__ = [
    "InfeasibleLayoutError",
    "InvalidBuildingError",
    "InvalidInputError",
    "MansionError",
    "PlannerError",
]


class MansionError(Exception):
    """Base class of every error mansion raises on purpose."""


class InvalidInputError(MansionError, ValueError):
    """The room graph, footprint, options or another argument is malformed.

    The message names the offending room, edge, core or coordinate.
    """


class InfeasibleLayoutError(MansionError):
    """The inputs are well formed, but no retry and no fallback produced a valid layout."""


class PlannerError(MansionError):
    """A seed planner failed or returned a seed plan the solver cannot use."""


class InvalidBuildingError(MansionError):
    """A generated building failed a check before it was written (a floor's graph not connected,
    a core not where the other floors have it, a room that cannot be reached).

    The message names the floor and the room, edge or core at fault.
    """
