"""Buildings in the MANSION authors' layout (their MansionWorld dataset and ``mansion_api``'s
``MansionGym``), read into the same in-memory view mansion's own manifest gives.

Their layout, as their gym reads it (``mansion-api`` 0.1.3) and their generator writes it: one
AI2-THOR house per floor named ``floor_1.json``, ``floor_2.json``, … (1-based, no gap, no
manifest); the agent's start in ``metadata.agent``; every room id prefixed ``F{n}_`` with ``n``
the floor; doors ``door|{i}|{room0}|{room1}`` (the outside door's ``room1`` is ``exterior``);
the cores are rooms named ``F{n}_stair``, ``F{n}_stair_2``, ``F{n}_elevator``, … (their roomType
``stair`` / ``elevator``) holding their fixtures: the stair asset ``small_stair`` on every floor
but the top one and ``small_stair_flat`` on every floor but the bottom one, an ``elevator_panel_N``
on an elevator's wall. Nothing else links the floors: a core is the stair or elevator room at the
same box on consecutive floors.

Reading such a folder (:func:`read_mansionworld`) gives a :class:`BuildingManifest` whose floors
keep their numbers (1, 2, …: floor ``n`` is ``floor_n.json`` and its rooms ``F{n}_…``), whose
cores are those rooms linked by box (each landing names the core's room on its floor,
``core_room``), and one house per floor as mansion reads its own: the core rooms carry their core
record (``metadata.core``), the outside door has ``room0 == room1`` (ProcTHOR's convention),
objects name their room in ``room``, and the core fixtures, which mansion represents by the core
record rather than by objects, are left out. The files are not changed.
"""

from __future__ import annotations

import copy
import json
import math
import os
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from shapely.geometry import Point, Polygon

from mansion.exceptions import InvalidInputError
from mansion.scene.house import AgentPose, CoreRecord, FloorRecord, House, Wall
from mansion.scene.manifest import BuildingManifest, CoreLanding, ManifestCore, ManifestFloor
from mansion.scene.poses import AGENT_MODES, landing_pose

__all__ = [
    "ELEVATOR_PANEL",
    "EXTERIOR",
    "FIXTURE_PREFIX",
    "MansionWorldBuilding",
    "STAIR_ASSET",
    "STAIR_FLAT_ASSET",
    "core_kind",
    "door_centre",
    "floor_file",
    "floor_numbers",
    "is_fixture",
    "is_mansionworld",
    "read_mansionworld",
    "room_prefix",
    "strip_prefix",
]

#: Their stair fixtures (the asset ids their generator places; shipped in their asset patch).
STAIR_ASSET = "small_stair"
STAIR_FLAT_ASSET = "small_stair_flat"
#: Their elevator panels are ``elevator_panel_N``, N the smallest of these >= the floors served.
ELEVATOR_PANEL = "elevator_panel"
ELEVATOR_PANEL_SIZES = (4, 5, 6, 8, 10)
#: Their generator names every core fixture ``vertical_core_<what>_<k> (<room>)``.
FIXTURE_PREFIX = "vertical_core_"
#: ``room1`` of their outside door.
EXTERIOR = "exterior"
#: Room types their generator takes for cores (lower case).
STAIR_TYPES = frozenset({"stair", "stairs", "staircase", "stairwell"})
ELEVATOR_TYPES = frozenset({"elevator", "lift"})
#: Room ids their gym takes for cores once the ``F{n}_`` prefix is off.
_CORE_NAME = re.compile(r"^(stair|elevator)(?:_(\d+))?$")
_PREFIX = re.compile(r"^F(\d+)_(.+)$")
#: Floor-to-floor height beyond the ceiling when a file does not say (mansion's slab, m).
_SLAB = 0.3
#: Two rooms of consecutive floors are one core when their boxes overlap this much (IoU).
_SAME_BOX = 0.5


def floor_file(n: int) -> str:
    """Their file of floor ``n`` (1-based)."""
    return f"floor_{n}.json"


def room_prefix(n: int) -> str:
    return f"F{n}_"


def strip_prefix(room_id: str) -> str:
    """``F2_kitchen`` → ``kitchen`` (an id without their prefix is returned as is)."""
    m = _PREFIX.match(room_id)
    return m.group(2) if m else room_id


def _mansion_manifest(folder: Path) -> bool:
    return (folder / "manifest.json").is_file() or (folder / "scenes" / "manifest.json").is_file()


def is_mansionworld(path: str | os.PathLike[str]) -> bool:
    """A folder in their layout: ``floor_1.json`` and no mansion manifest."""
    p = Path(path)
    return p.is_dir() and (p / floor_file(1)).is_file() and not _mansion_manifest(p)


