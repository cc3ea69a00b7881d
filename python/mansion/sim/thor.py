"""An optional AI2-THOR backend (``pip install mansion[ai2thor]``): the headless environment
decides every skill and the simulator mirrors it.

``BuildingEnv(path, backend=ThorBackend(controller))``: each floor is loaded with
``controller.reset(scene=house)`` (the paper's dynamic floor loading: the house JSON the skills
keep up to date, so a carried object is in the new floor's house), walks end with a
``TeleportFull`` to the pose the grid found, and the object skills are AI2-THOR's own actions
(``PickupObject``, ``PutObject``, ``OpenObject``, ``CloseObject``, ``RotateLeft/Right``). After a
floor change the agent is teleported to the core's landing and takes the carried object in hand
again. A skill the simulator refuses (``lastActionSuccess`` false) fails with the simulator's
``errorMessage`` and changes nothing in the headless state.

The simulator's Unity build could not be downloaded where this was written: the backend is
tested against a recording stand-in controller (the sequence of calls it receives), never
against the real simulator.
"""

from __future__ import annotations

from typing import Any

from mansion.exceptions import MansionError
from mansion.scene.poses import AGENT_Y

__all__ = ["ThorBackend", "thor_controller"]


def thor_controller(**kwargs: Any) -> Any:
    """A real ``ai2thor.controller.Controller`` (needs the ``ai2thor`` extra and a display or
    CloudRendering)."""
    try:
        from ai2thor.controller import Controller  # type: ignore[import-not-found]
    except ImportError as exc:
        raise MansionError("the AI2-THOR backend needs the simulator: pip install 'mansion[ai2thor]'") from exc
    return Controller(**kwargs)


class ThorBackend:
    def __init__(self, controller: Any, horizon: float = 30.0):
        self.controller = controller
        self.horizon = horizon

    def _ok(self, event: Any) -> tuple[bool, str]:
        meta = getattr(event, "metadata", None) or {}
        return bool(meta.get("lastActionSuccess", True)), str(meta.get("errorMessage", "") or "")

    def load_floor(self, house: dict[str, Any]) -> tuple[bool, str]:
        return self._ok(self.controller.reset(scene=house))

    def teleport(self, x: float, z: float, yaw: float) -> tuple[bool, str]:
        return self._ok(self.controller.step(
            action="TeleportFull", position={"x": x, "y": AGENT_Y, "z": z}, rotation={"x": 0.0, "y": yaw, "z": 0.0},
            horizon=self.horizon, standing=True,
        ))

    def pickup(self, object_id: str) -> tuple[bool, str]:
        return self._ok(self.controller.step(action="PickupObject", objectId=object_id, forceAction=True))

    def put(self, object_id: str, receptacle_id: str) -> tuple[bool, str]:
        return self._ok(self.controller.step(action="PutObject", objectId=receptacle_id, forceAction=True))

    def open(self, object_id: str) -> tuple[bool, str]:
        return self._ok(self.controller.step(action="OpenObject", objectId=object_id, forceAction=True))

    def close(self, object_id: str) -> tuple[bool, str]:
        return self._ok(self.controller.step(action="CloseObject", objectId=object_id, forceAction=True))

    def rotate(self, direction: str, degrees: float) -> tuple[bool, str]:
        return self._ok(self.controller.step(action=f"Rotate{direction}", degrees=degrees))
