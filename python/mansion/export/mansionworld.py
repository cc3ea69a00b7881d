"""``mansion export --format mansionworld``: a building in the MANSION authors' layout, so their
``MansionGym`` (``mansion-api``) and their MansionWorld tools open it.

What is written into the output folder (their conventions, see :mod:`mansion.scene.mansionworld`):

- ``floor_1.json`` … ``floor_N.json``, mansion's floors in order (1-based); ``floor_1.json`` is
  written last, so a folder their gym recognises has every floor;
- every room id prefixed ``F{n}_`` and every id naming a room renamed with it (walls, lights,
  objects, holes; ``|`` in an id, which their door ids split on, becomes ``__``); rooms that are
  not cores lose the words ``stair`` and ``elevator`` from their ids (their gym takes any room or
  object with those words for a core: ``stair_hall`` becomes ``F1_steps_hall``);
- the cores named as their gym looks them up: ``F{n}_stair``, ``F{n}_stair_2``, ``F{n}_elevator``,
  … on every floor they serve, each holding its fixtures: ``small_stair`` on every floor of the
  stair but its top one, ``small_stair_flat`` on every floor but its bottom one, an
  ``elevator_panel_N`` (N the smallest of 4, 5, 6, 8, 10 that is at least the floors served) on an
  elevator's side wall, named ``vertical_core_…_k (room)`` as their generator names them;
- each room's outline with a corner wherever another room's corner meets its edge (the same
  shape: their gym finds openings between rooms only so, see :func:`_t_junctions`);
- doors ``door|{i}|{room0}|{room1}``, the outside door with ``room1 = "exterior"``; an elevator's
  door has the elevator as ``room1`` (their ``CallElevator`` steps into ``room1``): where mansion
  had it as ``room0`` the door is turned over (walls swapped, hole mirrored into the other wall's
  frame, the same hole in the same place);
- ``metadata.agent`` (the spawn) beside ``agentPoses``; objects name their room in ``roomId``
  (mansion's ``room`` is kept, as are mansion's own records, with floor numbers 1-based).
"""

from __future__ import annotations

import copy
import math
import os
import re
from pathlib import Path
from typing import Any

from mansion._io import atomic_write_text
from mansion.exceptions import InvalidInputError
from mansion.scene.databases import hole_asset_position
from mansion.scene.house import House, Wall, house_text
from mansion.scene.manifest import ManifestCore
from mansion.scene.mansionworld import (
    ELEVATOR_PANEL,
    ELEVATOR_PANEL_SIZES,
    EXTERIOR,
    FIXTURE_PREFIX,
    STAIR_ASSET,
    STAIR_FLAT_ASSET,
    door_centre,
    floor_file,
    room_prefix,
    strip_prefix,
)
from mansion.scene.poses import yaw_of

__all__ = ["core_names", "room_names", "write_mansionworld"]

#: Their stair fixtures' heights (the centre of the asset's box): the flight and the landing slab.
STAIR_Y = 1.75
STAIR_FLAT_Y = 0.0125
#: Their panels hang at this height, face out of the wall (rotated 90 degrees about x).
PANEL_Y = 1.2
PANEL_DEPTH = 0.02
_UNSAFE = re.compile(r"[^A-Za-z0-9_&]")
_CORE_WORDS = ((re.compile("stairs?", re.I), "steps"), (re.compile("elevator", re.I), "lift"))


def _source(path: str | os.PathLike[str]) -> tuple[list[ManifestCore], dict[int, dict[str, Any]]]:
    """The cores and each floor's house (JSON) of a mansion building folder, a MansionWorld
    folder or a lone house JSON."""
    from mansion.export.building import read_building

    b = read_building(path)
    return b.cores, {k: h.to_dict() for k, h in b.houses.items()}


def core_names(cores: list[ManifestCore]) -> dict[str, str]:
    """Core id → their name for it: ``stair``, ``stair_2``, …, ``elevator``, … (by kind, in id
    order), the same on every floor."""
    out: dict[str, str] = {}
    for kind in ("stair", "elevator"):
        ids = sorted(c.id for c in cores if c.kind == kind)
        for k, cid in enumerate(ids, start=1):
            out[cid] = kind if k == 1 else f"{kind}_{k}"
    return out


def room_names(rooms: list[dict[str, Any]], n: int, cores: dict[str, str]) -> dict[str, str]:
    """Room id → its id on their floor ``n``. ``cores``: room id → core name on this floor."""
    out: dict[str, str] = {}
    taken: set[str] = set()
    for room in rooms:
        rid = str(room["id"])
        if rid in cores:
            new = room_prefix(n) + cores[rid]
        else:
            base = _UNSAFE.sub("_", strip_prefix(rid).replace("|", "__"))
            for pattern, word in _CORE_WORDS:
                base = pattern.sub(word, base)
            new = room_prefix(n) + (base or "room")
        stem, k = new, 2
        while new in taken or (rid not in cores and new in {room_prefix(n) + c for c in cores.values()}):
            new, k = f"{stem}_{k}", k + 1
        taken.add(new)
        out[rid] = new
    return out


