"""Settling placed objects in AI2-THOR (optional: ``mansion edit --settle``, needs the simulator).

The tools place objects by their bounding boxes; the simulator then lets physics settle them (an
apple rolls a few millimetres, a bottle leans on a fridge shelf). Each edited floor is loaded
with ``controller.reset(scene=house)`` and every object the tools added or moved takes the centre
of its axis-aligned bounding box from the simulator's object metadata (``position`` in the house
JSON is that centre, not the simulator's pivot), written back into the house the variant saves.
An object the simulator does not report, or reports having fallen off its receptacle, fails the
edit: the geometric placement was wrong, not something to hide.

The simulator's Unity build could not be downloaded where this was written: this is tested
against a stand-in controller that answers with object metadata, never against the real
simulator (as the environment's AI2-THOR backend, :mod:`mansion.sim.thor`).
"""

from __future__ import annotations

from typing import Any

from mansion.edit.tools import SceneTools
from mansion.exceptions import EditError

__all__ = ["settle"]

#: A settled object more than this far from where it was placed has fallen or been pushed (m).
DRIFT = 0.15


def settle(tools: SceneTools, controller: Any) -> list[str]:
    """Let the simulator settle every object the tools added or moved; returns one line per
    object ("settled <id>: moved 0.004 m")."""
    ws = tools.ws
    placed: dict[int, list[str]] = {}
    for e in tools.edits:
        if e.op in ("add", "move") and e.object_id in ws.floor(e.floor).objects:
            placed.setdefault(e.floor, []).append(e.object_id)
    out = []
    for k, ids in sorted(placed.items()):
        event = controller.reset(scene=ws.building.house(k).to_dict())
        meta = getattr(event, "metadata", None) or {}
        if not meta.get("lastActionSuccess", True):
            raise EditError(f"AI2-THOR refused floor {k}'s edited house: {meta.get('errorMessage', '')}")
        seen = {o.get("objectId"): o for o in meta.get("objects", [])}
        st = ws.floor(k)
        for oid in dict.fromkeys(ids):
            o = seen.get(oid)
            if o is None:
                raise EditError(f"AI2-THOR did not spawn {oid} on floor {k}")
            box = (o.get("axisAlignedBoundingBox") or {}).get("center") or o["position"]
            obj = st.objects[oid].obj
            drift = ((box["x"] - obj.position.x) ** 2 + (box["y"] - obj.position.y) ** 2
                     + (box["z"] - obj.position.z) ** 2) ** 0.5
            if drift > DRIFT:
                raise EditError(f"{oid} did not stay where it was placed on floor {k}: the simulator moved it {drift:.2f} m")
            obj.position.x, obj.position.y, obj.position.z = (round(box[a], 4) for a in ("x", "y", "z"))
            out.append(f"settled {oid} in AI2-THOR: moved {drift:.3f} m")
        ws.touch(k)
    return out
