"""Furniture and small objects as boxes sized from AI2-THOR's asset database (the asset meshes
ship inside the simulator, not in any package we can read)."""

from __future__ import annotations

import math

import numpy as np

from mansion.export.looks import object_look
from mansion.export.meshes import box, transformed
from mansion.export.model import Node
from mansion.scene.databases import asset_ids
from mansion.scene.house import HouseObject

__all__ = ["object_nodes"]

_UNKNOWN = {"x": 0.3, "y": 0.3, "z": 0.3}


def _object_node(obj: HouseObject, floor: str, parent: str | None) -> Node:
    rec = asset_ids().get(obj.asset_id)
    bb = rec["boundingBox"] if rec else _UNKNOWN
    kind = rec["objectType"] if rec else "Unknown"
    sx, sy, sz = bb["x"], bb["y"], bb["z"]
    # position is the centre of the object's box; its yaw turns +z toward +x.
    yaw = math.radians(obj.rotation.y)
    m = np.eye(4)
    m[:3, :3] = [[math.cos(yaw), 0.0, math.sin(yaw)], [0.0, 1.0, 0.0], [-math.sin(yaw), 0.0, math.cos(yaw)]]
    m[:3, 3] = [obj.position.x, obj.position.y, obj.position.z]
    mesh = transformed(box((-sx / 2, -sy / 2, -sz / 2), (sx / 2, sy / 2, sz / 2)), m)
    info: dict[str, str | float | int] = {"id": obj.id, "assetId": obj.asset_id, "objectType": kind}
    if parent is not None:
        info["parent"] = parent
    if rec is None:
        info["note"] = "asset not in the asset database; a 0.3 m box"
    return Node(f"{floor}/{obj.id}", "object", mesh=mesh, look=object_look(kind),
                physics="collider" if obj.kinematic else "rigid", info=info)


def object_nodes(objects: list[HouseObject], floor: str) -> list[tuple[str | None, Node]]:
    """(room id, node) for every object and, flat beside it, every object it carries (so a
    simulator never meets a rigid body nested in another; the parent's id is in ``info``)."""
    out: list[tuple[str | None, Node]] = []

    def visit(obj: HouseObject, parent: HouseObject | None) -> None:
        room = obj.room if obj.room is not None else (parent.room if parent is not None else None)
        out.append((room, _object_node(obj, floor, parent.id if parent is not None else None)))
        for child in obj.children:
            visit(child, obj)

    for obj in objects:
        visit(obj, None)
    return out