class _Renamer:
    """Renames the room id inside another id (``wall|0|kitchen|2``, ``kitchen|fridge``): its
    first whole-word room id only (``toilet_1|toilet_1`` is the toilet of room ``toilet_1``),
    never a part of a longer name."""

    def __init__(self, names: dict[str, str]):
        self.names = names
        alts = "|".join(re.escape(r) for r in sorted(names, key=len, reverse=True))
        self.pattern = re.compile(rf"(?<![A-Za-z0-9_&])({alts})(?![A-Za-z0-9_&])") if names else None

    def __call__(self, s: Any) -> Any:
        if not isinstance(s, str) or self.pattern is None:
            return s
        return self.pattern.sub(lambda m: self.names[m.group(1)], s, count=1)

    def room(self, rid: Any) -> Any:
        return self.names.get(rid, rid)


def _objects(items: list[Any], rename: _Renamer) -> None:
    for obj in items:
        if not isinstance(obj, dict):
            continue
        obj["id"] = rename(obj.get("id"))
        if obj.get("room") is not None:
            obj["room"] = rename.room(obj["room"])
        room = obj.get("room") or rename.room(obj.get("roomId"))
        if room is not None:
            obj["roomId"] = room
        if obj.get("tuckedUnder") is not None:
            obj["tuckedUnder"] = rename(obj["tuckedUnder"])
        _objects(obj.get("children") or [], rename)


def _turn_over(door: dict[str, Any], walls: dict[str, Wall]) -> None:
    """The same hole described from the other side: room1/wall1 become room0/wall0 and the hole
    is mirrored into the other wall's frame (x → length − x)."""
    w1 = walls.get(door["wall1"])
    if w1 is None:
        return
    (ax, az), (bx, bz) = w1.segment()
    length = math.hypot(bx - ax, bz - az)
    lo, hi = door["holePolygon"]
    new_lo = {**lo, "x": length - hi["x"]}
    new_hi = {**hi, "x": length - lo["x"]}
    door["room0"], door["room1"] = door["room1"], door["room0"]
    door["wall0"], door["wall1"] = door["wall1"], door["wall0"]
    door["holePolygon"] = [new_lo, new_hi]
    at = hole_asset_position(str(door.get("assetId")), (new_lo["x"], new_lo["y"]))
    pos = door.get("assetPosition") or {}
    if at is None:
        at = ((new_lo["x"] + new_hi["x"]) / 2, float(pos.get("y", (lo["y"] + hi["y"]) / 2)))
    door["assetPosition"] = {**pos, "x": at[0], "y": at[1]}


def _t_junctions(rooms: list[dict[str, Any]]) -> None:
    """Put a corner in each room's outline wherever another room's corner meets its edge.

    Their gym joins two rooms through an opening when the strips along the rooms' edges (each
    edge shortened by 0.11 m at both ends, widened 0.2 m) overlap and no solid wall crosses the
    overlap; an edge running past the end of an opening, where a solid wall meets it, carries its
    strip across that wall and the opening is lost. Split there, each strip stops short of it.
    The rooms' shapes do not change (the new corners lie on their edges)."""
    corners = {(float(p["x"]), float(p["z"])) for r in rooms for p in r.get("floorPolygon") or []}
    for room in rooms:
        ring = room.get("floorPolygon") or []
        out = []
        for i, a in enumerate(ring):
            b = ring[(i + 1) % len(ring)]
            out.append(a)
            ax, az, bx, bz = float(a["x"]), float(a["z"]), float(b["x"]), float(b["z"])
            length = math.hypot(bx - ax, bz - az)
            if length <= 0:
                continue
            ux, uz = (bx - ax) / length, (bz - az) / length
            inner = []
            for cx, cz in corners:
                t = (cx - ax) * ux + (cz - az) * uz
                if 1e-6 < t < length - 1e-6 and abs((cx - ax) * uz - (cz - az) * ux) < 1e-6:
                    inner.append((t, cx, cz))
            out += [{**a, "x": cx, "z": cz} for _, cx, cz in sorted(inner)]
        room["floorPolygon"] = out


def _walls(house: dict[str, Any]) -> dict[str, Wall]:
    out = {}
    for w in house.get("walls") or []:
        try:
            out[w["id"]] = Wall.model_validate(w)
        except (KeyError, ValueError):
            pass
    return out


