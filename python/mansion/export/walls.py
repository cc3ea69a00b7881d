"""Walls as solids with their door and window holes cut, and doors and windows sized from the
holes.

A house JSON wall is one-sided: every shared edge has two walls (one per room) and every outside
edge a twin facing out. Each becomes a skin ``SKIN`` metres thick on its visible side, so twins
together make a wall 2 × SKIN thick, each face in its own room's material. A hole is cut into
wall0 in its own frame and into wall1 mirrored (x → length − x), as the simulator's loader does.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from shapely.geometry import Point, Polygon
from shapely.geometry import box as rect
from shapely.prepared import prep

from mansion.exceptions import InvalidInputError
from mansion.export.looks import DOOR, GLASS, WINDOW_FRAME, material_look
from mansion.export.meshes import Mesh, box, merge, prism, transformed
from mansion.export.model import Node
from mansion.scene.house import Door, House, Wall, Window

__all__ = ["SKIN", "WallFrame", "hole_nodes", "wall_frames", "wall_node", "wall_nodes"]

#: Thickness of one wall face, m.
SKIN = 0.05
_FRAME = 0.05  # door and window frame bars
_LEAF = 0.04  # door leaf thickness


@dataclass(frozen=True)
class WallFrame:
    """A wall's local frame: u along p0 → p1, t across (toward its visible side), y up."""

    wall: Wall
    p0: tuple[float, float]
    direction: tuple[float, float]
    normal: tuple[float, float]
    length: float
    height: float

    def matrix(self) -> np.ndarray:
        """(u, t, y) → world (x, y, z)."""
        (dx, dz), (nx, nz) = self.direction, self.normal
        m = np.eye(4)
        m[:3, :3] = [[dx, nx, 0.0], [0.0, 0.0, 1.0], [dz, nz, 0.0]]
        m[:3, 3] = [self.p0[0], 0.0, self.p0[1]]
        return m

    def at(self, u: float, t: float = 0.0) -> tuple[float, float]:
        return (
            self.p0[0] + u * self.direction[0] + t * self.normal[0],
            self.p0[1] + u * self.direction[1] + t * self.normal[1],
        )


def _exterior(wall: Wall) -> bool:
    # ProcTHOR names outside twins "wall|exterior|...", Holodeck "<id>|exterior", mansion
    # "wall|<k>|exterior|...".
    return "exterior" in wall.id.split("|")


def wall_frames(house: House) -> dict[str, WallFrame]:
    """Every wall's frame, its normal toward its visible side: into its room, or out of it for
    an outside twin (decided against the room's polygon, so either winding of the file works)."""
    rooms = {r.id: prep(Polygon([(p.x, p.z) for p in r.floor_polygon]).buffer(0)) for r in house.rooms}
    out = {}
    for wall in house.walls:
        (x0, z0), (x1, z1) = wall.segment()
        length = math.hypot(x1 - x0, z1 - z0)
        if length < 1e-6:
            continue
        d = ((x1 - x0) / length, (z1 - z0) / length)
        n = (d[1], -d[0])
        room = rooms.get(wall.room_id)
        if room is not None:
            probe = Point((x0 + x1) / 2 + 0.02 * n[0], (z0 + z1) / 2 + 0.02 * n[1])
            if room.contains(probe) == _exterior(wall):
                n = (-n[0], -n[1])
        ys = [p.y for p in wall.polygon]
        out[wall.id] = WallFrame(wall, (x0, z0), d, n, length, max(ys) - min(ys))
    return out


def _holes(house: House, frames: dict[str, WallFrame]) -> dict[str, list[tuple[float, float, float, float]]]:
    """Wall id → its holes as (u0, u1, y0, y1) in the wall's own frame."""
    out: dict[str, list[tuple[float, float, float, float]]] = {}
    for hole in [*house.doors, *house.windows]:
        lo, hi = hole.hole_polygon
        f0 = frames.get(hole.wall0)
        if f0 is None:
            raise InvalidInputError(f"{hole.id}: its wall0 {hole.wall0!r} is not a wall of house {house.id!r}")
        out.setdefault(hole.wall0, []).append((lo.x, hi.x, lo.y, hi.y))
        f1 = frames.get(hole.wall1)
        if f1 is not None and hole.wall1 != hole.wall0:
            out.setdefault(hole.wall1, []).append((f1.length - hi.x, f1.length - lo.x, lo.y, hi.y))
    return out