def floor_numbers(folder: Path) -> list[int]:
    """1, 2, … while ``floor_n.json`` exists (their gym stops at the first gap too)."""
    out = []
    n = 1
    while (folder / floor_file(n)).is_file():
        out.append(n)
        n += 1
    return out


def core_kind(room: dict[str, Any]) -> str | None:
    """``stair`` or ``elevator`` when the room is a core by its name or type, else None. A core
    must also be a box (an axis-aligned rectangle): a shaft, not a stair hall."""
    name = strip_prefix(str(room.get("id", "")))
    m = _CORE_NAME.match(name.lower())
    kind = m.group(1) if m else None
    if kind is None:
        rtype = str(room.get("roomType", "")).lower()
        kind = "stair" if rtype in STAIR_TYPES else "elevator" if rtype in ELEVATOR_TYPES else None
    if kind is None:
        return None
    poly = _polygon(room)
    if poly is None:
        return None
    x0, z0, x1, z1 = poly.bounds
    return kind if abs((x1 - x0) * (z1 - z0) - poly.area) <= 0.01 * max(poly.area, 1e-9) else None


def _polygon(room: dict[str, Any]) -> Polygon | None:
    try:
        pts = [(float(p["x"]), float(p["z"])) for p in room.get("floorPolygon") or []]
    except (KeyError, TypeError, ValueError):
        return None
    if len(pts) < 3:
        return None
    poly = Polygon(pts)
    return poly if poly.is_valid and poly.area > 0 else None


def _iou(a: tuple[float, float, float, float], b: tuple[float, float, float, float]) -> float:
    ix = max(0.0, min(a[2], b[2]) - max(a[0], b[0]))
    iz = max(0.0, min(a[3], b[3]) - max(a[1], b[1]))
    inter = ix * iz
    union = (a[2] - a[0]) * (a[3] - a[1]) + (b[2] - b[0]) * (b[3] - b[1]) - inter
    return inter / union if union > 0 else 0.0


def is_fixture(obj: dict[str, Any]) -> bool:
    """A stair or elevator fixture of theirs (mansion keeps cores as records, not objects)."""
    asset = str(obj.get("assetId", "")).lower()
    return (asset in (STAIR_ASSET, STAIR_FLAT_ASSET) or asset.startswith(ELEVATOR_PANEL)
            or str(obj.get("id", "")).startswith(FIXTURE_PREFIX))


@dataclass
class _CoreRooms:
    kind: str
    box: tuple[float, float, float, float]
    rooms: dict[int, str] = field(default_factory=dict)
    name: str = ""


@dataclass
class MansionWorldBuilding:
    """A MansionWorld folder read: the manifest mansion would have written for it, the floors'
    files, and each floor's house as mansion reads it (JSON dicts, see the module doc)."""

    folder: Path
    manifest: BuildingManifest
    files: dict[int, Path]
    houses: dict[int, dict[str, Any]]
    #: per floor, the ids of the core fixtures left out of the house
    fixtures: dict[int, list[str]]

    def house_bytes(self, floor: int) -> bytes:
        return json.dumps(self.houses[floor]).encode("utf-8")

    def house(self, floor: int) -> House:
        return House.parse(self.houses[floor], source=str(self.files[floor]))


def _read(path: Path) -> dict[str, Any]:
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise InvalidInputError(f"cannot read house JSON {str(path)!r}: {exc}") from exc
    if not isinstance(data, dict) or not isinstance(data.get("rooms"), list):
        raise InvalidInputError(f"{str(path)!r} is no AI2-THOR house (no rooms)")
    return data


def _spawn(data: dict[str, Any], source: Path) -> AgentPose:
    meta = data.get("metadata") or {}
    raw = meta.get("agent") or (meta.get("agentPoses") or {}).get("default")
    if not raw:
        poses = meta.get("agentPoses") or {}
        raw = next(iter(poses.values()), None)
    if not raw:
        raise InvalidInputError(f"{str(source)!r} has no metadata.agent (nor agentPoses): "
                                "where the agent starts is missing")
    try:
        return AgentPose.model_validate(raw)
    except ValueError as exc:
        raise InvalidInputError(f"{str(source)!r}: metadata.agent is no pose: {exc}") from exc


def _ceiling(data: dict[str, Any]) -> float:
    best = 0.0
    for w in data.get("walls") or []:
        ys = [float(p.get("y", 0.0)) for p in w.get("polygon") or [] if isinstance(p, dict)]
        if ys:
            best = max(best, max(ys) - min(ys))
    return best if best > 0 else 3.0


def _walls(data: dict[str, Any]) -> dict[str, Wall]:
    out = {}
    for w in data.get("walls") or []:
        try:
            wall = Wall.model_validate(w)
        except ValueError:
            continue
        out[wall.id] = wall
    return out


