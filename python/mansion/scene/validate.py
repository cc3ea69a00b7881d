"""``mansion validate``: checks of a house JSON (and of a whole building) faithful to AI2-THOR's
loader (``ProceduralTools.CreateHouse`` at schema 1.0.0; docs/HOUSE_JSON.md).

Every problem has a severity. **Errors** are exactly what makes the loader throw, or leaves a
robot unable to move; **warnings** are quality findings the simulator loads anyway. ``mansion
validate`` exits 1 on errors only (``--strict``: on warnings too).

Errors (the loader throws, or the robot is stuck):

- ``schema``: the JSON does not parse as a house, or ``metadata.schema`` is not "1.0.0";
- ``duplicate-id``: two rooms, or two doors / windows, share an id (the loader keys them);
- ``one-hole-per-wall``: a wall carries two holes (the loader keys holes by wall);
- ``hole-wall``: a door's or window's ``wall0`` does not exist;
- ``hole-polygon``: a hole with fewer than two points;
- ``hole-asset``: a door or window asset AI2-THOR does not have;
- ``material``: a room's floor, a non-empty wall or the ceiling has a null or unknown material;
- ``skybox``: an unknown skybox;
- ``object-rotation``: an object (or a child) without ``rotation``;
- ``spawn``: the agent pose stands in no room, or nowhere an agent fits near it;
- ``navigable``: with every object removed, a room or a core (``metadata.core``) cannot be reached
  from the spawn by an agent of radius 0.25 m keeping 0.05 m (clear passages >= 0.6 m) through
  doors and openings (:mod:`mansion.scene.navigation`);
- ``room-doors``: a room's doors and openings fall apart inside it (a strip narrower than the
  agent is not part of the walkable room), or, in a house whose furnishing promised the agent's
  room (``metadata.mansion.furnishing``: mansion's own), its furniture cuts them apart or shuts
  one off (furniture is judged by its assets' bounding boxes, which over-approximate their
  colliders: in other houses, ProcTHOR's among them, this is the warning ``furniture-cut``);
- ``core-align`` (buildings): a core is not the same room at the same box on every floor it
  serves, lacks a door, or its landing stands in no room.

Warnings (loaded, but worth fixing): ``room-polygon``, ``room-overlap``, ``wall-geometry``,
``wall-room``, ``wall-closure``, ``wall-pair`` (geometry of rooms and walls), ``hole-extent`` (a
hole past its wall), ``door-floor``, ``door-rooms``, ``hole-twins``, ``asset-position``
(``assetPosition`` is not ProcTHOR's: the hole's minimum + the wall-holes offset + half the
asset's box), ``hole-asset-type`` (a window asset in a door...), ``object-asset`` (an object
asset the loader skips), ``duplicate-element`` (walls or objects sharing an id),
``object-in-room``, ``object-overlap``, ``object-child``, ``object-reach``, ``object-ceiling``
(an object reaching above the ceiling), ``seat-physics`` (a tucked seat that is not kinematic and
overlaps its table more than real houses do), ``furniture-cut`` (see above),
``furniture-blocked`` (the furniture shuts the agent off from a doorstep it reached in the empty
house), ``spawn-missing`` (no agent pose: navigability not checked), ``lights`` (more
shadow-casting lights than real houses use).

ProcTHOR's conventions are accepted: no top-level ``id``; the outside door with ``room0 ==
room1`` and ``wall1`` the exterior twin; exterior twins with ``roomId: "exterior"``; children
inside shelves and fridges; chairs overlapping tables without ``tuckedUnder``; wall-mounted
objects above the floor; ``metadata.agent`` instead of ``agentPoses``.

Each problem names the element (room, wall, door, window, object or core id); nothing stops at
the first problem.
"""

from __future__ import annotations

import json
import math
import os
from collections import defaultdict
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import shapely
from pydantic import ValidationError
from shapely.geometry import Point, Polygon
from shapely.geometry.base import BaseGeometry
from shapely.strtree import STRtree

