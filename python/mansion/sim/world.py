"""The state of a building's floors: each floor's house (the source of truth the skills change),
its objects indexed by id, and, for the loaded floor, its navigation grid and room landmarks.

What an object affords comes from AI2-THOR's asset database (``procthor``): it can be picked up
when its type is pickupable in the placement annotations, opened when the asset ``CanOpen``, and
holds things when it is a ``Receptacle``. A small object inside an openable receptacle (below its
top, where ``Put`` leaves it) is hidden and out of reach while the receptacle is closed.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path
from typing import Any

import numpy as np
from shapely.geometry import Point, Polygon
from shapely.ops import polylabel

from mansion.exceptions import InvalidInputError
from mansion.placement.assets import database
from mansion.scene.databases import asset_ids
from mansion.scene.house import House, HouseObject
from mansion.scene.manifest import BuildingManifest, ManifestCore
from mansion.scene.mansionworld import MansionWorldBuilding, is_mansionworld, read_mansionworld
from mansion.scene.validate import AGENT_RADIUS
from mansion.sim.grid import CELL, NavGrid, box_distance

__all__ = ["Building", "FloorState", "ObjectInfo", "building_root", "find_manifest", "props", "variant_folder"]

#: Key we add to a held object's record in the house JSON (the loader ignores unknown keys).
HELD_KEY = "heldBy"


@dataclass(frozen=True)
class Props:
    object_type: str
    width: float
    depth: float
    height: float
    pickupable: bool
    openable: bool
    receptacle: bool


@cache
def props(asset_id: str) -> Props:
    rec = asset_ids().get(asset_id)
    if rec is None:
        return Props("Unknown", 0.2, 0.2, 0.2, False, False, False)
    bb = rec["boundingBox"]
    t = rec["objectType"]
    sec = rec.get("secondaryProperties", [])
    pick = bool(database().pickupable.get(t, False)) or rec.get("primaryProperty") == "CanPickup"
    return Props(t, bb["x"], bb["z"], bb["y"], pick, "CanOpen" in sec, "Receptacle" in sec)


@dataclass
class ObjectInfo:
    """An object of the floor with its parent (the receptacle it lies on or in) and room."""

    obj: HouseObject
    parent: str | None
    room: str | None
    props: Props

    @property
    def id(self) -> str:
        return self.obj.id

    @property
    def centre(self) -> tuple[float, float]:
        return (self.obj.position.x, self.obj.position.z)

    def distance(self, x: float, z: float) -> float:
        p = self.props
        return float(box_distance(np.array([x]), np.array([z]), self.centre, p.width, p.depth,
                                  self.obj.rotation.y)[0])


def find_manifest(path: str | Path) -> Path:
    """A building folder (``scenes/manifest.json`` inside), a scenes folder or a manifest."""
    p = Path(path)
    for candidate in (p, p / "manifest.json", p / "scenes" / "manifest.json"):
        if candidate.is_file():
            return candidate
    raise InvalidInputError(f"{str(p)!r} is no building: no manifest.json nor scenes/manifest.json (nor floor_1.json, a MansionWorld building)")


def building_root(manifest_path: Path) -> Path:
    """The folder ``mansion generate`` wrote (task variants live in its ``variants/``): the
    parent of a ``scenes`` folder, else the manifest's own folder."""
    folder = manifest_path.parent
    return folder.parent if folder.name == "scenes" else folder


def variant_folder(path: str | Path, name: str) -> Path:
    """The folder of task variant ``name`` of a building (``mansion edit`` writes it:
    ``variants/<name>/scenes/`` holds its house JSONs and manifest)."""
    folder = building_root(find_manifest(path)) / "variants" / name
    if name.startswith(".") or not (folder / "scenes" / "manifest.json").is_file():
        raise InvalidInputError(f"{str(path)!r} has no task variant {name!r} (mansion variants list)")
    return folder