def _box(room: dict[str, Any]) -> tuple[float, float, float, float]:
    xs = [float(p["x"]) for p in room["floorPolygon"]]
    zs = [float(p["z"]) for p in room["floorPolygon"]]
    return min(xs), min(zs), max(xs), max(zs)


def _snap(yaw: float) -> float:
    return float((round(yaw / 90.0) * 90) % 360)


def _fixtures(room: dict[str, Any], kind: str, k: int, served: list[int], n: int,
              door: tuple[tuple[float, float], tuple[float, float]] | None) -> list[dict[str, Any]]:
    """Their fixtures of core room ``room`` on floor ``n`` (``k``: the core's rank of its kind,
    1-based; ``door``: the door's centre and wall direction)."""
    rid = str(room["id"])
    x0, z0, x1, z1 = _box(room)
    cx, cz = (x0 + x1) / 2, (z0 + z1) / 2
    out: list[dict[str, Any]] = []
    if kind == "stair":
        # their flight asset faces away from its +z: turned to face the door, then half a turn
        yaw = _snap(yaw_of(door[0][0] - cx, door[0][1] - cz) + 180.0) if door else 0.0
        parts = []
        if n != max(served):
            parts.append(("stair", STAIR_ASSET, STAIR_Y))
        if n != min(served):
            parts.append(("stair_flat", STAIR_FLAT_ASSET, STAIR_FLAT_Y))
        for label, asset, y in parts:
            out.append({
                "assetId": asset, "id": f"{FIXTURE_PREFIX}{label}_{k} ({rid})", "kinematic": True,
                "position": {"x": cx, "y": y, "z": cz}, "rotation": {"x": 0.0, "y": yaw, "z": 0.0},
                "room": rid, "roomId": rid,
            })
        return out
    size = next((s for s in ELEVATOR_PANEL_SIZES if len(served) <= s), ELEVATOR_PANEL_SIZES[-1])
    # the panel on the longest side wall (perpendicular to the door's wall), else the longest
    pts = [(float(p["x"]), float(p["z"])) for p in room["floorPolygon"]]
    edges = [(pts[i], pts[(i + 1) % len(pts)]) for i in range(len(pts))]

    def length(e: tuple[tuple[float, float], tuple[float, float]]) -> float:
        return math.dist(e[0], e[1])

    side = [e for e in edges if door is not None and length(e) > 0 and abs(
        ((e[1][0] - e[0][0]) * door[1][0] + (e[1][1] - e[0][1]) * door[1][1]) / length(e)) < 1e-2]
    (ax, az), (bx, bz) = max(side or edges, key=lambda e: (length(e), e))
    mx, mz = (ax + bx) / 2, (az + bz) / 2
    ux, uz = (bx - ax) / max(length(((ax, az), (bx, bz))), 1e-9), (bz - az) / max(length(((ax, az), (bx, bz))), 1e-9)
    nx, nz = -uz, ux
    if (cx - mx) * nx + (cz - mz) * nz < 0:
        nx, nz = -nx, -nz
    out.append({
        "assetId": f"{ELEVATOR_PANEL}_{size}", "id": f"{FIXTURE_PREFIX}elevator_panel_{k} ({rid})",
        "kinematic": True,
        "position": {"x": mx + nx * PANEL_DEPTH / 2, "y": PANEL_Y, "z": mz + nz * PANEL_DEPTH / 2},
        "rotation": {"x": 90.0, "y": _snap(yaw_of(nx, nz)), "z": 0.0}, "room": rid, "roomId": rid,
    })
    return out


