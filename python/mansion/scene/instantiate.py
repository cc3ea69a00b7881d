"""Scene instantiation (the paper's deterministic last stage before objects): a building's
floors → one AI2-THOR house per floor plus the building manifest.

Per floor: rooms from the layout's polygons (cores included, with their core record), walls from
the floor's interfaces (two one-sided walls per interface, each wall piece carrying at most one
hole), doors and openings from the graph's access edges, windows in exterior walls, materials
matched to the room cards, a point light per room and a sun, a skybox for the building, and an
agent spawn on a free cell of the hub. Then every room is furnished around those doors
(:mod:`mansion.scene.furnish`, the placement engine of issue 6).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from shapely.geometry import Point, Polygon

from mansion._collector import collector_paused
from mansion.exceptions import InvalidBuildingError, MansionError
from mansion.models.building import Building, Floor
from mansion.placement.place import PlaceOptions
from mansion.scene.databases import hole_asset_position, skyboxes
from mansion.scene.furnish import FurnishJob, furnish_houses
from mansion.scene.house import (
    HOUSE_SCHEMA,
    AgentPose,
    Color,
    CoreRecord,
    Door,
    FloorRecord,
    House,
    HouseMetadata,
    Light,
    MaterialProperties,
    ProceduralParameters,
    Room,
    RoomMetadata,
    ShadowParameters,
    Vec3,
    Wall,
    Window,
)
from mansion.scene.interfaces import Interface, Pt, RoomRings, find_interfaces, oriented
from mansion.scene.manifest import BuildingManifest, CoreLanding, ManifestCore, ManifestFloor
from mansion.scene.materials import floor_material, wall_material
from mansion.scene.navigation import AGENT_RADIUS, open_space, reached_rooms, wall_pieces
from mansion.scene.navigation import MARGIN as NAV_MARGIN
from mansion.scene.parts import split_room
from mansion.scene.passages import Feature, PassagePlan, plan_passages
from mansion.scene.poses import AGENT_MODES, hub_spawn, landing_pose

__all__ = [
    "BuildingScenes",
    "building_id",
    "build_scenes",
    "ceiling_height",
    "floor_house",
    "floor_file",
    "SLAB",
]

#: Slab thickness between floors (m): floor-to-floor height = ceiling height + slab.
SLAB = 0.3
#: ProcTHOR's light layers (``Procedural0``..``Procedural3``).
LAYERS = 4
#: Point lights of a floor that cast shadows (the largest rooms'); with the sun, 3 a floor.
SHADOW_LIGHTS = 2
#: Ceiling height by palette family (m): homes lower, offices and public buildings higher.
_CEILINGS = {"residential": 2.7, "work": 3.0, "public": 3.3}


def ceiling_height(building: Building) -> float:
    """One ceiling height for the whole building (the simulator uses one per house; the
    exporters need the same on every floor so the cores line up)."""
    from mansion.planning.program import typology

    try:
        family = typology(building.program.building_type).family
    except (MansionError, KeyError, ValueError):
        family = "work"
    return _CEILINGS.get(family, 3.0)


def building_id(building: Building) -> str:
    kind = re.sub(r"[^a-z0-9]+", "-", building.program.building_type.lower()).strip("-")
    return f"{kind or 'building'}-{building.seed}"


def floor_file(index: int) -> str:
    return f"floor_{index}.json"


def _camel(room_type: str) -> str:
    return "".join(w[:1].upper() + w[1:] for w in re.split(r"[^A-Za-z0-9]+", room_type) if w)


def _v(p: Pt, y: float = 0.0) -> Vec3:
    return Vec3(x=p[0], y=y, z=p[1])


def _wall(wid: str, room: str, corners: list[Vec3], material: str, empty: bool) -> Wall:
    return Wall(
        id=wid, room_id=room, empty=empty, material=MaterialProperties(name=material),
        polygon=corners,
    )


@dataclass
class _FloorParts:
    house: House
    plan: PassagePlan
    interfaces: list[Interface]
    floor: Floor
    #: Each room of the house (a part of a layout room) → the layout room.
    owner: dict[str, str]


class _WallBuilder:
    """Cuts every interface into wall pieces, one hole at most per piece, and emits both sides."""

    def __init__(
        self, floor: Floor, height: float, materials: dict[str, str], facade: str,
        owner: dict[str, str],
    ):
        self.floor, self.height, self.materials, self.facade = floor, height, materials, facade
        self.owner = owner
        self.count: dict[str, int] = {}
        self.walls: list[Wall] = []
        self.doors: list[Door] = []
        self.windows: list[Window] = []

    def _id(self, room: str, exterior: bool = False) -> str:
        key = f"exterior|{room}" if exterior else room
        self.count[key] = self.count.get(key, 0) + 1
        return f"wall|{self.floor.index}|{key}|{self.count[key]}"

    def interface(self, f: Interface, features: list[Feature], empty: bool) -> None:
        features = sorted(features, key=lambda g: g.t0)
        cuts: list[tuple[float, float, Feature | None]] = []
        t = 0.0
        for g in features:
            if g.t0 > t + 1e-6:
                cuts.append((t, g.t0, None))
            cuts.append((g.t0, g.t1, g))
            t = g.t1
        if f.length > t + 1e-6:
            cuts.append((t, f.length, None))
        for t0, t1, hole in cuts:
            p0, p1 = f.at(t0), f.at(t1)
            # the two faces share their corners (never changed in place): p0 → p1, then up
            a, b, b_top, a_top = _v(p0), _v(p1), _v(p1, self.height), _v(p0, self.height)
            right = self._id(f.room)
            self.walls.append(_wall(right, f.room, [a, b, b_top, a_top], self.materials[f.room], empty))
            if f.other is not None:
                left = self._id(f.other)
                self.walls.append(
                    _wall(left, f.other, [b, a, a_top, b_top], self.materials[f.other], empty)
                )
            else:
                left = self._id(f.room, exterior=True)
                self.walls.append(_wall(left, f.room, [b, a, a_top, b_top], self.facade, empty))
            if hole is not None:
                self._hole(hole, f, t0, right, left)

    def _hole(self, g: Feature, f: Interface, t0: float, wall0: str, wall1: str) -> None:
        lo = Vec3(x=g.x0 - t0, y=g.y0, z=0.0)
        hi = Vec3(x=g.x1 - t0, y=g.y1, z=0.0)
        # ProcTHOR's assetPosition: the hole's minimum + the wall-holes offset + half the box
        x, y = hole_asset_position(g.asset_id, (lo.x, lo.y)) or ((lo.x + hi.x) / 2, (lo.y + hi.y) / 2)
        at = Vec3(x=x, y=y, z=0.0)
        if g.kind == "door":
            # the feature names the layout room; the door names the part of it on its side. The
            # front door (no room beyond) is ProcTHOR's outside door: room0 == room1, wall1 the
            # exterior twin.
            other = f.other if f.other is not None else f.room
            swing = f.room if self.owner[f.room] == g.swing else other
            self.doors.append(
                Door(
                    id=g.id, asset_id=g.asset_id, room0=f.room, room1=other, wall0=wall0,
                    wall1=wall1, hole_polygon=[lo, hi], asset_position=at, openable=True,
                    openness=1.0, swing_room=swing,
                )
            )
        else:
            self.windows.append(
                Window(
                    id=g.id, asset_id=g.asset_id, room0=f.room, room1=f.room, wall0=wall0,
                    wall1=wall1, hole_polygon=[lo, hi], asset_position=at,
                )
            )


def room_layers(rooms: dict[str, Polygon]) -> dict[str, int]:
    """ProcTHOR's light layers: rooms that share a wall get different layers of the four
    ``Procedural0..3`` (a greedy colouring, most neighbours first; a room whose neighbours
    hold all four takes the least used among them), so a room's light, culling the other
    layers, does not shine through into its neighbours."""
    ids = list(rooms)
    near: dict[str, set[str]] = {r: set() for r in ids}
    edges = {r: rooms[r].boundary for r in ids}
    bounds = {r: rooms[r].bounds for r in ids}
    for i, a in enumerate(ids):
        ax0, ay0, ax1, ay1 = bounds[a]
        for b in ids[i + 1:]:
            bx0, by0, bx1, by1 = bounds[b]
            if bx0 > ax1 or ax0 > bx1 or by0 > ay1 or ay0 > by1:
                continue  # apart: no shared wall (most pairs of a floor)
            if edges[a].intersection(edges[b]).length > 1e-6:
                near[a].add(b)
                near[b].add(a)
    layer: dict[str, int] = {}
    for rid in sorted(ids, key=lambda r: (-len(near[r]), r)):
        used = [layer[n] for n in near[rid] if n in layer]
        free = [k for k in range(LAYERS) if k not in used]
        layer[rid] = free[0] if free else min(range(LAYERS), key=lambda k: (used.count(k), k))
    return layer


def _lights(rooms: dict[str, Polygon], height: float, layers: dict[str, int]) -> list[Light]:
    sun = Light(
        id="DirectionalLight", type="directional", position=Vec3(x=0.84, y=0.1855, z=-1.09),
        rotation=Vec3(x=43.375, y=-3.902, z=-63.618), intensity=0.35, indirect_multiplier=1.0,
        rgb=Color(r=1.0, g=1.0, b=1.0), shadow=ShadowParameters(bias=0.0),
    )
    out = [sun]
    # Soft shadows only for the largest rooms' lights: real houses cast shadows from a median
    # of 2 (at most 10) lights a floor, and every shadow map costs a render pass.
    shadowed = set(sorted(rooms, key=lambda r: (-rooms[r].area, r))[:SHADOW_LIGHTS])
    for rid, poly in rooms.items():
        # An L-shaped room's centroid can fall outside it: the representative point never does.
        c = poly.centroid if poly.contains(poly.centroid) else poly.representative_point()
        out.append(
            Light(
                id=f"light|{rid}", type="point", position=Vec3(x=c.x, y=height - 0.2, z=c.y),
                intensity=0.75, range=max(10.0, math.sqrt(poly.area) * 1.5),
                rgb=Color(r=1.0, g=0.855, b=0.722),
                shadow=ShadowParameters() if rid in shadowed else None, room_id=rid,
                layer=f"Procedural{layers[rid]}",
                culling_mask_off=[f"Procedural{k}" for k in range(LAYERS) if k != layers[rid]],
            )
        )
    return out


def _floor_parts(building: Building, floor: Floor, height: float) -> _FloorParts:
    layout, graph = floor.layout, floor.graph
    cards = {c.id: c for c in floor.room_cards}
    parts = [p for r in layout.rooms for p in split_room(r.id, r.polygon, r.holes)]
    owner = {p.id: p.room for p in parts}
    rings = {p.id: oriented(p.ring, clockwise=True) for p in parts}
    polygons = {p.id: Polygon(rings[p.id]) for p in parts}
    interfaces = find_interfaces([RoomRings(p.id, p.ring) for p in parts])
    plan = plan_passages(floor, interfaces, owner, polygons, seed=building.seed, ceiling=height)

    def card_text(room: str, which: str) -> str:
        card = cards.get(owner[room])
        return getattr(card, which) if card is not None else ""

    floors_mat = {p.id: floor_material(card_text(p.id, "floor_material")).name for p in parts}
    walls_mat = {p.id: wall_material(card_text(p.id, "wall_material")).name for p in parts}
    facade = wall_material(building.palette.style + " facade render").name

    def build_walls() -> _WallBuilder:
        builder = _WallBuilder(floor, height, walls_mat, facade, owner)
        by_interface: dict[int, list[Feature]] = {}
        for g in plan.features:
            by_interface.setdefault(g.interface, []).append(g)
        for i, f in enumerate(interfaces):
            builder.interface(f, by_interface.get(i, []), i in plan.empty)
        return builder

    def inside(front: Feature) -> AgentPose:
        # the ground floor's spawn: inside the front door, beyond its leaf, facing in
        f = interfaces[front.interface]
        inward = (-f.left_normal[0], -f.left_normal[1])
        return landing_pose(polygons[f.room], f.at((front.x0 + front.x1) / 2), inward,
                            steps=(1.4, 1.2, 1.6, 1.0, 1.8, 0.8))

    door_centres = [interfaces[g.interface].at((g.x0 + g.x1) / 2) for g in plan.features
                    if g.kind == "door"]
    if plan.entrance_options:
        front = plan.entrance_options[0]
        if len(plan.entrance_options) > 1:
            # the front door whose doorstep the agent walks on to most of the floor (the walls
            # without it, built here for the open space only)
            builder = build_walls()
            space = open_space(polygons.values(), wall_pieces(builder.walls, builder.doors),
                               AGENT_RADIUS + NAV_MARGIN)

            def reach(k: int) -> tuple[int, int]:
                p = inside(plan.entrance_options[k]).position
                return (len(reached_rooms(space, polygons, (p.x, p.z))), -k)

            front = plan.entrance_options[max(range(len(plan.entrance_options)), key=reach)]
        plan.features = [g for g in plan.features
                         if not (g.kind == "window" and g.interface == front.interface)] + [front]
        plan.entrance = front.id
        builder = build_walls()
        spawn = inside(front)
    else:
        builder = build_walls()
        spawn = hub_spawn(layout, graph.hub.id, door_centres)
    at = Point(spawn.position.x, spawn.position.z)
    hub = next(
        (pid for pid, poly in polygons.items() if owner[pid] == graph.hub.id and poly.contains(at)),
        next(pid for pid in polygons if owner[pid] == graph.hub.id),
    )

    cores = {c.id: c for c in building.program.cores}
    kinds = {r.id: r for r in layout.rooms}
    rooms: list[Room] = []
    for p in parts:
        r = kinds[p.room]
        meta = None
        if r.is_core and r.id in cores:
            meta = RoomMetadata(core=_core_record(building, floor, r.id, plan, interfaces, polygons))
        elif p.room == graph.hub.id:
            meta = RoomMetadata(role="hub")
        if p.id != p.room:
            meta = (meta or RoomMetadata()).model_copy(update={"part_of": p.room})
        rooms.append(
            Room(
                id=p.id, room_type=_camel(r.room_type) or "Room",
                floor_material=MaterialProperties(name=floors_mat[p.id]),
                floor_polygon=[_v(q) for q in rings[p.id]],
                metadata=meta,
            )
        )
    sky = skyboxes()[building.seed % len(skyboxes())]
    layers = room_layers(polygons)
    for room in rooms:
        room.layer = f"Procedural{layers[room.id]}"
    for wall in builder.walls:
        wall.layer = f"Procedural{layers[wall.room_id]}"
    house = House(
        id=f"{building_id(building)}-floor-{floor.index}",
        procedural_parameters=ProceduralParameters(
            skybox_id=sky, lights=_lights(polygons, height, layers),
            ceiling_material=MaterialProperties(name=wall_material("white painted plaster").name),
        ),
        rooms=rooms, walls=builder.walls, doors=builder.doors, windows=builder.windows,
        objects=[],
        metadata=HouseMetadata(
            schema=HOUSE_SCHEMA,
            agent_poses={mode: spawn for mode in AGENT_MODES},
            mansion=FloorRecord(
                building=building_id(building), floor=floor.index,
                floor_count=len(building.floors), elevation=floor.index * (height + SLAB),
                ceiling_height=height, hub=hub, copy_of=floor.copy_of,
            ),
        ),
    )
    return _FloorParts(house, plan, interfaces, floor, owner)


def _core_record(
    building: Building, floor: Floor, core_id: str, plan: PassagePlan,
    interfaces: list[Interface], polygons: dict[str, Polygon],
) -> CoreRecord:
    core = next(c for c in building.program.cores if c.id == core_id)
    door, room, landing = _landing(floor, core_id, plan, interfaces, polygons)
    return CoreRecord(
        id=core.id, kind=core.type, floors=sorted(core.floors),
        box=(core.x[0], core.y[0], core.x[1], core.y[1]), door=door, landing_room=room,
        landing=landing,
    )


def _landing(
    floor: Floor, core_id: str, plan: PassagePlan, interfaces: list[Interface],
    polygons: dict[str, Polygon],
) -> tuple[str | None, str, AgentPose]:
    """The core's door on this floor, the room (part) it opens into and the landing pose there."""
    features = {g.id: g for g in plan.features}
    for p in plan.passages:
        if core_id not in (p.a, p.b):
            continue
        if p.door is not None:
            g = features[p.door]
            f = interfaces[g.interface]
            centre = f.at((g.x0 + g.x1) / 2)
        else:
            f = max(
                (f for f in interfaces if core_id in (f.room, f.other) and f.other is not None),
                key=lambda f: f.length,
            )
            centre = f.at(f.length / 2)
        if f.room == core_id:
            room, n = f.other, f.left_normal
        else:
            room, n = f.room, (-f.left_normal[0], -f.left_normal[1])
        assert room is not None
        return p.door, room, landing_pose(polygons[room], centre, n)
    raise InvalidBuildingError(f"floor {floor.index}: core {core_id!r} has no door to any room")


