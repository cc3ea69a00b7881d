"""Checks of a house JSON (and of a whole building) against what the simulator needs.

Every rule here is one the loader or the scene's users depend on (docs/HOUSE_JSON.md):

- ``schema``: the house parses as schema 1.0.0 (``metadata.schema == "1.0.0"``), ids are unique;
- ``room-polygon``: floor polygons lie at y = 0 and are simple with positive area;
- ``room-overlap``: rooms do not overlap;
- ``wall-geometry``: a wall is a vertical rectangle on the floor with two distinct bottom points;
- ``wall-room``: a wall names a room that exists and bounds it, facing it (or, as an exterior
  twin, facing away from it into the outside);
- ``wall-closure``: each room's walls facing it cover its boundary exactly once;
- ``wall-pair``: every wall has exactly one twin, the same stretch reversed;
- ``hole-wall``: a door's or window's walls exist and its hole lies inside wall0;
- ``one-hole-per-wall``: no wall carries two holes (the loader fails on the whole house);
- ``door-floor``: door holes start at the floor;
- ``door-rooms``: a door joins the two rooms it names (wall0 is room0's, wall1 room1's);
- ``hole-twins``: wall1 is wall0's twin, so the hole mirrored onto wall1 lines up;
- ``asset-position``: a hole's ``assetPosition`` is the hole's centre;
- ``asset-id``: door, window and object assets exist in AI2-THOR's asset database, doors are
  doorways and windows windows; materials exist in its material database;
- ``object-in-room``: every object's centre lies inside a room (its own room when it names one)
  and its footprint (the asset's bounding box, turned by its rotation) within that room, to 1 cm;
- ``object-overlap``: no two floor objects of a room overlap by more than 1e-4 m², except a chair
  or stool tucked under (``tuckedUnder``) the table or desk it is paired with;
- ``object-child``: a small object lies on its receptacle: inside its footprint (1 cm), its
  bottom on the receptacle's top;
- ``object-reach``: an independent flood fill over the room's free space (the agent's radius,
  0.25 m unless the floor records another, from every solid wall and object) from the cells just
  inside its first door or opening an agent passes: every other such entrance is reached, every
  object has a reached cell within 0.5 m of its footprint (in front of it when it is used from
  one side), and no object stands on an agent pose;
- ``reachable``: every room is reached from the hub through doors and empty walls, and every agent
  pose stands inside a room.

For a building (its ``manifest.json``): every floor's house, plus ``core-align``: each core is a
room of every floor it serves, at the same box, with a door, and its landing stands in a room.

Each problem names the element (room, wall, door, window, object or core id); nothing stops at
the first problem.
"""

from __future__ import annotations

import json
import math
import os
from collections import defaultdict, deque
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from pydantic import ValidationError
from shapely.geometry import Point, Polygon
from shapely.strtree import STRtree

from mansion.exceptions import InvalidInputError
from mansion.scene.databases import asset_ids, material_names, skyboxes
from mansion.placement import check
from mansion.placement.assets import FRONT_TYPES, TABLES, TUCKABLE
from mansion.scene.entrances import room_entrances
from mansion.scene.house import HOUSE_SCHEMA, House, HouseObject, Vec3, Wall
from mansion.scene.manifest import BuildingManifest

__all__ = ["Problem", "validate_building", "validate_house", "validate_path"]

EPS = 1e-4
#: An object's footprint may leave its room by this much (issue 6's #OB: 1 cm).
OBJECT_TOLERANCE = 0.01
#: Two floor objects overlap when they share more than this (m², issue 6's #CN).
OVERLAP_AREA = 1e-4
#: The agent reaches an object from a free cell this close to its footprint (m).
REACH = 0.5
#: The agent's radius when the house records none (AI2-THOR's agents fit in 0.25 m).
AGENT_RADIUS = 0.25


@dataclass(frozen=True)
class _Placed:
    """An object with its type and footprint from AI2-THOR's asset database."""

    obj: HouseObject
    type: str
    fp: Polygon
    height: float
    depth: float


