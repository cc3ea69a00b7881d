"""The exceptions mansion raises.

The Rust binding (`mansion._core`) imports this module and raises these very classes, so a caller
can catch solver failures and Python-side validation failures with the same ``except`` clauses.
Keep the names stable: they are part of the binding contract.
"""

from __future__ import annotations

__all__ = [
    "ContainerClosedError",
    "EditError",
    "IncompatibleReceptacleError",
    "InfeasibleLayoutError",
    "InvalidBuildingError",
    "InvalidInputError",
    "MansionError",
    "PlannerError",
    "SurfaceFullError",
    "UnknownObjectError",
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


class EditError(MansionError):
    """A scene edit (``mansion edit``, :mod:`mansion.edit`) cannot be made; the message names the
    object, receptacle or floor at fault."""


class UnknownObjectError(EditError, InvalidInputError):
    """No object, receptacle, room or asset of that id (or an id on several floors: give one)."""


class SurfaceFullError(EditError):
    """No free spot on (or in) the receptacle for the object without overlapping what is there."""


class ContainerClosedError(EditError):
    """The container is closed: nothing can be put inside until it is opened."""


class IncompatibleReceptacleError(EditError):
    """The receptacle cannot take the object: not a receptacle, the wrong kind (a surface for a
    container), too small, or a type AI2-THOR's receptacle database never puts there."""