def wall_node(frame: WallFrame, holes: list[tuple[float, float, float, float]], floor: str) -> Node:
    face = rect(0.0, 0.0, frame.length, frame.height)
    for u0, u1, y0, y1 in holes:
        face = face.difference(rect(u0, y0, u1, y1))
    mesh = transformed(prism(face, 0.0, SKIN), frame.matrix())
    wall = frame.wall
    return Node(
        f"{floor}/{wall.id}", "wall", mesh=mesh, look=material_look(wall.material, "WallDrywallWhite"),
        physics="collider", info={"id": wall.id, "room": wall.room_id},
    )


def _door_mesh(door: Door, frame: WallFrame, room0_side: float) -> Mesh:
    lo, hi = door.hole_polygon
    u0, u1, top = lo.x, hi.x, hi.y
    depth = (-SKIN, SKIN)
    parts = [
        box((u0, depth[0], lo.y), (u0 + _FRAME, depth[1], top)),
        box((u1 - _FRAME, depth[0], lo.y), (u1, depth[1], top)),
        box((u0, depth[0], top - _FRAME), (u1, depth[1], top)),
    ]
    # The leaf hangs on the hole's low end and swings by openness × 90° into its swing room.
    width = u1 - u0 - 2 * _FRAME
    side = room0_side if door.swing_room in (None, door.room0) else -room0_side
    angle = door.openness * math.pi / 2
    c, s = math.cos(angle), side * math.sin(angle)
    turn = np.eye(4)
    turn[:3, :3] = [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]
    turn[:3, 3] = [u0 + _FRAME, 0.0, 0.0]
    leaf = box((0.0, -_LEAF / 2, lo.y), (width, _LEAF / 2, top - _FRAME))
    parts.append(transformed(leaf, turn))
    return transformed(merge(parts), frame.matrix())


def _window_meshes(window: Window, frame: WallFrame) -> tuple[Mesh, Mesh]:
    lo, hi = window.hole_polygon
    d0, d1 = -SKIN, SKIN
    bars = merge([
        box((lo.x, d0, lo.y), (lo.x + _FRAME, d1, hi.y)),
        box((hi.x - _FRAME, d0, lo.y), (hi.x, d1, hi.y)),
        box((lo.x, d0, lo.y), (hi.x, d1, lo.y + _FRAME)),
        box((lo.x, d0, hi.y - _FRAME), (hi.x, d1, hi.y)),
    ])
    pane = box((lo.x + _FRAME, -0.005, lo.y + _FRAME), (hi.x - _FRAME, 0.005, hi.y - _FRAME))
    m = frame.matrix()
    return transformed(bars, m), transformed(pane, m)


def hole_nodes(house: House, frames: dict[str, WallFrame], floor: str) -> list[tuple[str, Node]]:
    """(room id, node) for every door (in room0) and window; a window's glass is its child."""
    out = []
    for door in house.doors:
        f = frames[door.wall0]
        # room0 lies on wall0's visible side unless wall0 is an outside twin.
        room0_side = -1.0 if _exterior(f.wall) else 1.0
        node = Node(
            f"{floor}/{door.id}", "door", mesh=_door_mesh(door, f, room0_side), look=DOOR,
            physics="collider",
            info={"id": door.id, "assetId": door.asset_id, "room0": door.room0, "room1": door.room1},
        )
        out.append((door.room0, node))
    for window in house.windows:
        bars, pane = _window_meshes(window, frames[window.wall0])
        node = Node(
            f"{floor}/{window.id}", "window", mesh=bars, look=WINDOW_FRAME, physics="collider",
            info={"id": window.id, "assetId": window.asset_id, "room0": window.room0},
        )
        node.add(Node(f"{floor}/{window.id}/glass", "glass", mesh=pane, look=GLASS))
        out.append((window.room0, node))
    return out


def wall_nodes(house: House, floor: str) -> tuple[list[Node], dict[str, WallFrame]]:
    """A node for every wall that is not ``empty`` (an empty wall is an open connection)."""
    frames = wall_frames(house)
    holes = _holes(house, frames)
    nodes = [wall_node(f, holes.get(wid, []), floor) for wid, f in frames.items() if not f.wall.empty]
    return nodes, frames
