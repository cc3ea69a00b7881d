"""``mansion export``: the building re-opened in trimesh (GLB) and pxr (USD) has every floor at its
elevation, every wall, door, window and object once, real stairs, slab openings over the cores,
and the building's footprint and height."""

from __future__ import annotations

import json
import re
import struct
from collections import Counter
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from shapely.geometry import Polygon
from shapely.geometry import box as rect
from shapely.ops import unary_union
from typer.testing import CliRunner

from mansion.building import generate_building
from mansion.cli import app
from mansion.exceptions import InvalidInputError
from mansion.scene import BuildingManifest, House, write_scenes

trimesh = pytest.importorskip("trimesh")

from mansion.export import FORMATS, building_model, export_building  # noqa: E402
from mansion.export.cores import MAX_RISE, MIN_GOING, flight_node, plan_core  # noqa: E402
from mansion.export.walls import SKIN  # noqa: E402

runner = CliRunner()
TOL = 1e-4


@pytest.fixture(scope="module")
def building(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A furnished three-storey office with a stair and two elevators."""
    out = tmp_path_factory.mktemp("office")
    b = generate_building("a three-storey office with two elevators", floors=3, seed=0)
    write_scenes(b, out / "scenes")
    return out


def _houses(building: Path) -> tuple[BuildingManifest, dict[int, House]]:
    manifest = BuildingManifest.load(building / "scenes" / "manifest.json")
    return manifest, {f.index: House.load(building / "scenes" / f.house) for f in manifest.floors}


def _expected_ids(house: House) -> Counter[tuple[str, str]]:
    """(kind, id) of every element a floor must export once."""
    out: Counter[tuple[str, str]] = Counter()
    out.update(("wall", w.id) for w in house.walls if not w.empty)
    out.update(("door", d.id) for d in house.doors)
    out.update(("window", w.id) for w in house.windows)

    def visit(objects: list[Any]) -> None:
        for o in objects:
            out[("object", o.id)] += 1
            visit(o.children)

    visit(house.objects)
    return out


def _glb_json(path: Path) -> dict[str, Any]:
    data = path.read_bytes()
    length = struct.unpack("<I", data[12:16])[0]
    return json.loads(data[20 : 20 + length])


class GlbReader:
    """What a test needs of a re-opened GLB: node → world matrix, extras, world-space mesh."""

    def __init__(self, path: Path) -> None:
        self.scene = trimesh.load(path, force="scene")
        self.extras: dict[str, dict[str, Any]] = {}
        for (_parent, child), data in self.scene.graph.transforms.edge_data.items():
            self.extras[child] = data.get("metadata", {})

    def names(self, kind: str) -> list[str]:
        return [n for n, e in self.extras.items() if e.get("kind") == kind]

    def matrix(self, name: str) -> np.ndarray:
        return self.scene.graph.get(name)[0]

    def has_mesh(self, name: str) -> bool:
        return self.scene.graph.get(name)[1] is not None

    def mesh(self, name: str) -> Any:
        geometry = self.scene.graph.get(name)[1]
        return self.scene.geometry[geometry].copy().apply_transform(self.matrix(name))

    def children(self, name: str) -> list[str]:
        return list(self.scene.graph.transforms.children.get(name, []))

    def bounds(self) -> np.ndarray:
        return np.asarray(self.scene.bounds)


class UsdReader:
    """The same questions asked of a USD stage opened with pxr; nodes are found by the name in
    their prims' ``customData["mansion"]``."""

    def __init__(self, path: Path) -> None:
        from pxr import Usd

        self.stage = Usd.Stage.Open(str(path))
        self.prims: dict[str, Any] = {}
        self.extras: dict[str, dict[str, Any]] = {}
        for prim in self.stage.Traverse():
            data = prim.GetCustomDataByKey("mansion")
            if data:
                assert data["name"] not in self.prims, f"{data['name']} twice"
                self.prims[data["name"]] = prim
                self.extras[data["name"]] = dict(data)

    def names(self, kind: str) -> list[str]:
        return [n for n, e in self.extras.items() if e.get("kind") == kind]

    def _world(self, prim: Any) -> np.ndarray:
        from pxr import Usd, UsdGeom

        # Gf matrices act on row vectors: transpose to the column convention trimesh uses.
        return np.array(UsdGeom.Xformable(prim).ComputeLocalToWorldTransform(Usd.TimeCode.Default())).T

    def matrix(self, name: str) -> np.ndarray:
        return self._world(self.prims[name])

    def _mesh_prim(self, name: str) -> Any:
        prim = self.prims[name]
        return prim if prim.GetTypeName() == "Mesh" else prim.GetChild("mesh")

    def has_mesh(self, name: str) -> bool:
        return bool(self._mesh_prim(name))

    def mesh(self, name: str) -> Any:
        from pxr import UsdGeom

        prim = self._mesh_prim(name)
        geom = UsdGeom.Mesh(prim)
        points = np.array(geom.GetPointsAttr().Get(), float)
        faces = np.array(geom.GetFaceVertexIndicesAttr().Get(), int).reshape(-1, 3)
        assert set(geom.GetFaceVertexCountsAttr().Get()) == {3}
        return trimesh.Trimesh(points, faces, process=False).apply_transform(self._world(prim))

    def children(self, name: str) -> list[str]:
        return [c.GetCustomDataByKey("mansion")["name"] for c in self.prims[name].GetChildren() if c.GetCustomDataByKey("mansion")]

    def bounds(self) -> np.ndarray:
        from pxr import Usd, UsdGeom

        cache = UsdGeom.BBoxCache(Usd.TimeCode.Default(), [UsdGeom.Tokens.default_])
        r = cache.ComputeWorldBound(self.stage.GetDefaultPrim()).ComputeAlignedRange()
        return np.array([list(r.GetMin()), list(r.GetMax())])


FILES = {"gltf": "office.glb", "usd": "office.usda"}


@pytest.fixture(scope="module")
def exported(building: Path, tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    """The building written by the CLI in every format."""
    folder = tmp_path_factory.mktemp("exported")
    out = {}
    for fmt, name in FILES.items():
        out[fmt] = folder / name
        result = runner.invoke(app, ["export", str(building), "--format", fmt, "--out", str(out[fmt])])
        assert result.exit_code == 0, result.output
    return out


@pytest.fixture(scope="module", params=sorted(FILES))
def scene(request: pytest.FixtureRequest, exported: dict[str, Path]) -> GlbReader | UsdReader:
    if request.param == "usd":
        pytest.importorskip("pxr")
        return UsdReader(exported["usd"])
    return GlbReader(exported["gltf"])


Scene = GlbReader | UsdReader


def _floor_of(name: str) -> int:
    return int(re.match(r"floor_(\d+)/", name).group(1))  # type: ignore[union-attr]


def _top_cover(meshes: list[Any], y: float) -> Any:
    """The plan area covered by the upward faces of ``meshes`` lying at height ``y``."""
    tris = []
    for m in meshes:
        up = (m.face_normals[:, 1] > 0.99) & (np.abs(m.triangles[:, :, 1].mean(axis=1) - y) < 1e-3)
        tris += [Polygon(t[:, [0, 2]]) for t in m.triangles[up]]
    return unary_union([t for t in tris if t.area > 1e-12])


# -- both formats ---------------------------------------------------------------------------------------


def test_one_node_per_floor_at_its_elevation(building: Path, scene: Scene) -> None:
    manifest, _ = _houses(building)
    floors = sorted(scene.names("floor"))
    assert floors == sorted(f"floor_{f.index}" for f in manifest.floors)
    for f in manifest.floors:
        m = scene.matrix(f"floor_{f.index}")
        assert np.allclose(m[:3, 3], [0.0, f.elevation, 0.0], atol=TOL)
        assert scene.extras[f"floor_{f.index}"]["elevation"] == pytest.approx(f.elevation)


def test_every_wall_door_window_and_object_once(building: Path, scene: Scene) -> None:
    manifest, houses = _houses(building)
    found: dict[int, Counter[tuple[str, str]]] = {f.index: Counter() for f in manifest.floors}
    for name, extras in scene.extras.items():
        if extras.get("kind") in ("wall", "door", "window", "object"):
            found[_floor_of(name)][(extras["kind"], extras["id"])] += 1
    for k, house in houses.items():
        expected = _expected_ids(house)
        assert found[k] == expected, f"floor {k}: {set(found[k]) ^ set(expected)}"
        assert set(found[k].values()) == {1}
    # every object node carries its asset id; every room is a node
    for name in scene.names("object"):
        assert scene.extras[name]["assetId"]
    for k, house in houses.items():
        rooms = {scene.extras[n]["id"] for n in scene.names("room") if _floor_of(n) == k}
        assert rooms == {r.id for r in house.rooms}


def test_walls_have_their_door_and_window_holes_cut(building: Path, scene: Scene) -> None:
    _, houses = _houses(building)
    checked = 0
    for k, house in houses.items():
        holes: dict[str, float] = {}
        for h in [*house.doors, *house.windows]:
            lo, hi = h.hole_polygon
            for wid in {h.wall0, h.wall1}:
                holes[wid] = holes.get(wid, 0.0) + (hi.x - lo.x) * (hi.y - lo.y)
        for wall in house.walls:
            if wall.empty:
                continue
            (x0, z0), (x1, z1) = wall.segment()
            height = max(p.y for p in wall.polygon) - min(p.y for p in wall.polygon)
            area = float(np.hypot(x1 - x0, z1 - z0)) * height - holes.get(wall.id, 0.0)
            mesh = scene.mesh(f"floor_{k}/{wall.id}")
            mesh.merge_vertices()
            assert mesh.is_watertight
            assert mesh.volume == pytest.approx(area * SKIN, rel=1e-4), wall.id  # GLB stores float32
            checked += wall.id in holes
    assert checked > 0


def _flights(scene: Scene) -> list[str]:
    return scene.names("flight")


def test_stairs_climb_one_floor_per_flight_in_code_steps(building: Path, scene: Scene) -> None:
    manifest, _ = _houses(building)
    floors = {f.index: f for f in manifest.floors}
    stairs = [c for c in manifest.cores if c.kind == "stair"]
    assert stairs
    for core in stairs:
        served = sorted(core.floors)
        names = sorted(n for n in _flights(scene) if scene.extras[n]["core"] == core.id)
        assert len(names) == len(served) - 1
        for (lower, upper), name in zip(zip(served, served[1:], strict=False), names, strict=True):
            assert (scene.extras[name]["from_floor"], scene.extras[name]["to_floor"]) == (lower, upper)
            assert floors[upper].elevation - floors[lower].elevation == pytest.approx(floors[lower].height)
            steps = sorted((c for c in scene.children(name) if scene.extras[c]["kind"] == "step"))
            meshes = [scene.mesh(s) for s in steps]
            tops = [floors[lower].elevation] + [m.bounds[1][1] for m in meshes] + [floors[upper].elevation]
            rises = np.diff(tops)
            landings = {round(scene.mesh(c).bounds[1][1], 6) for c in scene.children(name) if scene.extras[c]["kind"] == "landing"}
            # a turning flight rises onto its half landing and from it: that riser is in the
            # landing's height, not between two treads.
            if landings:
                (mid,) = landings
                tops = sorted([*tops, mid])
                rises = np.diff(tops)
            assert np.all(rises > 0)
            assert np.all(rises <= MAX_RISE + 1e-9)
            assert np.allclose(rises, rises[0])
            assert sum(rises) == pytest.approx(floors[lower].height)
            for m in meshes:
                going = min(m.extents[0], m.extents[2])
                assert going >= MIN_GOING - 1e-9
                # inside the core's box
                assert m.bounds[0][0] >= core.x[0] - TOL and m.bounds[1][0] <= core.x[1] + TOL
                assert m.bounds[0][2] >= core.z[0] - TOL and m.bounds[1][2] <= core.z[1] + TOL


def test_slabs_open_over_every_core_and_close_under_it(building: Path, scene: Scene) -> None:
    manifest, _ = _houses(building)
    floors = {f.index: f for f in manifest.floors}
    assert {c.kind for c in manifest.cores} == {"stair", "elevator"}
    for core in manifest.cores:
        box = rect(core.x[0], core.z[0], core.x[1], core.z[1])
        served = sorted(core.floors)
        for k in served:
            rooms = [scene.mesh(n) for n in scene.names("room") if _floor_of(n) == k and scene.has_mesh(n)]
            cover = _top_cover(rooms, floors[k].elevation).intersection(box)
            if k == served[0]:
                assert cover.area == pytest.approx(box.area, rel=1e-6), f"{core.id} has no floor at {k}"
            elif core.kind == "elevator":
                assert cover.area < 1e-6, f"{core.id}: the slab of floor {k} closes the shaft"
            else:
                # every tread of the flight arriving here lies under the opening
                (arriving,) = [n for n in _flights(scene) if scene.extras[n]["core"] == core.id and scene.extras[n]["to_floor"] == k]
                for step in scene.children(arriving):
                    b = scene.mesh(step).bounds
                    assert cover.intersection(rect(b[0][0], b[0][2], b[1][0], b[1][2])).area < 1e-6
                assert cover.area < box.area - 1.0
    for core in manifest.cores:
        if core.kind == "elevator":
            car = scene.mesh(f"floor_{min(core.floors)}/{core.id}/car")
            assert box_contains(core, car.bounds)


def box_contains(core: Any, bounds: np.ndarray) -> bool:
    return bool(
        bounds[0][0] >= core.x[0] - TOL and bounds[1][0] <= core.x[1] + TOL
        and bounds[0][2] >= core.z[0] - TOL and bounds[1][2] <= core.z[1] + TOL
    )


def test_bounds_are_the_footprint_and_height(building: Path, scene: Scene) -> None:
    manifest, houses = _houses(building)
    outline = unary_union([Polygon([(p.x, p.z) for p in r.floor_polygon]) for h in houses.values() for r in h.rooms])
    x0, z0, x1, z1 = outline.bounds
    top = max(manifest.floors, key=lambda f: f.index)
    ground = min(manifest.floors, key=lambda f: f.index)
    lo, hi = scene.bounds()
    # walls are skins on their visible side: outside twins stand SKIN beyond the footprint
    assert lo[0] == pytest.approx(x0 - SKIN, abs=TOL) and hi[0] == pytest.approx(x1 + SKIN, abs=TOL)
    assert lo[2] == pytest.approx(z0 - SKIN, abs=TOL) and hi[2] == pytest.approx(z1 + SKIN, abs=TOL)
    assert hi[1] == pytest.approx(top.elevation + top.height, abs=TOL)
    assert lo[1] == pytest.approx(-(ground.height - ground.ceiling_height), abs=TOL)


def test_glb_is_deterministic_and_coloured(building: Path, exported: dict[str, Path], tmp_path: Path) -> None:
    glb = exported["gltf"]
    again = export_building(building, "gltf", tmp_path / "again.glb")
    assert again.read_bytes() == glb.read_bytes()
    tree = _glb_json(glb)
    colours = {tuple(m["pbrMetallicRoughness"]["baseColorFactor"]) for m in tree["materials"]}
    assert len(colours) >= 5
    assert any(m.get("alphaMode") == "BLEND" for m in tree["materials"])  # glass


def test_usd_is_laid_out_for_physics(building: Path, exported: dict[str, Path]) -> None:
    pytest.importorskip("pxr")
    from pxr import UsdGeom, UsdPhysics

    usd = UsdReader(exported["usd"])
    stage = usd.stage
    assert UsdGeom.GetStageUpAxis(stage) == UsdGeom.Tokens.y
    assert UsdGeom.GetStageMetersPerUnit(stage) == 1.0
    assert any(p.IsA(UsdPhysics.Scene) for p in stage.Traverse())
    for name in usd.names("floor"):
        assert usd.prims[name].GetTypeName() == "Xform"
    _, houses = _houses(building)
    movable = {o.id for h in houses.values() for o in _all_objects(h.objects) if not o.kinematic}
    assert movable
    for kind in ("wall", "room", "step", "object", "door"):
        for name in usd.names(kind):
            if not usd.has_mesh(name):
                continue
            prim = usd._mesh_prim(name)
            assert prim.HasAPI(UsdPhysics.CollisionAPI), name
            rigid = prim.HasAPI(UsdPhysics.RigidBodyAPI)
            assert rigid == (kind == "object" and usd.extras[name]["id"] in movable), name
            if rigid:
                assert UsdPhysics.MeshCollisionAPI(prim).GetApproximationAttr().Get() == "convexHull"
    # every mesh has a material
    from pxr import UsdShade

    meshes = [p for p in stage.Traverse() if p.GetTypeName() == "Mesh"]
    assert all(UsdShade.MaterialBindingAPI(p).ComputeBoundMaterial()[0] for p in meshes)


def test_usd_is_deterministic_in_text_and_binary(building: Path, exported: dict[str, Path], tmp_path: Path) -> None:
    pytest.importorskip("pxr")
    from pxr import Usd

    again = export_building(building, "usd", tmp_path / "again.usda")
    assert again.read_text() == exported["usd"].read_text()
    crate = export_building(building, "usd", tmp_path / "b.usd")
    assert crate.read_bytes()[:8] == b"PXR-USDC"
    assert export_building(building, "usd", tmp_path / "c.usd").read_bytes() == crate.read_bytes()
    assert len(list(Usd.Stage.Open(str(crate)).Traverse())) == len(list(UsdReader(exported["usd"]).stage.Traverse()))


def _all_objects(objects: list[Any]) -> list[Any]:
    return [x for o in objects for x in (o, *_all_objects(o.children))]


# -- stairs on their own -----------------------------------------------------------------------


def test_a_short_core_gets_a_turning_flight_within_the_step_rules() -> None:
    plan = plan_core("stair_1", "stair", (0.0, 0.0, 4.0, 3.0), door=(2.0, 0.0))
    node, opening = flight_node(plan, 3.3, 0, 1, "floor_0")
    assert node.info["turns"] == 1
    tops = sorted({round(float(c.mesh[0][:, 1].max()), 9) for c in node.children})
    rises = np.diff([0.0, *tops, 3.3])
    assert np.all(rises <= MAX_RISE + 1e-9) and np.allclose(rises, rises[0])
    for c in node.children:
        if c.kind == "step":
            ext = c.mesh[0].max(axis=0) - c.mesh[0].min(axis=0)
            assert min(ext[0], ext[2]) >= MIN_GOING - 1e-9
    # the opening leaves a floor landing by the door (z = 0 side) in the box
    assert rect(0.0, 0.0, 4.0, 3.0).difference(opening).area > 0.5
    with pytest.raises(InvalidInputError, match="too short"):
        flight_node(plan_core("s", "stair", (0.0, 0.0, 2.0, 1.5), None), 3.3, 0, 1, "floor_0")


@pytest.mark.parametrize("door", [(3.0, 0.0), (3.0, 3.0), (0.0, 1.5), (6.0, 1.5)])
def test_a_straight_flight_leaves_floor_in_front_of_the_door(door: tuple[float, float]) -> None:
    plan = plan_core("stair_1", "stair", (0.0, 0.0, 6.0, 3.0), door=door)
    node, opening = flight_node(plan, 3.3, 0, 1, "floor_0")
    assert node.info["turns"] == 0
    # half a metre of floor at least between the door and the opening
    assert opening.distance(Polygon.from_bounds(door[0], door[1], door[0], door[1]).buffer(0.01)) > 0.5 - 0.01


# -- CLI ---------------------------------------------------------------------------------------


def test_export_cli_errors_are_clear(building: Path, tmp_path: Path) -> None:
    bad = runner.invoke(app, ["export", str(tmp_path / "missing"), "--out", str(tmp_path / "x.glb")])
    assert bad.exit_code == 2 and "not a building folder" in bad.output
    wrong = runner.invoke(app, ["export", str(building), "--format", "gltf", "--out", str(tmp_path / "x.usd")])
    assert wrong.exit_code == 2 and ".glb" in wrong.output
    unknown = runner.invoke(app, ["export", str(building), "--format", "obj", "--out", str(tmp_path / "x.obj")])
    assert unknown.exit_code == 2 and "gltf" in unknown.output
    assert set(FORMATS) >= {"gltf", "usd"}


def test_preview_draws_the_building_in_3d(building: Path, tmp_path: Path) -> None:
    from PIL import Image

    png = tmp_path / "preview.png"
    result = runner.invoke(app, ["export", str(building), "--preview", str(png)])
    assert result.exit_code == 0, result.output
    image = Image.open(png).convert("RGB")
    assert max(image.size) == 1600 and min(image.size) > 800
    pixels = np.asarray(image).reshape(-1, 3)
    drawn = np.any(pixels != 255, axis=1).mean()
    assert 0.3 < drawn < 0.95  # the building fills the picture, on a white ground
    assert len(np.unique(pixels[::7], axis=0)) > 50  # shaded faces in many materials
    again = tmp_path / "again.png"
    runner.invoke(app, ["export", str(building), "--preview", str(again)])
    assert again.read_bytes() == png.read_bytes()
    assert runner.invoke(app, ["export", str(building)]).exit_code == 2  # nothing to write


def test_real_houses_export_every_element_with_its_holes(tmp_path: Path) -> None:
    """Every real house AI2-THOR loads (ProcTHOR's, Holodeck's; ../shared/data/real-houses), given
    alone, is a one-floor model with every wall, door, window and object once, and walls whose
    solid is the wall less its holes."""
    import gzip
    import os

    folder = os.environ.get("MANSION_REAL_HOUSES") or Path(__file__).resolve().parents[1].parent / "shared" / "data" / "real-houses"
    data = Path(folder) / "houses.jsonl.gz"
    if not data.is_file():
        pytest.skip(f"{data} is absent")
    walls = exact = houses = 0
    with gzip.open(data, "rt", encoding="utf-8") as lines:
        for line in lines:
            record = json.loads(line)
            file = tmp_path / "house.json"
            file.write_text(json.dumps(record["house"]))
            house = House.parse(record["house"])
            model = building_model(file)
            assert [n.name for n in model.root.children] == ["floor_0"]
            found: Counter[tuple[str, str]] = Counter(
                (n.kind, str(n.info["id"])) for n, _ in model.root.walk() if n.kind in ("wall", "door", "window", "object")
            )
            assert found == _expected_ids(house), record["name"]
            cut: dict[str, float] = {}
            for h in [*house.doors, *house.windows]:
                lo, hi = h.hole_polygon
                for wid in {h.wall0, h.wall1}:
                    cut[wid] = cut.get(wid, 0.0) + (hi.x - lo.x) * (hi.y - lo.y)
            by_id = {w.id: w for w in house.walls}
            for node, _ in model.root.walk():
                if node.kind != "wall":
                    continue
                wall = by_id[str(node.info["id"])]
                (x0, z0), (x1, z1) = wall.segment()
                full = float(np.hypot(x1 - x0, z1 - z0)) * (max(p.y for p in wall.polygon) - min(p.y for p in wall.polygon))
                volume = trimesh.Trimesh(*node.mesh).volume / SKIN
                assert 0.0 < volume <= full + 1e-6, wall.id
                walls += 1
                exact += abs(volume - (full - cut.get(wall.id, 0.0))) < 1e-6
            houses += 1
    assert houses == 127
    assert exact >= 0.99 * walls  # the rest: holes reaching past their wall's end


def test_every_flight_starts_and_ends_on_floor(building: Path, scene: Scene) -> None:
    """The floor goes on before the first tread and after the last: a flight connects the two
    floors' slabs (and through them the landings outside the core's door)."""
    manifest, _ = _houses(building)
    floors = {f.index: f for f in manifest.floors}
    covers = {}
    for k, f in floors.items():
        rooms = [scene.mesh(n) for n in scene.names("room") if _floor_of(n) == k and scene.has_mesh(n)]
        covers[k] = _top_cover(rooms, f.elevation)
    flights = _flights(scene)
    assert flights
    for name in flights:
        steps = sorted(c for c in scene.children(name) if scene.extras[c]["kind"] == "step")
        centres = [scene.mesh(s).bounds.mean(axis=0)[[0, 2]] for s in steps]
        for a, b, floor in ((centres[1], centres[0], scene.extras[name]["from_floor"]),
                            (centres[-2], centres[-1], scene.extras[name]["to_floor"])):
            step = (b - a) / np.linalg.norm(b - a)
            going = float(scene.extras[name]["going"])
            x, z = b + step * (going / 2 + 0.1)  # just beyond the end tread, along the run
            probe = Polygon.from_bounds(x - 0.01, z - 0.01, x + 0.01, z + 0.01)
            assert covers[floor].contains(probe), f"{name}: no floor at {floor} beyond ({x:.2f}, {z:.2f})"
    # and the landing pose outside each core's door stands on its floor's slab
    for core in manifest.cores:
        for landing in core.landings:
            p = landing.pose.position
            assert covers[landing.floor].contains(Polygon.from_bounds(p.x - 0.01, p.z - 0.01, p.x + 0.01, p.z + 0.01))