from mansion.exceptions import InvalidInputError
from mansion.placement import check
from mansion.placement.assets import FRONT_TYPES, TABLES, TUCKABLE
from mansion.scene import navigation
from mansion.scene.databases import asset_ids, hole_asset_position, material_names, skyboxes
from mansion.scene.entrances import room_entrances
from mansion.scene.house import HOUSE_SCHEMA, House, HouseObject, Vec3, Wall
from mansion.scene.manifest import BuildingManifest

__all__ = [
    "ERRORS",
    "Problem",
    "TUCKED_OVERLAP",
    "errors",
    "validate_building",
    "validate_house",
    "validate_mansionworld",
    "validate_path",
    "validate_paths",
]

#: The rules whose problems are errors (the loader throws, or the robot cannot move); every
#: other rule is a warning.
ERRORS = frozenset({
    "schema", "duplicate-id", "one-hole-per-wall", "hole-wall", "hole-polygon", "hole-asset",
    "material", "skybox", "object-rotation", "spawn", "navigable", "room-doors",
    "core-align",
})
#: Real tucked seats (ProcTHOR's chairs at tables) overlap their table by at most this share of
#: their footprint; a non-kinematic seat overlapping more is pushed out by the physics.
TUCKED_OVERLAP = 0.38
#: Real houses light a floor with at most this many shadow-casting lights.
MAX_SHADOW_LIGHTS = 10
#: An object's footprint may leave its room by this much area beyond 1 cm (real houses: 0.012 m²).
OVERHANG_AREA = 0.02

EPS = 1e-4
#: A hole may run this far past its wall's end (real houses: 0.3 mm) (m).
HOLE_TOLERANCE = 1e-3
#: An object's footprint may leave its room by this much (issue 6's #OB: 1 cm).
OBJECT_TOLERANCE = 0.01
#: A small object may rest this far above its receptacle's box (ProcTHOR's: up to 6 cm) (m).
SETTLE = 0.08
#: Two floor objects overlap when they share more than this (m², issue 6's #CN).
OVERLAP_AREA = 1e-4
#: The agent reaches an object from a free cell this close to its footprint (m).
REACH = 0.5
#: The agent's radius when the house records none (AI2-THOR's agents fit in 0.25 m).
AGENT_RADIUS = navigation.AGENT_RADIUS


@dataclass(frozen=True)
class _Placed:
    """An object with its type and footprint from AI2-THOR's asset database."""

    obj: HouseObject
    type: str
    fp: Polygon
    height: float
    depth: float


def _tucked(seat: _Placed, table: _Placed) -> bool:
    """A chair or stool at a table or desk: ours say so (``tuckedUnder``), ProcTHOR's do not."""
    return (seat.obj.tucked_under in (None, table.obj.id) and seat.type in TUCKABLE
            and table.type in TABLES)


@dataclass(frozen=True)
class Problem:
    rule: str
    element: str
    message: str
    source: str = ""

    @property
    def severity(self) -> str:
        """"error" (the loader throws or the robot cannot move) or "warning"."""
        return "error" if self.rule in ERRORS else "warning"

    def __str__(self) -> str:
        where = f"{self.source}: " if self.source else ""
        return f"{where}{self.severity} [{self.rule}] {self.element}: {self.message}"

    def to_dict(self) -> dict[str, str]:
        return {"severity": self.severity, "rule": self.rule, "element": self.element,
                "message": self.message, "source": self.source}


