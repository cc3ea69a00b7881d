"""A generated building folder (its manifest and one house JSON per floor) → a :class:`BuildingModel`:
the floors stacked at their elevations, with slabs, walls, doors, windows, stairs, elevator cars
and objects. A lone house JSON (ProcTHOR's, Holodeck's, one mansion floor) is a one-floor
building without cores."""

from __future__ import annotations

import json
import os
from dataclasses import dataclass
from pathlib import Path

from shapely.geometry import Polygon
from shapely.ops import unary_union

from mansion.exceptions import InvalidInputError
from mansion.export.cores import CorePlan, car_node, flight_node, plan_core
from mansion.export.furniture import object_nodes
from mansion.export.looks import material_look
from mansion.export.meshes import prism
from mansion.export.model import BuildingModel, Node
from mansion.export.walls import WallFrame, hole_nodes, wall_nodes
from mansion.scene.house import House
from mansion.scene.manifest import BuildingManifest, ManifestCore
from mansion.scene.mansionworld import is_mansionworld, read_mansionworld

__all__ = ["BuildingFiles", "building_model", "find_manifest", "read_building"]


@dataclass(frozen=True)
class _Floor:
    index: int
    house: str
    elevation: float
    height: float
    ceiling_height: float

_MIN_SLAB = 0.2  # when floors leave no gap between a ceiling and the next floor


def find_manifest(path: str | os.PathLike[str]) -> Path:
    """The manifest of a building folder (``DIR/scenes/manifest.json`` or ``DIR/manifest.json``),
    or ``path`` itself when it is a JSON file (a manifest or a lone house)."""
    p = Path(path)
    for candidate in (p / "scenes" / "manifest.json", p / "manifest.json", p):
        if candidate.is_file() and candidate.suffix == ".json":
            return candidate
    raise InvalidInputError(
        f"{str(p)!r} is not a building folder or a house JSON: no scenes/manifest.json or "
        "manifest.json in it (write one with `mansion generate ... --out DIR`)"
    )


def _door_centre(house: House, frames: dict[str, WallFrame], door_id: str | None) -> tuple[float, float] | None:
    door = next((d for d in house.doors if d.id == door_id), None)
    if door is None or door.wall0 not in frames:
        return None
    lo, hi = door.hole_polygon
    return frames[door.wall0].at((lo.x + hi.x) / 2)


def _slab_thickness(floors: list[_Floor], i: int) -> float:
    below = floors[i - 1] if i > 0 else floors[i]
    gap = (floors[i].elevation - below.elevation if i > 0 else below.height) - below.ceiling_height
    return gap if gap > 0.01 else _MIN_SLAB


@dataclass
class BuildingFiles:
    """A building as read from its files: what the exporters start from."""

    name: str
    info: dict[str, str | float | int]
    floors: list[_Floor]
    houses: dict[int, House]
    cores: list[ManifestCore]