def _tucked(seat: _Placed, table: _Placed) -> bool:
    return (seat.obj.tucked_under == table.obj.id and seat.type in TUCKABLE
            and table.type in TABLES)


@dataclass(frozen=True)
class Problem:
    rule: str
    element: str
    message: str
    source: str = ""

    def __str__(self) -> str:
        where = f"{self.source}: " if self.source else ""
        return f"{where}[{self.rule}] {self.element}: {self.message}"


def _xz(v: Vec3) -> tuple[float, float]:
    return (v.x, v.z)


@dataclass(frozen=True)
class _Seg:
    p0: tuple[float, float]
    p1: tuple[float, float]
    height: float

    @property
    def length(self) -> float:
        return math.dist(self.p0, self.p1)

    def key(self) -> tuple[tuple[float, float], tuple[float, float]]:
        r = lambda p: (round(p[0], 4) + 0.0, round(p[1], 4) + 0.0)  # noqa: E731
        return (r(self.p0), r(self.p1))

    def at(self, t: float) -> tuple[float, float]:
        n = self.length
        return (
            self.p0[0] + (self.p1[0] - self.p0[0]) * t / n,
            self.p0[1] + (self.p1[1] - self.p0[1]) * t / n,
        )

    def side_point(self, right: bool, eps: float = 0.02) -> tuple[float, float]:
        """A point just beside the wall's middle, to its right (seen from above, x right and
        z up) or its left."""
        n = self.length
        dx, dz = (self.p1[0] - self.p0[0]) / n, (self.p1[1] - self.p0[1]) / n
        nx, nz = (dz, -dx) if right else (-dz, dx)
        m = self.at(n / 2)
        return (m[0] + nx * eps, m[1] + nz * eps)


def _wall_segment(wall: Wall) -> _Seg | None:
    p0, p1 = wall.segment()
    height = max(p.y for p in wall.polygon) - min(p.y for p in wall.polygon)
    seg = _Seg(p0, p1, height)
    if seg.length < EPS or height <= EPS:
        return None
    return seg


