"""The building model → binary glTF (``.glb``) through trimesh, for Blender and any glTF viewer.

Every model node is a glTF node (floors translated to their elevations), its ids in the node's
``extras``; meshes carry a PBR material with the look's colour (glass blended).
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from mansion._io import atomic_write_bytes
from mansion.export.model import BuildingModel, Look, Node

__all__ = ["write_gltf"]


def _scene(model: BuildingModel):  # type: ignore[no-untyped-def]
    import trimesh
    from trimesh.visual.material import PBRMaterial

    scene = trimesh.Scene(base_frame="world")
    materials: dict[Look, PBRMaterial] = {}

    def material(look: Look) -> PBRMaterial:
        if look not in materials:
            rgba = [int(round(255 * c)) for c in look.rgba]
            materials[look] = PBRMaterial(
                name=look.name, baseColorFactor=rgba, metallicFactor=0.0, roughnessFactor=0.8,
                alphaMode="BLEND" if look.rgba[3] < 1.0 else "OPAQUE", doubleSided=look.rgba[3] < 1.0,
            )
        return materials[look]

    def add(node: Node, parent: str) -> None:
        matrix = np.eye(4)
        matrix[:3, 3] = node.offset
        extras = {"kind": node.kind, "physics": node.physics, **node.info}
        if node.mesh is not None and len(node.mesh[1]):
            v, f = node.mesh
            mesh = trimesh.Trimesh(v, f, process=False)
            if node.look is not None:
                mesh.visual = trimesh.visual.TextureVisuals(material=material(node.look))
            scene.geometry[node.name] = mesh
            scene.graph.update(frame_to=node.name, frame_from=parent, matrix=matrix, geometry=node.name, metadata=extras)
        else:
            scene.graph.update(frame_to=node.name, frame_from=parent, matrix=matrix, metadata=extras)
        for child in node.children:
            add(child, node.name)

    add(model.root, "world")
    return scene


def write_gltf(model: BuildingModel, path: str | os.PathLike[str]) -> Path:
    """Write ``model`` as GLB (binary glTF 2.0; y up, metres, as glTF itself)."""
    data = _scene(model).export(file_type="glb")
    return atomic_write_bytes(path, data)