def errors(problems: list[Problem]) -> list[Problem]:
    """The problems that are errors."""
    return [p for p in problems if p.severity == "error"]


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
        self.lights()
        self.reach()
        return self.problems

    def ids(self) -> None:
        """Rooms, and doors with windows, are keyed by id in the loader (a duplicate throws);
        walls and objects only should be unique."""
        h = self.house
        for kind, items in (("room", h.rooms), ("door or window", [*h.doors, *h.windows])):
            seen: set[str] = set()
            for item in items:
                if item.id in seen:
                    self.add("duplicate-id", item.id, f"{kind} id used twice (the loader fails)")
                seen.add(item.id)

        def all_objects(items: list[HouseObject]) -> list[HouseObject]:
            return [x for o in items for x in (o, *all_objects(o.children))]

        named: list[tuple[str, list[str]]] = [
            ("wall", [w.id for w in h.walls]), ("object", [o.id for o in all_objects(h.objects)])]
        for kind, ids in named:
            seen = set()
            for eid in ids:
                if eid in seen:
                    self.add("duplicate-element", eid, f"{kind} id used twice")
                seen.add(eid)

    def rooms(self) -> dict[str, Polygon]:
        polys: dict[str, Polygon] = {}
        for room in self.house.rooms:
            if any(abs(p.y) > EPS for p in room.floor_polygon):
                self.add("room-polygon", room.id, "floor polygon points must have y = 0")
            poly = Polygon([_xz(p) for p in room.floor_polygon])
            if not poly.is_valid or poly.area <= EPS:
                self.add("room-polygon", room.id, "floor polygon is not a simple polygon with area")
                continue
            shapely.prepare(poly)  # many point-in-room tests follow
            polys[room.id] = poly
        ids = list(polys)
        tree = STRtree([polys[i] for i in ids])
        self.room_tree, self.room_ids = tree, ids
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
        walls = self.house.walls
        found = [_wall_segment(wall) for wall in walls]
        # whether each wall's room holds the point just to its right, in one call for the floor
        asked = [k for k, (wall, seg) in enumerate(zip(walls, found, strict=True))
                 if seg is not None and wall.room_id != "exterior" and wall.room_id in self.polys]
        rights = {k: found[k].side_point(True) for k in asked}  # type: ignore[union-attr]
        held = dict(zip(asked, shapely.contains_xy(
            [self.polys[walls[k].room_id] for k in asked],
            [rights[k][0] for k in asked], [rights[k][1] for k in asked]).tolist(), strict=True)) if asked else {}
        for k, (wall, seg) in enumerate(zip(walls, found, strict=True)):
            if seg is None:
                self.add("wall-geometry", wall.id, "wall has no length or no height")
                continue
            low = min(q.y for q in wall.polygon)
            if any(abs(p.y - low) > EPS and abs(p.y - low - seg.height) > EPS for p in wall.polygon):
                self.add("wall-geometry", wall.id, "wall polygon is not a rectangle")
            segs[wall.id] = seg
            poly = self.polys.get(wall.room_id)
            if wall.room_id == "exterior":  # ProcTHOR's exterior twins
                self.faces[wall.id] = False
                continue
            if poly is None:
                if wall.room_id not in {r.id for r in self.house.rooms}:
                    self.add("wall-room", wall.id, f"names room {wall.room_id!r}, which does not exist")
                continue
            right = rights[k]
            if held[k]:
                self.faces[wall.id] = True
            elif shapely.contains_xy(poly, *seg.side_point(False)) and not len(
                self.room_tree.query(Point(right), predicate="within")
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
            # each wall's middle and start, measured in one call
            ends = np.array([[s.at(s.length / 2), s.p0] for s in segs]).reshape(-1, 2)
            far = (shapely.distance(boundary, shapely.points(ends)) > 1e-3).reshape(-1, 2).any(axis=1)
            for s, off in zip(segs, far.tolist(), strict=True):
                if off:
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
                if hole.wall0 not in walls:
                    self.add("hole-wall", hole.id, f"wall0 {hole.wall0!r} does not exist (the loader fails)")
                    continue
                if hole.wall1 not in walls:
                    self.add("hole-twins", hole.id, f"wall1 {hole.wall1!r} does not exist")
                    continue
                for r in (hole.room0, hole.room1):
                    if r not in rooms:
                        self.add("door-rooms", hole.id, f"names room {r!r}, which does not exist")
                w0, w1 = walls[hole.wall0], walls[hole.wall1]
                # ProcTHOR's outside door: room0 == room1, wall1 the exterior twin (its roomId
                # the room's or "exterior")
                outside = hole.room0 == hole.room1 and (
                    w1.room_id == "exterior" or self.faces.get(w1.id) is False)
                if w0.room_id != hole.room0 or (w1.room_id != hole.room1 and not outside):
                    self.add("door-rooms", hole.id, f"joins {hole.room0!r} and {hole.room1!r} but "
                             f"its walls belong to {w0.room_id!r} and {w1.room_id!r}")
                if kind == "door" and hole.room0 == hole.room1 and not outside:
                    self.add("door-rooms", hole.id, "joins a room to itself (and is not a door to "
                             "the outside: wall1 is not the exterior twin)")
                lo, hi = hole.hole_polygon[0], hole.hole_polygon[-1]
                s0, s1 = self.segs.get(w0.id), self.segs.get(w1.id)
                if s0 is None or s1 is None:
                    continue
                tol = HOLE_TOLERANCE
                if not (-tol <= lo.x < hi.x <= s0.length + tol and -tol <= lo.y < hi.y <= s0.height + tol):
                    self.add("hole-extent", hole.id, f"hole x {lo.x:.3f}..{hi.x:.3f}, y {lo.y:.3f}..{hi.y:.3f} "
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
                want = hole_asset_position(hole.asset_id, (lo.x, lo.y))
                pos = hole.asset_position
                if want is not None and (abs(pos.x - want[0]) > 1e-3 or abs(pos.y - want[1]) > 1e-3):
                    self.add("asset-position", hole.id, f"assetPosition ({pos.x:.4f}, {pos.y:.4f}) is not "
                             f"ProcTHOR's ({want[0]:.4f}, {want[1]:.4f}): hole minimum + wall-holes offset "
                             "+ half the asset's box")
        for wid, holes in per_wall.items():
            if len(holes) > 1:
                self.add("one-hole-per-wall", wid, f"carries {len(holes)} holes: {sorted(holes)} "
                         "(the loader fails)")

    def assets(self) -> None:
        db = asset_ids()
        for kind, items, types in (("door", self.house.doors, {"Doorway", "Doorframe"}),
                                   ("window", self.house.windows, {"Window"})):
            for hole in items:
                rec = db.get(hole.asset_id)
                if rec is None:
                    self.add("hole-asset", hole.id, f"asset {hole.asset_id!r} is not in AI2-THOR's "
                             "asset database (the loader fails)")
                elif rec["objectType"] not in types:
                    self.add("hole-asset-type", hole.id, f"asset {hole.asset_id!r} is a {rec['objectType']}, not a {kind}")

        def objects(items: list[Any]) -> None:
            for obj in items:
                if obj.asset_id not in db:
                    self.add("object-asset", obj.id, f"asset {obj.asset_id!r} is not in AI2-THOR's "
                             "asset database (the loader skips it)")
                objects(obj.children)

        objects(self.house.objects)
        names = material_names()
        mats = [(r.id, "floor", r.floor_material) for r in self.house.rooms] + [
            (w.id, "wall", w.material) for w in self.house.walls if not w.empty
        ] + [("proceduralParameters", "ceiling", self.house.procedural_parameters.ceiling_material)]
        for eid, what, mat in mats:
            if mat is None or mat.name is None:
                self.add("material", eid, f"{what} material is null (the loader fails)")
            elif mat.name not in names:
                self.add("material", eid, f"{what} material {mat.name!r} is not in AI2-THOR's material database")
        sky = self.house.procedural_parameters.skybox_id
        if sky not in skyboxes():
            self.add("skybox", "proceduralParameters", f"skybox {sky!r} is not an AI2-THOR skybox")

    def objects(self) -> None:
        db = asset_ids()
        floor: dict[str, list[_Placed]] = defaultdict(list)
        ids, tree = self.room_ids, self.room_tree
        margins: dict[str, BaseGeometry] = {}
        # the rooms covering each object's centre, in the house's order (one query for all)
        covering: dict[int, list[int]] = defaultdict(list)
        if self.house.objects:
            centres = shapely.points([(o.position.x, o.position.z) for o in self.house.objects])
            for k, j in zip(*tree.query(centres, predicate="covered_by").tolist(), strict=True):
                covering[k].append(j)
        for n, obj in enumerate(self.house.objects):
            inside = [ids[k] for k in sorted(covering.get(n, []))]
            if not inside:
                self.add("object-in-room", obj.id, f"centre ({obj.position.x:.3f}, {obj.position.z:.3f}) is in no room")
                continue
            if obj.room is not None and obj.room in self.polys and obj.room not in inside:
                self.add("object-in-room", obj.id, f"names room {obj.room!r} but stands in {inside[0]!r}")
                continue
            room = obj.room if obj.room in self.polys else inside[0]
            placed = self._placed(obj, db)
            if placed is None:
                continue  # an unknown asset: reported under object-asset
            if room not in margins:
                margins[room] = self.polys[room].buffer(OBJECT_TOLERANCE, join_style="mitre")
                shapely.prepare(margins[room])
            # the difference only for the few footprints not plainly inside (a prepared test)
            out = None if margins[room].contains(placed.fp) else placed.fp.difference(margins[room])
            if out is not None and out.area > OVERHANG_AREA:
                self.add("object-in-room", obj.id, f"footprint leaves room {room!r} "
                         f"({out.area:.4f} m² outside, beyond {OBJECT_TOLERANCE * 100:.0f} cm)")
            floor[room].append(placed)
            self.children(placed, db)
            self.ceiling(placed, db)
        for room, items in floor.items():
            self.overlaps(items)
            self.object_reach(room, items)
        self.poses_clear([x for items in floor.values() for x in items])

    def _ceiling_height(self) -> float | None:
        record = self.house.metadata.mansion
        if record is not None:
            return record.ceiling_height
        heights = [s.height for s in self.segs.values()]
        return max(heights) if heights else None

    def ceiling(self, placed: _Placed, db: dict[str, Any]) -> None:
        """Nothing (small objects on shelves included) reaches above the ceiling."""
        height = self._ceiling_height()
        if height is None:
            return
        stack = [(placed.obj, placed.height)]
        while stack:
            obj, h = stack.pop()
            top = obj.position.y + h / 2
            if top > height + OBJECT_TOLERANCE:
                self.add("object-ceiling", obj.id, f"reaches y = {top:.3f}, above the ceiling at {height:.3f}")
            for child in obj.children:
                rec = db.get(child.asset_id)
                if rec is not None:
                    stack.append((child, rec["boundingBox"]["y"]))

    def _placed(self, obj: HouseObject, db: dict[str, Any]) -> _Placed | None:
        rec = db.get(obj.asset_id)
        if rec is None:
            return None
        bb = rec["boundingBox"]
        fp = check.footprint((obj.position.x, obj.position.z), bb["x"], bb["z"], obj.rotation.y)
        return _Placed(obj, rec["objectType"], fp, bb["y"], bb["z"])

    def children(self, parent: _Placed, db: dict[str, Any]) -> None:
        """Small objects lie on their receptacle: inside its footprint, resting on its top."""
        if not parent.obj.children:
            return
        top = parent.obj.position.y + parent.height / 2
        base = parent.obj.position.y - parent.height / 2
        rect = check.rectangle(parent.fp)
        area = None
        for child in parent.obj.children:
            c = self._placed(child, db)
            if c is None:
                continue
            # A child whose corners all lie in the receptacle's rectangle grown by the tolerance
            # is inside its grown footprint (the answer below): measured only for the others.
            if rect is None or not check.corners_within(rect, c.fp, OBJECT_TOLERANCE):
                if area is None:
                    area = parent.fp.buffer(OBJECT_TOLERANCE, join_style="mitre")
                    shapely.prepare(area)
                if not area.contains(c.fp) and c.fp.difference(area).area > 1e-6:
                    self.add("object-child", child.id, f"footprint leaves its receptacle {parent.obj.id!r}")
            bottom = child.position.y - c.height / 2
            # on its receptacle's top (ProcTHOR's settle up to a few cm above it), or inside it
            # (a shelf's or a fridge's own shelves)
            if not base - OBJECT_TOLERANCE <= bottom <= top + SETTLE:
                self.add("object-child", child.id, f"rests at y = {bottom:.3f}, neither on nor in "
                         f"{parent.obj.id!r} (y {base:.3f}..{top:.3f})")
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
                for seat, table in ((a, b), (b, a)):
                    if (_tucked(seat, table) and not seat.obj.kinematic
                            and area > TUCKED_OVERLAP * seat.fp.area):
                        self.add("seat-physics", seat.obj.id, f"is not kinematic and overlaps "
                                 f"{table.obj.id!r} by {100 * area / seat.fp.area:.0f} % of its "
                                 f"footprint (real tucked seats: at most {TUCKED_OVERLAP:.0%})")
                # objects at different heights (a picture above a sideboard) do not collide
                apart = (a.obj.position.y - a.height / 2 >= b.obj.position.y + b.height / 2 - 1e-3
                         or b.obj.position.y - b.height / 2 >= a.obj.position.y + a.height / 2 - 1e-3)
                if area <= OVERLAP_AREA or apart or _tucked(a, b) or _tucked(b, a):
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
        fronts = [((x.obj.position.x, x.obj.position.z), x.obj.rotation.y, x.depth)
                  if x.type in FRONT_TYPES else None for x in items]
        found = space.reaches_each(reached, [x.fp for x in items], REACH, fronts)
        for x, front, ok in zip(items, fronts, found, strict=True):
            if not ok:
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

    def _furnishing_radius(self) -> float | None:
        record = self.house.metadata.mansion
        if record is not None and record.furnishing is not None:
            return record.furnishing.agent_radius
        return None

    def _radius(self) -> float:
        radius = self._furnishing_radius()
        return AGENT_RADIUS if radius is None else radius

    def house_room(self, rid: str) -> Any:
        return next(r for r in self.house.rooms if r.id == rid)

    def lights(self) -> None:
        shadows = [x for x in self.house.procedural_parameters.lights
                   if x.shadow is not None and x.shadow.type.lower() != "none"]
        if len(shadows) > MAX_SHADOW_LIGHTS:
            self.add("lights", "proceduralParameters", f"{len(shadows)} shadow-casting lights "
                     f"(real houses: at most {MAX_SHADOW_LIGHTS} a floor)")

    def reach(self) -> None:
        """The robot can move: it stands at the spawn, reaches every room and core with the
        objects removed, walks between every room's doors inside it, and the furniture shuts it
        off from no doorstep (:mod:`mansion.scene.navigation`)."""
        pose = navigation.spawn_pose(self.house)
        if pose is None:
            self.add("spawn-missing", "metadata", "no agent pose (agentPoses or agent): navigability not checked")
            return
        p = Point(pose.position.x, pose.position.z)
        if not any(poly.covers(p) for poly in self.polys.values()):
            self.add("spawn", "metadata.agentPoses", f"the agent pose ({p.x:.2f}, {p.y:.2f}) stands in no room")
            return
        radius, margin = self._radius(), navigation.MARGIN
        # the floor's free space without objects, shared by the three checks (built once)
        space = navigation.free_space(self.house, radius + margin)
        lost = navigation.unreachable_rooms(self.house, radius=radius, margin=margin, space=space)
        if lost is None:
            self.add("spawn", "metadata.agentPoses", f"an agent of radius {radius} m (+{margin} m) "
                     f"cannot stand within 0.5 m of the pose ({p.x:.2f}, {p.y:.2f})")
            return
        cores = {r.id for r in self.house.rooms if r.metadata and r.metadata.core}
        for rid in lost:
            what = "core" if rid in cores else "room"
            self.add("navigable", rid, f"{what} not reached from the spawn by an agent of radius "
                     f"{radius} m keeping {margin} m (passages narrower than "
                     f"{2 * (radius + margin):.2f} m), even with every object removed")
        # Furniture is judged by its assets' bounding boxes, which over-approximate their
        # colliders: an error for houses whose furnishing promised the agent's room (ours record
        # it in metadata.mansion.furnishing), a warning for the others (ProcTHOR's own houses
        # have such rooms).
        promised = self._furnishing_radius() is not None
        obstacles = navigation.Obstacles.of(self.house, radius + margin)
        for cut in navigation.disconnected_entrances(self.house, radius=radius, margin=margin, space=space,
                                                     obstacles=obstacles):
            parts = " | ".join(", ".join(g) for g in cut.groups)
            shut = f"; {', '.join(cut.blocked)} reached by no free space" if cut.blocked else ""
            if not cut.furniture:
                self.add("room-doors", cut.room, f"its doors and openings fall apart inside it "
                         f"(a strip narrower than {2 * (radius + margin):.2f} m): {parts}{shut}")
            else:
                self.add("room-doors" if promised else "furniture-cut", cut.room,
                         f"its furniture cuts its doors apart: {parts}{shut}")
        for rid, eid in navigation.blocked_entrances(self.house, radius=radius, margin=margin, space=space,
                                                     obstacles=obstacles):
            self.add("furniture-blocked", rid,
                     f"the furniture shuts the agent off from the doorstep of {eid!r} in this room")


def _loader_traps(data: dict[str, Any], source: str) -> tuple[list[Problem], set[tuple[Any, ...]]]:
    """What the loader throws on before anything else: hole polygons of fewer than two points and
    objects without a rotation (both read blindly). Returns the problems and the locations the
    schema errors need not report again."""
    out: list[Problem] = []
    seen: set[tuple[Any, ...]] = set()
    for kind in ("doors", "windows"):
        for i, hole in enumerate(data.get(kind) or []):
            pts = hole.get("holePolygon") if isinstance(hole, dict) else None
            if not isinstance(pts, list) or len(pts) < 2:
                out.append(Problem("hole-polygon", str(hole.get("id", f"{kind}.{i}")) if isinstance(hole, dict) else f"{kind}.{i}",
                                   "holePolygon has fewer than two points (the loader fails)", source))
                seen.add((kind, i, "holePolygon"))

    def objects(items: Any, loc: tuple[Any, ...]) -> None:
        for i, obj in enumerate(items if isinstance(items, list) else []):
            if not isinstance(obj, dict):
                continue
            if obj.get("rotation") is None:
                out.append(Problem("object-rotation", str(obj.get("id", ".".join(map(str, (*loc, i))))),
                                   "object has no rotation (the loader fails)", source))
                seen.add((*loc, i, "rotation"))
            objects(obj.get("children"), (*loc, i, "children"))

    objects(data.get("objects"), ("objects",))
    return out, seen


def validate_house(house: House | dict[str, Any], *, source: str = "") -> list[Problem]:
    """Every problem of one house (a :class:`House` or the parsed JSON), errors and warnings."""
    return _checked(house, source)[0]


def _checked(house: House | dict[str, Any], source: str) -> tuple[list[Problem], House | None]:
    """:func:`validate_house`'s problems and the parsed house (None when the schema failed)."""
    data = house.to_dict() if isinstance(house, House) else house
    if not isinstance(data, dict):
        return [Problem("schema", "house", "a house is a JSON object", source)], None
    traps, covered = _loader_traps(data, source)
    try:
        parsed = House.model_validate(data)
    except ValidationError as exc:
        return traps + [
            Problem("schema", ".".join(str(p) for p in e["loc"]) or "house", e["msg"], source)
            for e in exc.errors(include_url=False)
            if not any(tuple(e["loc"][:len(c)]) == c for c in covered)
        ], None
    if traps:
        return traps, parsed
    return _HouseCheck(parsed, source).run(), parsed


def _read(path: Path, text: str | None = None) -> Any:
    """The JSON in ``path`` (``text``: its contents, when read already)."""
    try:
        return json.loads(path.read_text(encoding="utf-8") if text is None else text)
    except (OSError, ValueError) as exc:
        raise InvalidInputError(f"cannot read {str(path)!r}: {exc}") from exc


def _model_traps(house: House, source: str) -> list[Problem]:
    """:func:`_loader_traps` of a house that parsed: the objects whose rotation the file left out
    (the model's default stands in for it; a hole polygon of fewer than two points does not parse)."""
    out: list[Problem] = []

    def objects(items: list[HouseObject]) -> None:
        for obj in items:
            if "rotation" not in obj.model_fields_set:
                out.append(Problem("object-rotation", obj.id, "object has no rotation (the loader fails)", source))
            objects(obj.children)

    objects(house.objects)
    return out


def _checked_file(path: Path) -> tuple[list[Problem], House | None]:
    """:func:`_checked` of a house JSON file. The text goes straight to the model (pydantic's
    JSON parser: a third of the time of :func:`json.loads` and validating the dict); a file the
    model rejects is parsed again as a dict, so that every schema problem is named as before."""
    source = str(path)
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise InvalidInputError(f"cannot read {source!r}: {exc}") from exc
    try:
        parsed = House.model_validate_json(text)
    except ValidationError:
        return _checked(_read(path, text), source)
    traps = _model_traps(parsed, source)
    return (traps if traps else _HouseCheck(parsed, source).run()), parsed


def validate_building(
    manifest_path: str | os.PathLike[str], *, written: Sequence[House] | None = None,
) -> list[Problem]:
    """Every floor of a building, and the cores across its floors.

    ``written``: the houses just written to the manifest's floor files, in its order (what
    :func:`mansion.scene.save_scenes` wrote them from); they are checked as they are rather than
    read back. A model writes every field it holds and reads back equal (a golden round trip of
    the tests), so the answers are the same, without parsing a dataset's floors again (a tenth of
    the validation)."""
    path = Path(manifest_path)
    manifest = BuildingManifest.load(path)
    if written is not None and len(written) != len(manifest.floors):
        raise InvalidInputError(f"{len(written)} houses given for the {len(manifest.floors)} floors of {str(path)!r}")
    problems: list[Problem] = []
    houses: dict[int, House] = {}
    for k, floor in enumerate(manifest.floors):
        file = path.parent / floor.house
        if written is not None:
            found, parsed = _HouseCheck(written[k], str(file)).run(), written[k]
        else:
            found, parsed = _checked_file(file)
        problems += found
        if parsed is not None and not any(p.rule == "schema" for p in found):
            houses[floor.index] = parsed
    return problems + _core_problems(manifest, houses, str(path))


def validate_mansionworld(folder: str | os.PathLike[str]) -> list[Problem]:
    """A building in the MANSION authors' layout (``floor_1.json`` …, no manifest): every floor
    as mansion reads it (:mod:`mansion.scene.mansionworld`: their core fixtures left out, the
    outside door as ProcTHOR's) and the cores the reader linked across the floors."""
    from mansion.scene.mansionworld import read_mansionworld

    world = read_mansionworld(folder)
    problems: list[Problem] = []
    houses: dict[int, House] = {}
    for k, data in world.houses.items():
        found = validate_house(data, source=str(world.files[k]))
        problems += found
        if not any(p.rule == "schema" for p in found):
            houses[k] = House.model_validate(data)
    return problems + _core_problems(world.manifest, houses, str(world.folder))


def _core_problems(manifest: BuildingManifest, houses: dict[int, House], src: str) -> list[Problem]:
    problems: list[Problem] = []
    for core in manifest.cores:
        box = (core.x[0], core.z[0], core.x[1], core.z[1])
        for k in core.floors:
            house = houses.get(k)
            if house is None:
                if k not in {f.index for f in manifest.floors}:
                    problems.append(Problem("core-align", core.id, f"serves floor {k}, which the manifest lacks", src))
                continue
            rid = core.room_on(k)
            room = next((r for r in house.rooms if r.id == rid), None)
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
            joined = any(rid in (d.room0, d.room1) for d in house.doors) or any(
                w.empty and w.room_id == rid for w in walls.values()
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
    """A house JSON file, a building's ``manifest.json``, or a folder holding one (or
    ``scenes/manifest.json``), a MansionWorld folder (``floor_1.json`` …), or else a folder of
    house JSON files."""
    p = Path(path)
    if p.is_dir():
        for candidate in (p / "manifest.json", p / "scenes" / "manifest.json"):
            if candidate.is_file():
                return validate_building(candidate)
        from mansion.scene.mansionworld import is_mansionworld

        if is_mansionworld(p):
            return validate_mansionworld(p)
        houses = sorted(p.glob("*.json"))
        if not houses:
            raise InvalidInputError(f"{str(p)!r} holds no manifest.json (nor scenes/manifest.json) "
                                    "and no house JSON")
        return [q for h in houses for q in validate_path(h)]
    data = _read(p)
    if isinstance(data, dict) and "floors" in data and "rooms" not in data:
        return validate_building(p)
    return validate_house(data, source=str(p))


def validate_paths(paths: list[str | os.PathLike[str]]) -> list[Problem]:
    """Every problem of many paths (house JSONs, manifests, building folders), in order."""
    return [q for p in paths for q in validate_path(p)]
