"""The building model → OpenUSD through usd-core (``pxr``), laid out for NVIDIA Isaac Sim.

One Xform per floor (translated to its elevation), per room and per group; UsdGeom meshes with a
UsdPreviewSurface material each; ``PhysicsCollisionAPI`` on walls, slabs, stairs, doors,
windows and fixed furniture (triangle-mesh colliders), ``PhysicsRigidBodyAPI`` with a convex-hull
collider on every object the agent can move; a physics scene with gravity along -y. metres, y up.
A node's ids (house JSON id, asset id, ...) are in its prim's ``customData["mansion"]``.
"""

from __future__ import annotations

import os
import re
import tempfile
from pathlib import Path
from typing import Any

from mansion._io import atomic_write_bytes, atomic_write_text
from mansion.export.model import BuildingModel, Look, Node

__all__ = ["prim_name", "write_usd"]


def prim_name(text: str) -> str:
    """A valid USD prim name for ``text`` (letters, digits and _; not starting with a digit)."""
    name = re.sub(r"[^A-Za-z0-9_]", "_", text)
    return name if name and not name[0].isdigit() else f"_{name}"


def _local(node: Node, parent: Node | None) -> str:
    if parent is not None and node.name.startswith(parent.name + "/"):
        return node.name[len(parent.name) + 1 :]
    return node.name.rsplit("/", 1)[-1]


def _stage(model: BuildingModel) -> Any:
    from pxr import Gf, Sdf, Usd, UsdGeom, UsdPhysics, UsdShade, Vt

    stage = Usd.Stage.CreateInMemory()
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.y)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    UsdPhysics.SetStageKilogramsPerUnit(stage, 1.0)
    root_path = Sdf.Path("/" + prim_name(model.root.name))
    looks: dict[Look, Any] = {}

    def material(look: Look) -> Any:
        if look not in looks:
            path = root_path.AppendChild("Looks").AppendChild(prim_name(look.name))
            while stage.GetPrimAtPath(path):
                path = path.GetParentPath().AppendChild(path.name + "_")
            mat = UsdShade.Material.Define(stage, path)
            shader = UsdShade.Shader.Define(stage, path.AppendChild("PreviewSurface"))
            shader.CreateIdAttr("UsdPreviewSurface")
            r, g, b, a = look.rgba
            shader.CreateInput("diffuseColor", Sdf.ValueTypeNames.Color3f).Set(Gf.Vec3f(r, g, b))
            shader.CreateInput("opacity", Sdf.ValueTypeNames.Float).Set(float(a))
            shader.CreateInput("roughness", Sdf.ValueTypeNames.Float).Set(0.8)
            mat.CreateSurfaceOutput().ConnectToSource(shader.ConnectableAPI(), "surface")
            looks[look] = mat
        return looks[look]

    def mesh_prim(path: Any, node: Node) -> Any:
        assert node.mesh is not None
        v, f = node.mesh
        mesh = UsdGeom.Mesh.Define(stage, path)
        mesh.CreatePointsAttr(Vt.Vec3fArray.FromNumpy(v.astype("float32")))
        mesh.CreateFaceVertexCountsAttr(Vt.IntArray([3] * len(f)))
        mesh.CreateFaceVertexIndicesAttr(Vt.IntArray.FromNumpy(f.reshape(-1).astype("int32")))
        mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
        lo, hi = v.min(axis=0), v.max(axis=0)
        mesh.CreateExtentAttr(Vt.Vec3fArray([Gf.Vec3f(*map(float, lo)), Gf.Vec3f(*map(float, hi))]))
        if node.look is not None:
            mesh.CreateDisplayColorAttr(Vt.Vec3fArray([Gf.Vec3f(*node.look.rgba[:3])]))
            if node.look.rgba[3] < 1.0:
                mesh.CreateDisplayOpacityAttr(Vt.FloatArray([node.look.rgba[3]]))
            UsdShade.MaterialBindingAPI.Apply(mesh.GetPrim()).Bind(material(node.look))
        prim = mesh.GetPrim()
        if node.physics in ("collider", "rigid"):
            UsdPhysics.CollisionAPI.Apply(prim)
            collider = UsdPhysics.MeshCollisionAPI.Apply(prim)
            # PhysX moves only convex shapes; fixed ones keep their exact triangles.
            collider.CreateApproximationAttr("convexHull" if node.physics == "rigid" else "none")
        if node.physics == "rigid":
            UsdPhysics.RigidBodyAPI.Apply(prim)
        return prim

    def add(node: Node, parent: Node | None, parent_path: Any) -> None:
        path = parent_path.AppendChild(prim_name(_local(node, parent)))
        while stage.GetPrimAtPath(path):  # two ids that read the same once made prim names
            path = parent_path.AppendChild(path.name + "_")
        has_mesh = node.mesh is not None and len(node.mesh[1]) > 0
        if has_mesh and not node.children:
            prim = mesh_prim(path, node)
        else:
            # a gprim may not have children: the node is an Xform, its own mesh a child of it
            prim = UsdGeom.Xform.Define(stage, path).GetPrim()
            if has_mesh:
                mesh_prim(path.AppendChild("mesh"), node)
        if any(node.offset) or node.kind == "floor":
            UsdGeom.Xformable(prim).AddTranslateOp().Set(Gf.Vec3d(*node.offset))
        prim.SetCustomData({"mansion": {"kind": node.kind, "name": node.name, "physics": node.physics, **node.info}})
        for child in node.children:
            add(child, node, path)

    add(model.root, None, Sdf.Path.absoluteRootPath)
    stage.SetDefaultPrim(stage.GetPrimAtPath(root_path))
    scene = UsdPhysics.Scene.Define(stage, root_path.AppendChild("PhysicsScene"))
    scene.CreateGravityDirectionAttr(Gf.Vec3f(0.0, -1.0, 0.0))
    scene.CreateGravityMagnitudeAttr(9.81)
    return stage


def write_usd(model: BuildingModel, path: str | os.PathLike[str]) -> Path:
    """Write ``model`` as USD: text for ``.usda``, binary crate for ``.usd`` and ``.usdc``."""
    target = Path(path)
    stage = _stage(model)
    if target.suffix.lower() == ".usda":
        return atomic_write_text(target, stage.GetRootLayer().ExportToString())
    with tempfile.TemporaryDirectory() as tmp:
        scratch = Path(tmp) / f"building{target.suffix.lower()}"
        stage.GetRootLayer().Export(str(scratch))
        return atomic_write_bytes(target, scratch.read_bytes())