class _HouseCheck:
    def __init__(self, house: House, source: str):
        self.house, self.source = house, source
        self.problems: list[Problem] = []

    def add(self, rule: str, element: str, message: str) -> None:
        self.problems.append(Problem(rule, element, message, self.source))

    def run(self) -> list[Problem]:
        h = self.house
        if h.metadata.schema_version != HOUSE_SCHEMA:
            self.add("schema", "metadata", f"schema is {h.metadata.schema_version!r}, not {HOUSE_SCHEMA!r}")
        self.ids()
        self.polys = self.rooms()
        self.segs = self.walls()
        self.pairs()
        self.closure()
        self.holes()
        self.assets()
        self.entrances = room_entrances(self.house)
        self.objects()
        self.reach()
        return self.problems

    def ids(self) -> None:
        seen: dict[str, str] = {}
        h = self.house
        groups: dict[str, list[Any]] = {
            "room": h.rooms, "wall": h.walls, "door": h.doors, "window": h.windows,
            "object": h.objects,
        }
        for kind, items in groups.items():
            for item in items:
                if item.id in seen:
                    self.add("schema", item.id, f"{kind} id already used by a {seen[item.id]}")
                seen[item.id] = kind

    def rooms(self) -> dict[str, Polygon]:
        polys: dict[str, Polygon] = {}
        for room in self.house.rooms:
            if any(abs(p.y) > EPS for p in room.floor_polygon):
                self.add("room-polygon", room.id, "floor polygon points must have y = 0")
            poly = Polygon([_xz(p) for p in room.floor_polygon])
            if not poly.is_valid or poly.area <= EPS:
                self.add("room-polygon", room.id, "floor polygon is not a simple polygon with area")
                continue
            polys[room.id] = poly
        ids = list(polys)
        tree = STRtree([polys[i] for i in ids])
        for k, rid in enumerate(ids):
            for j in tree.query(polys[rid]):
                other = ids[int(j)]
                if int(j) > k and polys[rid].intersection(polys[other]).area > 1e-3:
                    self.add("room-overlap", rid, f"overlaps room {other!r} "
                             f"({polys[rid].intersection(polys[other]).area:.3f} m²)")
        return polys

    def walls(self) -> dict[str, _Seg]:
        segs: dict[str, _Seg] = {}
        self.faces: dict[str, bool] = {}  # wall id → faces its room (False: exterior twin)
        for wall in self.house.walls:
            seg = _wall_segment(wall)
            if seg is None:
                self.add("wall-geometry", wall.id, "wall has no length or no height")
                continue
            if any(abs(p.y - min(q.y for q in wall.polygon)) > EPS and abs(p.y - min(q.y for q in wall.polygon) - seg.height) > EPS for p in wall.polygon):
                self.add("wall-geometry", wall.id, "wall polygon is not a rectangle")
            segs[wall.id] = seg
            poly = self.polys.get(wall.room_id)
            if poly is None:
                if wall.room_id not in {r.id for r in self.house.rooms}:
                    self.add("wall-room", wall.id, f"names room {wall.room_id!r}, which does not exist")
                continue
            if poly.contains(Point(seg.side_point(True))):
                self.faces[wall.id] = True
            elif poly.contains(Point(seg.side_point(False))) and not any(
                p.contains(Point(seg.side_point(True))) for p in self.polys.values()
            ):
                self.faces[wall.id] = False
            else:
                self.add("wall-room", wall.id, f"does not bound room {wall.room_id!r} "
                         "(the room must be on the right of p0→p1, or on the left of an exterior twin)")
        return segs

    def pairs(self) -> None:
        by_key: dict[Any, list[str]] = defaultdict(list)
        for wid, seg in self.segs.items():
            by_key[seg.key()].append(wid)
        self.twin: dict[str, str] = {}
        for wid, seg in self.segs.items():
            k0, k1 = seg.key()
            twins = by_key.get((k1, k0), [])
            if len(twins) != 1:
                what = "no twin (the same stretch reversed)" if not twins else f"{len(twins)} twins {twins}"
                self.add("wall-pair", wid, f"has {what}")
            else:
                self.twin[wid] = twins[0]
        for key, ids in by_key.items():
            if len(ids) > 1:
                self.add("wall-pair", ids[1], f"duplicates wall {ids[0]!r}")

    def closure(self) -> None:
        by_room: dict[str, list[_Seg]] = defaultdict(list)
        for wall in self.house.walls:
            if self.faces.get(wall.id) and wall.id in self.segs:
                by_room[wall.room_id].append(self.segs[wall.id])
        for rid, poly in self.polys.items():
            segs = by_room.get(rid, [])
            total = sum(s.length for s in segs)
            if abs(total - poly.exterior.length) > 1e-3:
                self.add("wall-closure", rid, f"walls facing the room cover {total:.3f} m of its "
                         f"{poly.exterior.length:.3f} m boundary")
                continue
            boundary = poly.exterior
            for s in segs:
                if boundary.distance(Point(s.at(s.length / 2))) > 1e-3 or boundary.distance(Point(s.p0)) > 1e-3:
                    self.add("wall-closure", rid, f"a wall at {s.p0} → {s.p1} is not on its boundary")
            # Equal length and all on the boundary: any overlap would leave a gap elsewhere.
            lines: dict[Any, list[tuple[float, float]]] = defaultdict(list)
            for s in segs:
                if abs(s.p0[1] - s.p1[1]) < EPS:
                    lines[("z", round(s.p0[1], 4))].append((min(s.p0[0], s.p1[0]), max(s.p0[0], s.p1[0])))
                elif abs(s.p0[0] - s.p1[0]) < EPS:
                    lines[("x", round(s.p0[0], 4))].append((min(s.p0[1], s.p1[1]), max(s.p0[1], s.p1[1])))
            for spans in lines.values():
                spans.sort()
                for (a0, a1), (b0, b1) in zip(spans, spans[1:]):
                    if b0 < a1 - 1e-3:
                        self.add("wall-closure", rid, f"two walls overlap between {b0:.3f} and {a1:.3f}")

    def holes(self) -> None:
        walls = {w.id: w for w in self.house.walls}
        rooms = {r.id for r in self.house.rooms}
        per_wall: dict[str, list[str]] = defaultdict(list)
        for kind, items in (("door", self.house.doors), ("window", self.house.windows)):
            for hole in items:
                for w in (hole.wall0, hole.wall1):
                    per_wall[w].append(hole.id)
                missing = [w for w in (hole.wall0, hole.wall1) if w not in walls]
                if missing:
                    self.add("hole-wall", hole.id, f"names wall(s) {missing} that do not exist")
                    continue
                for r in (hole.room0, hole.room1):
                    if r not in rooms:
                        self.add("door-rooms", hole.id, f"names room {r!r}, which does not exist")
                w0, w1 = walls[hole.wall0], walls[hole.wall1]
                if w0.room_id != hole.room0 or w1.room_id != hole.room1:
                    self.add("door-rooms", hole.id, f"joins {hole.room0!r} and {hole.room1!r} but "
                             f"its walls belong to {w0.room_id!r} and {w1.room_id!r}")
                if kind == "door" and hole.room0 == hole.room1:
                    self.add("door-rooms", hole.id, "joins a room to itself")
                lo, hi = hole.hole_polygon
                s0, s1 = self.segs.get(w0.id), self.segs.get(w1.id)
                if s0 is None or s1 is None:
                    continue
                if not (-EPS <= lo.x < hi.x <= s0.length + EPS and -EPS <= lo.y < hi.y <= s0.height + EPS):
                    self.add("hole-wall", hole.id, f"hole x {lo.x:.3f}..{hi.x:.3f}, y {lo.y:.3f}..{hi.y:.3f} "
                             f"is not inside wall {w0.id!r} ({s0.length:.3f} × {s0.height:.3f} m)")
                if kind == "door" and abs(lo.y) > EPS:
                    self.add("door-floor", hole.id, f"door hole starts at y = {lo.y:.3f}, not the floor")
                if self.twin.get(w0.id) != w1.id:
                    self.add("hole-twins", hole.id, f"wall1 {w1.id!r} is not the twin of wall0 {w0.id!r}")
                else:
                    a, b = s0.at(lo.x), s0.at(hi.x)
                    c, d = s1.at(s1.length - lo.x), s1.at(s1.length - hi.x)
                    if math.dist(a, c) > 1e-3 or math.dist(b, d) > 1e-3:
                        self.add("hole-twins", hole.id, "the hole mirrored onto wall1 does not line up")
                centre = ((lo.x + hi.x) / 2, (lo.y + hi.y) / 2)
                pos = hole.asset_position
                if abs(pos.x - centre[0]) > 1e-3 or abs(pos.y - centre[1]) > 1e-3:
                    self.add("asset-position", hole.id, "assetPosition is not the hole's centre")
        for wid, holes in per_wall.items():
            if len(holes) > 1:
                self.add("one-hole-per-wall", wid, f"carries {len(holes)} holes: {sorted(holes)}")

    def assets(self) -> None:
        db = asset_ids()
        for kind, items, types in (("door", self.house.doors, {"Doorway", "Doorframe"}),
                                   ("window", self.house.windows, {"Window"})):
            for hole in items:
                rec = db.get(hole.asset_id)
                if rec is None:
                    self.add("asset-id", hole.id, f"asset {hole.asset_id!r} is not in AI2-THOR's asset database")
                elif rec["objectType"] not in types:
                    self.add("asset-id", hole.id, f"asset {hole.asset_id!r} is a {rec['objectType']}, not a {kind}")

        def objects(items: list[Any]) -> None:
            for obj in items:
                if obj.asset_id not in db:
                    self.add("asset-id", obj.id, f"asset {obj.asset_id!r} is not in AI2-THOR's asset database")
                objects(obj.children)

        objects(self.house.objects)
        names = material_names()
        mats = [(r.id, r.floor_material) for r in self.house.rooms] + [
            (w.id, w.material) for w in self.house.walls
        ] + [("proceduralParameters", self.house.procedural_parameters.ceiling_material)]
        for eid, mat in mats:
            if mat is not None and mat.name is not None and mat.name not in names:
                self.add("asset-id", eid, f"material {mat.name!r} is not in AI2-THOR's material database")
        sky = self.house.procedural_parameters.skybox_id
        if sky not in skyboxes():
            self.add("asset-id", "proceduralParameters", f"skybox {sky!r} is not an AI2-THOR skybox")

    def objects(self) -> None:
        db = asset_ids()
        floor: dict[str, list[_Placed]] = defaultdict(list)
        for obj in self.house.objects:
            p = Point(obj.position.x, obj.position.z)
            inside = [rid for rid, poly in self.polys.items() if poly.covers(p)]
            if not inside:
                self.add("object-in-room", obj.id, f"centre ({obj.position.x:.3f}, {obj.position.z:.3f}) is in no room")
                continue
            if obj.room is not None and obj.room in self.polys and obj.room not in inside:
                self.add("object-in-room", obj.id, f"names room {obj.room!r} but stands in {inside[0]!r}")
                continue
            room = obj.room if obj.room in self.polys else inside[0]
            placed = self._placed(obj, db)
            if placed is None:
                continue  # an unknown asset: reported under asset-id
            out = placed.fp.difference(self.polys[room].buffer(OBJECT_TOLERANCE, join_style="mitre"))
            if out.area > 1e-6:
                self.add("object-in-room", obj.id, f"footprint leaves room {room!r} "
                         f"({out.area:.4f} m² outside, beyond {OBJECT_TOLERANCE * 100:.0f} cm)")
            floor[room].append(placed)
            self.children(placed, db)
        for room, items in floor.items():
            self.overlaps(items)
            self.object_reach(room, items)
        self.poses_clear([x for items in floor.values() for x in items])

    def _placed(self, obj: HouseObject, db: dict[str, Any]) -> _Placed | None:
        rec = db.get(obj.asset_id)
        if rec is None:
            return None
        bb = rec["boundingBox"]
        fp = check.footprint((obj.position.x, obj.position.z), bb["x"], bb["z"], obj.rotation.y)
        return _Placed(obj, rec["objectType"], fp, bb["y"], bb["z"])

    def children(self, parent: _Placed, db: dict[str, Any]) -> None:
        """Small objects lie on their receptacle: inside its footprint, resting on its top."""
        top = parent.obj.position.y + parent.height / 2
        area = parent.fp.buffer(OBJECT_TOLERANCE, join_style="mitre")
        for child in parent.obj.children:
            c = self._placed(child, db)
            if c is None:
                continue
            if c.fp.difference(area).area > 1e-6:
                self.add("object-child", child.id, f"footprint leaves its receptacle {parent.obj.id!r}")
            bottom = child.position.y - c.height / 2
            if abs(bottom - top) > OBJECT_TOLERANCE:
                self.add("object-child", child.id, f"rests at y = {bottom:.3f}, not on the top of "
                         f"{parent.obj.id!r} (y = {top:.3f})")
            if child.children:
                self.children(c, db)

    def overlaps(self, items: list[_Placed]) -> None:
        """No two floor objects overlap, except a seat tucked under the table it is paired with."""
        tree = STRtree([x.fp for x in items])
        for i, a in enumerate(items):
            for j in tree.query(a.fp):
                if int(j) <= i:
                    continue
                b = items[int(j)]
                area = a.fp.intersection(b.fp).area
                if area <= OVERLAP_AREA or _tucked(a, b) or _tucked(b, a):
                    continue
                self.add("object-overlap", a.obj.id, f"overlaps {b.obj.id!r} by {area:.4f} m²")

    def object_reach(self, room: str, items: list[_Placed]) -> None:
        """The independent flood fill: the room's free space for an agent of the floor's radius
        (objects and solid walls inflated by it), from the cells just inside its first door the
        agent fits through; every other such door and every object must be reached."""
        radius = self._radius()
        ring = [(p.x, p.z) for p in self.house_room(room).floor_polygon]
        ways = self.entrances.get(room, [])
        space = check.FreeSpace.build(ring, [(e.a, e.b) for e in ways], [x.fp for x in items], radius)
        fronts = [(e, space.in_front_of(e.a, e.b, REACH)) for e in ways]
        # a way no agent passes, narrower than it or blocked even in the empty room, is no
        # entrance (a gap left where no door asset fitted)
        usable = [(e, cells) for e, cells in fronts
                  if check.passable(e.width, radius) and (cells & space.open).any()]
        if not usable:
            for x in items:
                self.add("object-reach", x.obj.id, f"room {room!r} has no door or opening an agent "
                         f"of radius {radius} m passes, so nothing in it is reachable")
            return
        # entrances the empty room connects (a neck narrower than the agent may part them) must
        # stay connected; objects must be reached from one of them
        reached = np.zeros_like(space.free)
        grouped = np.zeros_like(space.free)
        for e, cells in usable:
            if (grouped & cells).any():
                continue
            part = space.flood(cells, empty=True)
            grouped |= part
            mine = space.flood(cells)
            reached |= mine
            for other, more in usable:
                if other is not e and (part & more).any() and not (mine & more).any():
                    self.add("object-reach", other.id, f"objects in room {room!r} cut it off from {e.id!r}")
        first = usable[0][0]
        for x in items:
            front = ((x.obj.position.x, x.obj.position.z), x.obj.rotation.y, x.depth) \
                if x.type in FRONT_TYPES else None
            if not space.reaches(reached, x.fp, REACH, front):
                where = " from its front" if front else ""
                self.add("object-reach", x.obj.id, f"no free cell connected to a door ({first.id!r}, …) lies within "
                         f"{REACH} m of it{where} (agent radius {radius} m)")

    def poses_clear(self, items: list[_Placed]) -> None:
        radius = self._radius()
        poses = [(f"agentPoses.{m}", p) for m, p in self.house.metadata.agent_poses.items()]
        poses += [(r.id, r.metadata.core.landing) for r in self.house.rooms
                  if r.metadata and r.metadata.core and r.metadata.core.landing]
        for name, pose in poses:
            p = Point(pose.position.x, pose.position.z)
            for x in items:
                if x.fp.distance(p) < radius:
                    self.add("object-reach", name, f"object {x.obj.id!r} stands where the agent is posed")

    def _radius(self) -> float:
        record = self.house.metadata.mansion
        if record is not None and record.furnishing is not None:
            return record.furnishing.agent_radius
        return AGENT_RADIUS

    def house_room(self, rid: str) -> Any:
        return next(r for r in self.house.rooms if r.id == rid)

    def reach(self) -> None:
        for mode, pose in self.house.metadata.agent_poses.items():
            p = Point(pose.position.x, pose.position.z)
            if not any(poly.contains(p) for poly in self.polys.values()):
                self.add("reachable", f"agentPoses.{mode}", "the agent pose stands in no room")
        record = self.house.metadata.mansion
        if record is None or record.hub not in self.polys:
            if record is not None:
                self.add("reachable", record.hub, "the hub named in metadata.mansion is not a room")
            return
        walls = {w.id: w for w in self.house.walls}
        links: dict[str, set[str]] = defaultdict(set)
        for door in self.house.doors:
            links[door.room0].add(door.room1)
            links[door.room1].add(door.room0)
        for wid, wall in walls.items():
            twin = self.twin.get(wid)
            if wall.empty and twin is not None and walls[twin].empty:
                a, b = wall.room_id, walls[twin].room_id
                if a != b:
                    links[a].add(b)
                    links[b].add(a)
        seen = {record.hub}
        queue = deque(seen)
        while queue:
            for v in links[queue.popleft()]:
                if v not in seen:
                    seen.add(v)
                    queue.append(v)
        for rid in self.polys:
            if rid not in seen:
                self.add("reachable", rid, f"is not reached from the hub {record.hub!r} through doors or openings")


