"""Object placement (issue 6): object plans per room, assets from AI2-THOR's database, the Rust
placement engine with guaranteed reachability, and export to AI2-THOR ``objects`` entries.

Stages: an object planner (:func:`plan_objects` offline, :class:`LLMObjectPlanner` with Claude)
writes an :class:`~mansion.models.objects.ObjectPlan`; :func:`furnish_room` picks assets by size
and runs the engine; :func:`thor_objects` exports; :func:`furnish_floor` does every room of a
floor of a :class:`mansion.Building`.
"""

from mansion.placement.floor import furnish_floor, layout_doors
from mansion.placement.offline import plan_objects, room_kind
from mansion.placement.place import PlaceOptions, RoomSpec, furnish_room, furnish_rooms, thor_objects

__all__ = [
    "PlaceOptions",
    "RoomSpec",
    "furnish_floor",
    "furnish_room",
    "furnish_rooms",
    "layout_doors",
    "plan_objects",
    "room_kind",
    "thor_objects",
]
