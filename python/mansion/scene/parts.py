"""Rooms with holes cut into simple parts: AI2-THOR floor polygons cannot have holes.

A corridor that runs around a block of rooms, or a lobby wrapped around a core, is one room with a
hole. We cut it along the line through one of the hole's edges (the shortest such cut that leaves
no part in lobes joined by a passage narrower than an agent), which opens the hole into a notch,
until no part has a hole. The parts become rooms ``<room>|<k>`` of the house, joined by empty walls (open
connections), each recording the room it is ``part_of``.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from shapely.geometry import LineString, MultiPolygon, Polygon, box
from shapely.ops import orient

from mansion.exceptions import InvalidBuildingError

__all__ = ["RoomPart", "split_room"]

#: Narrowest passage (m) inside a part: an agent of radius 0.3 m keeping 0.05 m.
PASSAGE = 0.7


@dataclass(frozen=True)
class RoomPart:
    id: str
    room: str
    ring: list[tuple[float, float]]


def _pieces(geom: object) -> list[Polygon]:
    if isinstance(geom, Polygon):
        return [geom] if geom.area > 1e-9 else []
    if isinstance(geom, MultiPolygon):
        return [g for g in geom.geoms if g.area > 1e-9]
    parts = getattr(geom, "geoms", [])
    return [g for g in parts if isinstance(g, Polygon) and g.area > 1e-9]


def _cramped(part: Polygon) -> bool:
    """True when an agent cannot walk all of ``part``: lobes joined only through a passage
    narrower than :data:`PASSAGE`, or a strip that narrow. A cut that leaves such a part would
    cut its doors apart inside it, though the room as a whole connects them."""
    core = part.buffer(-PASSAGE / 2, join_style="mitre")
    lobes = _pieces(core)
    if len(lobes) != 1:
        return True
    return part.area - core.buffer(PASSAGE / 2, join_style="mitre").intersection(part).area > 1e-6


def _cut(poly: Polygon) -> list[Polygon]:
    hole = Polygon(poly.interiors[0])
    hx0, hy0, hx1, hy1 = hole.bounds
    x0, y0, x1, y1 = poly.bounds
    options = []
    # Cut along one of the hole's own edges: they lie on the layout's grid lines, so the cut
    # never passes through a cell centre (where the agent spawns) and parts stay on the grid.
    for vertical, c in ((True, hx0), (True, hx1), (False, hy0), (False, hy1)):
        line = LineString([(c, y0 - 1), (c, y1 + 1)] if vertical else [(x0 - 1, c), (x1 + 1, c)])
        length = line.intersection(poly).length
        halves = (
            (box(x0 - 1, y0 - 1, c, y1 + 1), box(c, y0 - 1, x1 + 1, y1 + 1))
            if vertical
            else (box(x0 - 1, y0 - 1, x1 + 1, c), box(x0 - 1, c, x1 + 1, y1 + 1))
        )
        pieces = [p for h in halves for p in _pieces(poly.intersection(h))]
        options.append((sum(map(_cramped, pieces)), length, pieces))
    return min(options, key=lambda o: o[:2])[2]


def split_room(room_id: str, outer: Sequence[Sequence[float]], holes: Sequence[Sequence[Sequence[float]]]) -> list[RoomPart]:
    """The room as one part (its own id) when it has no hole, else its simple parts."""
    if not holes:
        return [RoomPart(room_id, room_id, [(float(p[0]), float(p[1])) for p in outer])]
    todo = [Polygon(outer, holes)]
    done: list[Polygon] = []
    for _ in range(64):
        if not todo:
            break
        poly = todo.pop()
        if poly.interiors:
            todo.extend(_cut(poly))
        else:
            done.append(poly)
    if todo:
        raise InvalidBuildingError(f"room {room_id!r}: could not cut its holes into simple parts")
    # Parts in a stable order (bottom-left first) so ids do not depend on the cutting order.
    done.sort(key=lambda p: (round(p.bounds[1], 6), round(p.bounds[0], 6)))
    return [
        RoomPart(f"{room_id}|{k + 1}", room_id, [(x, y) for x, y in orient(p).exterior.coords[:-1]])
        for k, p in enumerate(done)
    ]