def door_centre(door: dict[str, Any], walls: dict[str, Wall]) -> tuple[tuple[float, float], tuple[float, float]] | None:
    """The centre of a door's hole on the floor plane, and the unit direction of its wall."""
    wall = walls.get(str(door.get("wall0")))
    hole = door.get("holePolygon") or []
    if wall is None or len(hole) < 2:
        return None
    (ax, az), (bx, bz) = wall.segment()
    length = math.hypot(bx - ax, bz - az)
    if length <= 0:
        return None
    ux, uz = (bx - ax) / length, (bz - az) / length
    t = (float(hole[0]["x"]) + float(hole[1]["x"])) / 2
    return (ax + ux * t, az + uz * t), (ux, uz)


def _landing(data: dict[str, Any], core_room: str, polys: dict[str, Polygon],
             walls: dict[str, Wall]) -> tuple[str | None, str, AgentPose] | None:
    """The core's door on this floor (or its widest opening), the room beyond and the pose a
    step into that room facing away from the core."""
    core_poly = polys[core_room]
    c = core_poly.centroid
    for door in sorted(data.get("doors") or [], key=lambda d: str(d.get("id"))):
        rooms = (door.get("room0"), door.get("room1"))
        if core_room not in rooms:
            continue
        other = rooms[1] if rooms[0] == core_room else rooms[0]
        if other == core_room or other not in polys:
            continue
        at = door_centre(door, walls)
        if at is None:
            continue
        (x, z), (ux, uz) = at
        nx, nz = -uz, ux
        if (x - c.x) * nx + (z - c.y) * nz < 0:
            nx, nz = -nx, -nz
        return str(door.get("id")), str(other), landing_pose(polys[other], (x, z), (nx, nz))
    # no door: the longest empty wall the core shares with another room (an opening)
    best: tuple[float, str, tuple[float, float], tuple[float, float]] | None = None
    for w in walls.values():
        if not w.empty or w.room_id == core_room or w.room_id not in polys:
            continue
        (ax, az), (bx, bz) = w.segment()
        seg_len = math.hypot(bx - ax, bz - az)
        mid = ((ax + bx) / 2, (az + bz) / 2)
        if seg_len <= 0 or core_poly.boundary.distance(Point(mid)) > 1e-3:
            continue
        if best is None or seg_len > best[0]:
            best = (seg_len, w.room_id, mid, ((bx - ax) / seg_len, (bz - az) / seg_len))
    if best is None:
        return None
    _, other, (x, z), (ux, uz) = best
    nx, nz = -uz, ux
    if (x - c.x) * nx + (z - c.y) * nz < 0:
        nx, nz = -nx, -nz
    return None, other, landing_pose(polys[other], (x, z), (nx, nz))


def _objects(items: list[Any], room: str | None, dropped: list[str], cores: set[str]) -> list[Any]:
    out = []
    for obj in items:
        if not isinstance(obj, dict):
            out.append(obj)
            continue
        where = obj.get("room") or obj.get("roomId") or room
        if is_fixture(obj) and (where in cores or not where):
            dropped.append(str(obj.get("id")))
            continue
        obj = dict(obj)
        if obj.get("room") is None and where is not None:
            obj["room"] = where
        if isinstance(obj.get("children"), list):
            obj["children"] = _objects(obj["children"], where, dropped, cores)
        out.append(obj)
    return out


def _link_cores(floors: dict[int, dict[str, Any]]) -> list[_CoreRooms]:
    """Stair and elevator rooms of consecutive floors at the same box → one core each."""
    groups: list[_CoreRooms] = []
    for n in sorted(floors):
        for room in floors[n].get("rooms") or []:
            kind = core_kind(room)
            if kind is None:
                continue
            poly = _polygon(room)
            assert poly is not None
            box = poly.bounds
            rid = str(room["id"])
            match = None
            for g in groups:
                if g.kind == kind and n not in g.rooms and (n - 1) in g.rooms and _iou(g.box, box) >= _SAME_BOX:
                    match = g
                    break
            if match is None:
                match = _CoreRooms(kind, box)
                groups.append(match)
            match.rooms[n] = rid
    used: set[str] = set()
    for g in groups:
        first = g.rooms[min(g.rooms)]
        records = {((r.get("metadata") or {}).get("core") or {}).get("id")
                   for n, rid in g.rooms.items() for r in floors[n]["rooms"] if r["id"] == rid}
        # mansion's own export keeps its core ids in the rooms' records; else their room name
        name = str(records.pop()) if len(records) == 1 and None not in records else strip_prefix(first)
        base, k = name, 2
        while name in used:
            name, k = f"{base}_{k}", k + 1
        used.add(name)
        g.name = name
    return groups