def mansionworld_floor(
    data: dict[str, Any], n: int, floor: int, numbers: dict[int, int], cores: list[ManifestCore],
) -> tuple[dict[str, Any], dict[str, str], dict[str, str]]:
    """Floor ``floor`` (mansion's index) as their floor ``n``: the house, the room renames and
    the door renames."""
    house = copy.deepcopy(data)
    names_of = core_names(cores)
    here = {c.room_on(floor): c for c in cores if floor in c.floors}
    rooms = house.get("rooms") or []
    names = room_names(rooms, n, {rid: names_of[c.id] for rid, c in here.items()})
    rename = _Renamer(names)
    walls_before = _walls(house)
    kind_of = {rid: c.kind for rid, c in here.items()}
    doors: dict[str, str] = {}
    for i, d in enumerate(house.get("doors") or []):
        old = str(d.get("id"))
        outside = d.get("room0") == d.get("room1") or EXTERIOR in (d.get("room0"), d.get("room1"))
        if outside and d.get("room0") == EXTERIOR:
            d["room0"], d["room1"] = d["room1"], d["room0"]
        if not outside and kind_of.get(d.get("room0")) == "elevator" and d.get("room1") not in kind_of:
            _turn_over(d, walls_before)
        d["room0"] = rename.room(d.get("room0"))
        d["room1"] = EXTERIOR if outside else rename.room(d.get("room1"))
        d["wall0"], d["wall1"] = rename(d.get("wall0")), rename(d.get("wall1"))
        if d.get("swingRoom") is not None:
            d["swingRoom"] = rename.room(d["swingRoom"])
        d["id"] = f"door|{i}|{d['room0']}|{d['room1']}"
        doors[old] = d["id"]
    for win in house.get("windows") or []:
        win["id"] = rename(win.get("id"))
        win["room0"], win["room1"] = rename.room(win.get("room0")), rename.room(win.get("room1"))
        win["wall0"], win["wall1"] = rename(win.get("wall0")), rename(win.get("wall1"))
    for w in house.get("walls") or []:
        w["id"] = rename(w.get("id"))
        w["roomId"] = rename.room(w.get("roomId"))
    for light in (house.get("proceduralParameters") or {}).get("lights") or []:
        light["id"] = rename(light.get("id"))
        if light.get("roomId") is not None:
            light["roomId"] = rename.room(light["roomId"])
    _objects(house.get("objects") or [], rename)
    walls_after = _walls(house)
    fixtures: list[dict[str, Any]] = []
    rank = {cid: int(name.rsplit("_", 1)[1]) if "_" in name else 1 for cid, name in names_of.items()}
    _t_junctions(rooms)
    for room in rooms:
        old_id = str(room["id"])
        room["id"] = names[old_id]
        for ceiling in room.get("ceilings") or []:
            ceiling["id"] = rename(ceiling.get("id"))
        meta = room.get("metadata") or {}
        rec = meta.get("core")
        if isinstance(rec, dict):
            rec["floors"] = sorted(numbers.get(f, f) for f in rec.get("floors") or [])
            if rec.get("door") is not None:
                rec["door"] = doors.get(rec["door"], rec["door"])
            if rec.get("landingRoom") is not None:
                rec["landingRoom"] = rename.room(rec["landingRoom"])
        core = here.get(old_id)
        if core is not None:
            door = next((d for d in house.get("doors") or [] if room["id"] in (d["room0"], d["room1"])), None)
            at = door_centre(door, walls_after) if door is not None else None
            served = sorted(numbers[f] for f in core.floors if f in numbers)
            fixtures += _fixtures(room, core.kind, rank[core.id], served, n, at)
    house["objects"] = [o for o in house.get("objects") or [] if not str(o.get("id", "")).startswith(FIXTURE_PREFIX)] + fixtures
    meta = house.setdefault("metadata", {})
    poses = meta.get("agentPoses") or {}
    spawn = meta.get("agent") or poses.get("default") or next(iter(poses.values()), None)
    if spawn is None:
        raise InvalidInputError(f"floor {floor} has no agent pose (metadata.agentPoses): their gym "
                                "starts the agent at metadata.agent")
    meta["agent"] = copy.deepcopy(spawn)
    record = meta.get("mansion")
    if isinstance(record, dict):
        record["floor"] = n
        if record.get("hub") is not None:
            record["hub"] = rename.room(record["hub"])
        if record.get("copyOf") is not None:
            record["copyOf"] = numbers.get(record["copyOf"], record["copyOf"])
        furnishing = record.get("furnishing")
        if isinstance(furnishing, dict) and isinstance(furnishing.get("rooms"), dict):
            furnishing["rooms"] = {rename.room(k): v for k, v in furnishing["rooms"].items()}
    House.parse(house, source=floor_file(n))
    return house, names, doors


def write_mansionworld(building: str | os.PathLike[str], out: str | os.PathLike[str]) -> Path:
    """Write ``building`` (a mansion building folder, its manifest, a lone house JSON or a
    MansionWorld folder) into the folder ``out`` in their layout; returns ``out``."""
    cores, houses = _source(building)
    folder = Path(out)
    if folder.exists() and not folder.is_dir():
        raise InvalidInputError(f"--format mansionworld writes a folder; {str(folder)!r} is a file")
    if (folder / "manifest.json").is_file():
        raise InvalidInputError(f"{str(folder)!r} holds a mansion building (manifest.json): "
                                "give an empty or MansionWorld folder")
    order = sorted(houses)
    numbers = {k: i + 1 for i, k in enumerate(order)}
    texts = {}
    for k in order:
        house, _, _ = mansionworld_floor(houses[k], numbers[k], k, numbers, cores)
        texts[numbers[k]] = house_text(house)
    folder.mkdir(parents=True, exist_ok=True)
    # floors left from a taller building written here before would be read as this one's
    stale = len(order) + 1
    while (folder / floor_file(stale)).is_file():
        (folder / floor_file(stale)).unlink()
        stale += 1
    for n in sorted(texts, reverse=True):
        atomic_write_text(folder / floor_file(n), texts[n])
    return folder
