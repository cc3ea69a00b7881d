"""Object placement (issue 6): object plans per room, assets from AI2-THOR's database, the Rust
placement engine with guaranteed reachability, and export to AI2-THOR ``objects`` entries.

Stages: an object planner (:func:`plan_objects` offline, :class:`LLMObjectPlanner` with Claude)
writes an :class:`~mansion.models.objects.ObjectPlan`; :func:`furnish_room` picks assets by size
and runs the engine; :func:`thor_objects` exports. The scene stage furnishes every room of a
building's floors around their real doors (:mod:`mansion.scene.furnish`).
"""

from mansion.placement.offline import plan_objects, room_kind
from mansion.placement.place import (
    Entrance,
    PlaceOptions,
    RoomSpec,
    Spot,
    furnish_room,
    furnish_rooms,
    thor_objects,
)

__all__ = [
    "Entrance",
    "PlaceOptions",
    "RoomSpec",
    "Spot",
    "furnish_room",
    "furnish_rooms",
    "plan_objects",
    "room_kind",
    "thor_objects",
]