def read_mansionworld(path: str | os.PathLike[str]) -> MansionWorldBuilding:
    """Read a building folder in their layout (see the module doc)."""
    folder = Path(path)
    if not is_mansionworld(folder):
        raise InvalidInputError(f"{str(folder)!r} is no MansionWorld building: no floor_1.json "
                                "(their floors are floor_1.json, floor_2.json, …), or it has a mansion manifest")
    numbers = floor_numbers(folder)
    files = {n: folder / floor_file(n) for n in numbers}
    raw = {n: _read(files[n]) for n in numbers}
    groups = _link_cores(raw)
    houses: dict[int, dict[str, Any]] = {}
    fixtures: dict[int, list[str]] = {}
    manifest_floors: list[ManifestFloor] = []
    landings: dict[int, list[CoreLanding]] = {i: [] for i in range(len(groups))}
    first = numbers[0]
    for n in numbers:
        data = copy.deepcopy(raw[n])
        spawn = _spawn(data, files[n])
        polys = {str(r.get("id")): p for r in data["rooms"] if (p := _polygon(r)) is not None}
        walls = _walls(data)
        core_rooms = {g.rooms[n]: i for i, g in enumerate(groups) if n in g.rooms}
        for door in data.get("doors") or []:
            # ProcTHOR's outside door (room0 == room1), which mansion reads, for their "exterior"
            if door.get("room1") == EXTERIOR:
                door["room1"] = door.get("room0")
            elif door.get("room0") == EXTERIOR:
                door["room0"] = door.get("room1")
        dropped: list[str] = []
        data["objects"] = _objects(data.get("objects") or [], None, dropped, set(core_rooms))
        fixtures[n] = dropped
        for rid, i in core_rooms.items():
            g = groups[i]
            found = _landing(data, rid, polys, walls)
            room = next(r for r in data["rooms"] if r.get("id") == rid)
            old = ((room.get("metadata") or {}).get("core")) or {}
            record: dict[str, Any] = {
                "id": g.name, "kind": g.kind, "floors": sorted(g.rooms), "box": list(g.box),
            }
            if found is not None:
                door_id, other, pose = found
                # a landing written by mansion's export is kept: it is the one mansion chose
                if old.get("landing") and old.get("landingRoom") == other and old.get("door") == door_id:
                    pose = AgentPose.model_validate(old["landing"])
                record.update(door=door_id, landingRoom=other, landing=pose.model_dump(mode="json", by_alias=True))
                landings[i].append(CoreLanding(floor=n, room=other, door=door_id, pose=pose, core_room=rid))
            room["metadata"] = {**(room.get("metadata") or {}),
                                "core": CoreRecord.model_validate(record).model_dump(mode="json", by_alias=True, exclude_none=True)}
        meta = data.setdefault("metadata", {})
        poses = meta.setdefault("agentPoses", {})
        for mode in AGENT_MODES:
            poses.setdefault(mode, spawn.model_dump(mode="json", by_alias=True))
        meta.setdefault("schema", "1.0.0")
        ceiling = _ceiling(data)
        record_floor = meta.get("mansion") if isinstance(meta.get("mansion"), dict) else None
        elevation = float(record_floor["elevation"]) if record_floor and "elevation" in record_floor \
            else (n - first) * (ceiling + _SLAB)
        at = Point(spawn.position.x, spawn.position.z)
        hub = next((rid for rid, p in polys.items() if p.covers(at)), next(iter(polys), ""))
        if record_floor is None:
            meta["mansion"] = FloorRecord(
                building=folder.name, floor=n, floor_count=len(numbers), elevation=elevation,
                ceiling_height=ceiling, hub=hub,
            ).model_dump(mode="json", by_alias=True, exclude_none=True)
        entrance = next((str(d.get("id")) for d in data.get("doors") or []
                         if d.get("room0") == d.get("room1")), None)
        manifest_floors.append(ManifestFloor(
            index=n, house=floor_file(n), elevation=elevation, height=ceiling + _SLAB,
            ceiling_height=ceiling, hub=hub, spawn=spawn, entrance=entrance,
        ))
        houses[n] = data
    cores = [
        ManifestCore(id=g.name, kind=g.kind, x=(g.box[0], g.box[2]), z=(g.box[1], g.box[3]),  # type: ignore[arg-type]
                     floors=sorted(g.rooms), landings=landings[i])
        for i, g in enumerate(groups)
    ]
    manifest = BuildingManifest(
        id=folder.name, description=f"MansionWorld building {folder.name}",
        building_type="mansionworld", seed=0, floors=manifest_floors, cores=cores,
    )
    return MansionWorldBuilding(folder, manifest, files, houses, fixtures)