def read_building(path: str | os.PathLike[str]) -> BuildingFiles:
    """Read a building folder, its manifest, a lone house JSON (a one-floor building without
    cores) or a MansionWorld folder (``floor_1.json`` …, read as :mod:`mansion.scene.mansionworld`
    reads it)."""
    if is_mansionworld(path):
        world = read_mansionworld(path)
        m = world.manifest
        floors = [_Floor(f.index, f.house, f.elevation, f.height, f.ceiling_height) for f in m.floors]
        info: dict[str, str | float | int] = {"id": m.id, "description": m.description,
                                              "buildingType": m.building_type, "seed": m.seed}
        return BuildingFiles(m.id, info, floors, {k: world.house(k) for k in world.houses}, m.cores)
    file = find_manifest(path)
    try:
        data = json.loads(file.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise InvalidInputError(f"cannot read {str(file)!r}: {exc}") from exc
    if isinstance(data, dict) and "rooms" in data and "floors" not in data:
        house = House.parse(data, source=str(file))
        heights = [p.y for w in house.walls for p in w.polygon] or [3.0]
        ceiling = max(heights) - min(heights) or 3.0
        floor = _Floor(0, file.name, 0.0, ceiling + _MIN_SLAB, ceiling)
        info = {"id": house.id or file.stem, "house": file.name}
        return BuildingFiles(house.id or file.stem, info, [floor], {0: house}, [])
    manifest = BuildingManifest.load(file)
    floors = [_Floor(f.index, f.house, f.elevation, f.height, f.ceiling_height) for f in manifest.floors]
    if not floors:
        raise InvalidInputError(f"{str(file)!r} lists no floors")
    houses = {f.index: House.load(file.parent / f.house) for f in floors}
    info = {"id": manifest.id, "description": manifest.description,
            "buildingType": manifest.building_type, "seed": manifest.seed}
    return BuildingFiles(manifest.id, info, floors, houses, manifest.cores)


def building_model(path: str | os.PathLike[str]) -> BuildingModel:
    """Read a building folder, its manifest, a lone house JSON or a MansionWorld folder
    (:func:`read_building`), and build its model (see :mod:`mansion.export`)."""
    b = read_building(path)
    return _model(b.name, b.info, b.floors, b.houses, b.cores)


def _model(
    name: str, info: dict[str, str | float | int], floors: list[_Floor], houses: dict[int, House],
    cores: list[ManifestCore],
) -> BuildingModel:
    floors = sorted(floors, key=lambda f: f.index)
    by_index = {f.index: f for f in floors}

    walls: dict[int, tuple[list[Node], dict[str, WallFrame]]] = {}
    for f in floors:
        walls[f.index] = wall_nodes(houses[f.index], f"floor_{f.index}")

    # Cores: a frame from where the door is on the lowest floor that has one, the flights
    # between consecutive floors served, and the openings they need.
    openings: dict[int, list[Polygon]] = {f.index: [] for f in floors}
    core_nodes: dict[int, list[Node]] = {f.index: [] for f in floors}
    for core in cores:
        served = sorted(k for k in set(core.floors) if k in by_index)
        if not served:
            continue
        door = None
        for landing in sorted(core.landings, key=lambda c: c.floor):
            if landing.floor in houses:
                door = _door_centre(houses[landing.floor], walls[landing.floor][1], landing.door)
                if door is not None:
                    break
        plan: CorePlan = plan_core(core.id, core.kind, (core.x[0], core.z[0], core.x[1], core.z[1]), door)
        if core.kind == "elevator":
            core_nodes[served[0]].append(car_node(plan, f"floor_{served[0]}"))
            for k in served[1:]:
                openings[k].append(Polygon.from_bounds(core.x[0], core.z[0], core.x[1], core.z[1]))
        else:
            for lower, upper in zip(served, served[1:], strict=False):
                height = by_index[upper].elevation - by_index[lower].elevation
                node, opening = flight_node(plan, height, lower, upper, f"floor_{lower}")
                core_nodes[lower].append(node)
                openings[upper].append(opening)

    root = Node(name, "building", info=info)
    outline = []
    for i, f in enumerate(floors):
        house, name = houses[f.index], f"floor_{f.index}"
        floor = root.add(Node(name, "floor", offset=(0.0, f.elevation, 0.0),
                              info={"index": f.index, "elevation": f.elevation, "height": f.height,
                                    "house": f.house}))
        cut = unary_union(openings[f.index]) if openings[f.index] else None
        thickness = _slab_thickness(floors, i)
        rooms: dict[str, Node] = {}
        shapes = []
        for room in house.rooms:
            shape = Polygon([(p.x, p.z) for p in room.floor_polygon]).buffer(0)
            shapes.append(shape)
            slab = shape.difference(cut) if cut is not None else shape
            rooms[room.id] = floor.add(Node(
                f"{name}/{room.id}", "room", mesh=prism(slab, -thickness, 0.0) if slab.area > 1e-9 else None,
                look=material_look(room.floor_material, "WoodFloorsCross"), physics="collider",
                info={"id": room.id, "roomType": room.room_type},
            ))
        outline += shapes

        def home(room_id: str | None, floor: Node = floor, rooms: dict[str, Node] = rooms) -> Node:
            return rooms.get(room_id or "", floor)

        for node in walls[f.index][0]:
            home(str(node.info["room"])).add(node)
        for room_id, node in hole_nodes(house, walls[f.index][1], name):
            home(room_id).add(node)
        for owner, node in object_nodes(house.objects, name):
            home(owner).add(node)
        for node in core_nodes[f.index]:
            floor.add(node)
        if i == len(floors) - 1:
            roof = unary_union(shapes)
            floor.add(Node(f"{name}/roof", "roof", mesh=prism(roof, f.ceiling_height, f.height),
                           look=material_look(None, "ConcreteFloor"), physics="collider"))

    top = floors[-1]
    x0, z0, x1, z1 = unary_union(outline).bounds
    return BuildingModel(root, (x0, z0, x1, z1), top.elevation + top.height, _slab_thickness(floors, 0))