def validate_house(house: House | dict[str, Any], *, source: str = "") -> list[Problem]:
    """Every problem of one house (a :class:`House` or the parsed JSON)."""
    if not isinstance(house, House):
        try:
            house = House.model_validate(house)
        except ValidationError as exc:
            return [
                Problem("schema", ".".join(str(p) for p in e["loc"]) or "house", e["msg"], source)
                for e in exc.errors(include_url=False)
            ]
    return _HouseCheck(house, source).run()


def _read(path: Path) -> Any:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise InvalidInputError(f"cannot read {str(path)!r}: {exc}") from exc


def validate_building(manifest_path: str | os.PathLike[str]) -> list[Problem]:
    """Every floor of a building, and the cores across its floors."""
    path = Path(manifest_path)
    manifest = BuildingManifest.load(path)
    problems: list[Problem] = []
    houses: dict[int, House] = {}
    for floor in manifest.floors:
        file = path.parent / floor.house
        data = _read(file)
        found = validate_house(data, source=str(file))
        problems += found
        if not any(p.rule == "schema" for p in found):
            houses[floor.index] = House.model_validate(data)
    src = str(path)
    for core in manifest.cores:
        box = (core.x[0], core.z[0], core.x[1], core.z[1])
        for k in core.floors:
            house = houses.get(k)
            if house is None:
                if k not in {f.index for f in manifest.floors}:
                    problems.append(Problem("core-align", core.id, f"serves floor {k}, which the manifest lacks", src))
                continue
            room = next((r for r in house.rooms if r.id == core.id), None)
            if room is None:
                problems.append(Problem("core-align", core.id, f"is not a room of floor {k}", src))
                continue
            poly = Polygon([_xz(p) for p in room.floor_polygon])
            if any(abs(a - b) > 1e-3 for a, b in zip(poly.bounds, box)) or abs(poly.area - (box[2] - box[0]) * (box[3] - box[1])) > 1e-3:
                problems.append(Problem("core-align", core.id, f"on floor {k} covers {tuple(round(v, 3) for v in poly.bounds)}, not the box {box}", src))
            rec = room.metadata.core if room.metadata else None
            if rec is None or rec.kind != core.kind or sorted(rec.floors) != sorted(core.floors):
                problems.append(Problem("core-align", core.id, f"on floor {k} lacks a core record matching the manifest", src))
            walls = {w.id: w for w in house.walls}
            joined = any(core.id in (d.room0, d.room1) for d in house.doors) or any(
                w.empty and w.room_id == core.id for w in walls.values()
            )
            if not joined:
                problems.append(Problem("core-align", core.id, f"has no door on floor {k}", src))
        for landing in core.landings:
            house = houses.get(landing.floor)
            if house is None:
                continue
            room = next((r for r in house.rooms if r.id == landing.room), None)
            p = Point(landing.pose.position.x, landing.pose.position.z)
            if room is None or not Polygon([_xz(q) for q in room.floor_polygon]).contains(p):
                problems.append(Problem("core-align", core.id, f"landing on floor {landing.floor} is not inside room {landing.room!r}", src))
    return problems


def validate_path(path: str | os.PathLike[str]) -> list[Problem]:
    """A house JSON file, a building's ``manifest.json``, or a folder holding one."""
    p = Path(path)
    if p.is_dir():
        for candidate in (p / "manifest.json", p / "scenes" / "manifest.json"):
            if candidate.is_file():
                return validate_building(candidate)
        raise InvalidInputError(f"{str(p)!r} holds no manifest.json (nor scenes/manifest.json)")
    data = _read(p)
    if isinstance(data, dict) and "floors" in data and "rooms" not in data:
        return validate_building(p)
    return validate_house(data, source=str(p))