@dataclass
class BuildingScenes:
    """Every floor's house and the manifest that stacks them."""

    houses: list[House]
    manifest: BuildingManifest


def _furnish(
    building: Building, parts: list[_FloorParts], options: PlaceOptions | None
) -> None:
    jobs = [
        FurnishJob(p.house, {part: kinds[room] for part, room in p.owner.items()}, building.seed)
        for p in parts
        for kinds in [{r.id: r.room_type for r in p.floor.layout.rooms}]
    ]
    furnish_houses(jobs, building.program.building_type, options)
    for p in parts:
        # objects light like their room (ProcTHOR's layers)
        layers = {r.id: r.layer for r in p.house.rooms}
        for obj in p.house.objects:
            obj.layer = layers.get(obj.room or "")
            for child in obj.children:
                child.layer = obj.layer


def floor_house(
    building: Building, index: int, *, objects: bool = True, options: PlaceOptions | None = None
) -> House:
    """The house of floor ``index`` alone (furnished unless ``objects`` is False)."""
    with collector_paused():
        parts = _floor_parts(building, building.floors[index], ceiling_height(building))
        if objects:
            _furnish(building, [parts], options)
    return parts.house


def build_scenes(
    building: Building, *, objects: bool = True, options: PlaceOptions | None = None
) -> BuildingScenes:
    """Every floor's house JSON and the building manifest. With ``objects`` (the default) every
    room is furnished (:mod:`mansion.scene.furnish`); ``options`` tunes the placement engine."""
    height = ceiling_height(building)
    with collector_paused():
        parts = [_floor_parts(building, f, height) for f in building.floors]
        if objects:
            _furnish(building, parts, options)
    floors = [
        ManifestFloor(
            index=f.index, house=floor_file(f.index), elevation=f.index * (height + SLAB),
            height=height + SLAB, ceiling_height=height, hub=f.graph.hub.id,
            spawn=p.house.metadata.agent_poses["default"], copy_of=f.copy_of,
            entrance=p.plan.entrance,
        )
        for f, p in zip(building.floors, parts, strict=True)
    ]
    cores = []
    for core in building.program.cores:
        landings = []
        for k in sorted(core.floors):
            room = next(r for r in parts[k].house.rooms if r.id == core.id)
            assert room.metadata is not None and room.metadata.core is not None
            rec = room.metadata.core
            assert rec.landing is not None
            assert rec.landing_room is not None
            landings.append(
                CoreLanding(floor=k, room=rec.landing_room, door=rec.door, pose=rec.landing)
            )
        cores.append(
            ManifestCore(
                id=core.id, kind=core.type, x=core.x, z=core.y, floors=sorted(core.floors),
                landings=landings,
            )
        )
    manifest = BuildingManifest(
        id=building_id(building), description=building.description,
        building_type=building.program.building_type, seed=building.seed, floors=floors,
        cores=cores,
    )
    return BuildingScenes([p.house for p in parts], manifest)