class FloorState:
    """One floor's house and what the skills need to read from it."""

    def __init__(self, house: House, cores: dict[str, ManifestCore], cell: float = CELL,
                 grid: NavGrid | None = None):
        self.house = house
        #: set when floor objects or doors changed: the grid of the floor as written no longer holds
        self.changed_grid = False
        self.cell = cell
        self.core_ids = {r.id for r in house.rooms if r.metadata and r.metadata.core} | set(cores)
        record = house.metadata.mansion
        self.index = record.floor if record else 0
        self.radius = (record.furnishing.agent_radius if record and record.furnishing else AGENT_RADIUS)
        self.rooms = {r.id: r for r in house.rooms}
        self.polygons = {r.id: Polygon([(p.x, p.z) for p in r.floor_polygon]) for r in house.rooms}
        self.objects: dict[str, ObjectInfo] = {}
        self.reindex()
        self._grid: NavGrid | None = grid
        self._landmarks: dict[str, tuple[float, float]] | None = None

    # -- objects --------------------------------------------------------------------------------
    def reindex(self) -> None:
        self.version = getattr(self, "version", 0) + 1
        self.objects = {}

        def walk(obj: HouseObject, parent: str | None, room: str | None) -> None:
            self.objects[obj.id] = ObjectInfo(obj, parent, obj.room or room, props(obj.asset_id))
            for child in obj.children:
                walk(child, obj.id, obj.room or room)

        for obj in self.house.objects:
            walk(obj, None, obj.room)
        self.doors = {d.id: d for d in self.house.doors}

    def inside(self, info: ObjectInfo) -> str | None:
        """The closed receptacle ``info`` is shut in, if any."""
        if info.parent is None:
            return None
        parent = self.objects[info.parent]
        top = parent.obj.position.y + parent.props.height / 2
        below_top = info.obj.position.y - info.props.height / 2 < top - 0.02
        if parent.props.openable and below_top and not self.is_open(parent.obj.id):
            return parent.obj.id
        return self.inside(parent)

    def is_open(self, oid: str) -> bool:
        if oid in self.doors:
            return self.doors[oid].openness > 0.0 or not self.doors[oid].openable
        info = self.objects[oid]
        return (info.obj.openness or 0.0) > 0.0

    def held(self) -> ObjectInfo | None:
        for info in self.objects.values():
            if info.parent is None and (info.obj.model_extra or {}).get(HELD_KEY):
                return info
        return None

    def detach(self, oid: str) -> HouseObject:
        """Take an object out of the house (from its receptacle or the floor)."""
        info = self.objects[oid]
        siblings = self.objects[info.parent].obj.children if info.parent else self.house.objects
        siblings[:] = [o for o in siblings if o.id != oid]
        self.reindex()
        if info.parent is None and not (info.obj.model_extra or {}).get(HELD_KEY):
            self._grid = None  # a floor object moved: the free space changed
            self.changed_grid = True
        return info.obj

    def attach(self, obj: HouseObject, parent: str | None) -> None:
        if parent is None:
            self.house.objects.append(obj)
        else:
            self.objects[parent].obj.children.append(obj)
        self.reindex()

    # -- navigation -----------------------------------------------------------------------------
    @property
    def grid(self) -> NavGrid:
        if self._grid is None:
            floor_objects = [
                (i.centre, i.props.width, i.props.depth, i.obj.rotation.y)
                for i in self.objects.values()
                if i.parent is None and not (i.obj.model_extra or {}).get(HELD_KEY)
            ]
            closed = {d.id for d in self.house.doors if d.openable and d.openness <= 0.0}
            self._grid = NavGrid.build(self.house, self.radius, objects=floor_objects,
                                       closed_doors=closed, cores=self.core_ids, cell=self.cell)
        return self._grid

    def invalidate(self) -> None:
        self.version += 1
        self._grid = None
        self.changed_grid = True

    @property
    def landmarks(self) -> dict[str, tuple[float, float]]:
        """Each room's landmark: the point of the room farthest from its outline."""
        if self._landmarks is None:
            out = {}
            for rid, poly in self.polygons.items():
                try:
                    p = polylabel(poly, tolerance=0.1)
                except Exception:  # a degenerate polygon: its representative point will do
                    p = poly.representative_point()
                out[rid] = (round(p.x, 3), round(p.y, 3))
            self._landmarks = out
        return self._landmarks

    def room_of(self, x: float, z: float) -> str | None:
        for rid, poly in self.polygons.items():
            if poly.covers(_point(x, z)):
                return rid
        return None

    def room_graph(self) -> dict[str, set[str]]:
        """Rooms joined by doors or openings (empty walls shared by two rooms)."""
        links: dict[str, set[str]] = {r: set() for r in self.rooms}
        for d in self.house.doors:
            if d.room0 in links and d.room1 in links:
                links[d.room0].add(d.room1)
                links[d.room1].add(d.room0)
        by_seg: dict[Any, list[str]] = {}
        for w in self.house.walls:
            if w.empty:
                a, b = w.segment()
                key = tuple(sorted(((round(a[0], 3), round(a[1], 3)), (round(b[0], 3), round(b[1], 3)))))
                by_seg.setdefault(key, []).append(w.room_id)
        for rooms in by_seg.values():
            for x in rooms:
                for y in rooms:
                    if x != y and x in links and y in links:
                        links[x].add(y)
        return links


