"""The ways into each room of a house JSON: its doors and its openings (walls marked ``empty``),
each as a segment of the room's outline on the floor plane (x, z).

Read from the written house alone, so the furnishing (which keeps them free) and ``mansion
validate`` (which checks that the furniture left them connected) see the same doors.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

from mansion.scene.house import House

__all__ = ["RoomEntrance", "room_entrances"]

Pt = tuple[float, float]


@dataclass(frozen=True)
class RoomEntrance:
    """A door or opening of ``room``: the segment a→b of its outline. ``swings_here``: a door
    whose leaf swings into this room."""

    id: str
    kind: Literal["door", "opening"]
    room: str
    a: Pt
    b: Pt
    swings_here: bool = False

    @property
    def width(self) -> float:
        return math.dist(self.a, self.b)


def _along(p0: Pt, p1: Pt, t: float) -> Pt:
    n = math.dist(p0, p1)
    return (p0[0] + (p1[0] - p0[0]) * t / n, p0[1] + (p1[1] - p0[1]) * t / n)


def room_entrances(house: House) -> dict[str, list[RoomEntrance]]:
    """Every room's doors (the hole's stretch of wall0, for both rooms it joins) and openings
    (each empty wall of the room), in the house's order."""
    out: dict[str, list[RoomEntrance]] = {r.id: [] for r in house.rooms}
    walls = {w.id: w for w in house.walls}
    for door in house.doors:
        wall = walls.get(door.wall0)
        if wall is None:
            continue  # a broken reference: validation reports it under hole-wall
        p0, p1 = wall.segment()
        if math.dist(p0, p1) <= 0.0:
            continue
        lo, hi = door.hole_polygon[0].x, door.hole_polygon[1].x
        a, b = _along(p0, p1, lo), _along(p0, p1, hi)
        for room in dict.fromkeys((door.room0, door.room1)):
            if room in out:
                out[room].append(RoomEntrance(door.id, "door", room, a, b, door.swing_room == room))
    for wall in house.walls:
        if wall.empty and wall.room_id in out:
            a, b = wall.segment()
            if math.dist(a, b) > 0.0:
                out[wall.room_id].append(RoomEntrance(wall.id, "opening", wall.room_id, a, b))
    return out