def _point(x: float, z: float) -> Point:
    return Point(x, z)


@dataclass
class Building:
    """A building's manifest and the current state of its floors (read from disk when first
    needed; kept in memory as the agent changes them). ``manifest_path`` may also be a
    MansionWorld folder (:mod:`mansion.scene.mansionworld`): read as mansion reads its own."""

    manifest_path: Path
    manifest: BuildingManifest = field(init=False)
    houses: dict[int, House] = field(default_factory=dict)
    #: the floors' files as read, shared by the episodes of an env (each parses its own copy)
    raw: dict[int, bytes] = field(default_factory=dict)
    #: grids of floors as written, shared likewise; ``dirty`` floors have changed since
    grids: dict[int, NavGrid] = field(default_factory=dict)
    dirty: set[int] = field(default_factory=set)
    #: the MansionWorld folder as read (None for mansion's own buildings)
    world: MansionWorldBuilding | None = None

    def __post_init__(self) -> None:
        if self.world is None and is_mansionworld(self.manifest_path):
            self.world = read_mansionworld(self.manifest_path)
        if self.world is not None:
            # their layout has no manifest: the reader's, and its floors as mansion reads them
            self.manifest_path = self.world.folder
            self.manifest = self.world.manifest
            self.floor_files = dict(self.world.files)
            for k in self.world.houses:
                self.raw.setdefault(k, self.world.house_bytes(k))
            return
        self.manifest_path = find_manifest(self.manifest_path)
        self.manifest = BuildingManifest.load(self.manifest_path)
        if not self.manifest.floors:
            raise InvalidInputError(f"{str(self.manifest_path)!r}: the building has no floors")
        self.floor_files = {f.index: self.manifest_path.parent / f.house for f in self.manifest.floors}

    @property
    def floors(self) -> list[int]:
        return sorted(self.floor_files)

    def house(self, floor: int) -> House:
        if floor not in self.houses:
            if floor not in self.floor_files:
                raise InvalidInputError(f"the building has no floor {floor}")
            if floor not in self.raw:
                try:
                    self.raw[floor] = self.floor_files[floor].read_bytes()
                except OSError as exc:
                    raise InvalidInputError(f"cannot read house JSON {str(self.floor_files[floor])!r}: {exc}") from exc
            try:
                self.houses[floor] = House.model_validate_json(self.raw[floor])
            except ValueError as exc:
                raise InvalidInputError(f"{self.floor_files[floor]}: {exc}") from exc
        return self.houses[floor]

    def floor_state(self, floor: int, cell: float = CELL) -> FloorState:
        """A floor's state, with the grid of the floor as written when nothing changed it."""
        cores = {c.id: c for c in self.manifest.cores if floor in c.floors}
        clean = floor not in self.dirty
        grid = self.grids.get(floor) if clean and self.grids.get(floor, None) is not None \
            and self.grids[floor].cell == cell else None
        st = FloorState(self.house(floor), cores, cell, grid)
        if clean and grid is None:
            self.grids[floor] = st.grid
        return st

    def fresh(self) -> Building:
        """The building as written again, sharing what was read and built from the files."""
        b = Building(self.manifest_path, raw=self.raw, world=self.world)
        b.grids = self.grids
        return b

    def cores_on(self, floor: int) -> list[ManifestCore]:
        return [c for c in self.manifest.cores if floor in c.floors]

    def core_named(self, floor: int, name: str) -> ManifestCore | None:
        """The core of ``floor`` called ``name``: its id, or its room's id on that floor."""
        return next((c for c in self.cores_on(floor) if name in (c.id, c.room_on(floor))), None)

    def landing(self, core: ManifestCore, floor: int) -> Any:
        return next((l for l in core.landings if l.floor == floor), None)

    def write(self, folder: str | Path) -> Path:
        """Write the building as it is now (every floor's house, the manifest) into ``folder``;
        returns the manifest path. ``BuildingEnv(folder)`` starts from this state."""
        out = Path(folder)
        for k, file in self.floor_files.items():
            if k in self.houses:
                self.houses[k].to_json(out / file.name)
            else:
                from mansion._io import atomic_write_bytes

                atomic_write_bytes(out / file.name, self.raw[k] if k in self.raw else file.read_bytes())
        return self.manifest.to_json(out / "manifest.json")

    def house_json(self, floor: int) -> dict[str, Any]:
        return json.loads(json.dumps(self.house(floor).to_dict()))

