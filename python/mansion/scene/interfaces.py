"""Where rooms meet: the floor's boundaries cut into *interfaces*, the maximal straight stretches
of boundary between one room and one neighbour (another room, or the outside).

AI2-THOR walls are one-sided, so every interface becomes two walls: one facing each room, or one
facing the room and a reversed twin facing the outside. Computing the interfaces once, from the
room polygons, is what makes the two sides of a wall identical and reversed (the loader mirrors a
door's hole onto the second wall, so they must line up to the millimetre).

Plan coordinates are x right, y up (the layout's); the scene maps them to AI2-THOR's x and z.
A room's outer ring is walked clockwise and its holes counter-clockwise, so the room is always on
the right of a→b, which is the side the simulator shows.
"""

from __future__ import annotations

import math
from collections import defaultdict
from collections.abc import Sequence
from dataclasses import dataclass

from mansion.exceptions import InvalidBuildingError

__all__ = ["Interface", "Pt", "RoomRings", "find_interfaces", "oriented"]

Pt = tuple[float, float]

#: Room polygons come from a grid of 0.5 m (or finer) cells, so coordinates that should be equal
#: differ only by float noise; rounding to a micrometre makes them identical keys.
_DIGITS = 6


def _snap(p: Sequence[float]) -> Pt:
    return (round(float(p[0]), _DIGITS) + 0.0, round(float(p[1]), _DIGITS) + 0.0)


def _signed_area(ring: Sequence[Pt]) -> float:
    return 0.5 * sum(
        ring[i][0] * ring[(i + 1) % len(ring)][1] - ring[(i + 1) % len(ring)][0] * ring[i][1]
        for i in range(len(ring))
    )


def oriented(ring: Sequence[Sequence[float]], clockwise: bool) -> list[Pt]:
    """The ring snapped, without repeated or collinear-redundant points, in the given direction."""
    pts: list[Pt] = []
    for p in ring:
        q = _snap(p)
        if not pts or pts[-1] != q:
            pts.append(q)
    if len(pts) > 1 and pts[0] == pts[-1]:
        pts.pop()
    # Drop vertices in the middle of a straight edge: they would split walls for no reason.
    changed = True
    while changed and len(pts) > 3:
        changed = False
        for i in range(len(pts)):
            a, b, c = pts[i - 1], pts[i], pts[(i + 1) % len(pts)]
            if abs((b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])) < 1e-9:
                del pts[i]
                changed = True
                break
    if (_signed_area(pts) < 0) != clockwise:
        pts.reverse()
    return pts


@dataclass(frozen=True)
class RoomRings:
    """A room's outer ring and holes, as the layout gives them (any orientation)."""

    id: str
    outer: Sequence[Sequence[float]]
    holes: Sequence[Sequence[Sequence[float]]] = ()


@dataclass(frozen=True)
class Interface:
    """The straight stretch a→b with ``room`` on its right and ``other`` (None: outside) on its
    left, seen from above with x right and y (the scene's z) up."""

    room: str
    other: str | None
    a: Pt
    b: Pt

    @property
    def length(self) -> float:
        return math.dist(self.a, self.b)

    @property
    def direction(self) -> Pt:
        n = self.length
        return ((self.b[0] - self.a[0]) / n, (self.b[1] - self.a[1]) / n)

    def at(self, t: float) -> Pt:
        """The point ``t`` metres from a towards b."""
        d = self.direction
        return (self.a[0] + d[0] * t, self.a[1] + d[1] * t)

    @property
    def left_normal(self) -> Pt:
        """Unit normal pointing into ``other`` (away from ``room``)."""
        d = self.direction
        return (-d[1], d[0])


def _split_edge(p: Pt, q: Pt, on_x: dict[float, list[Pt]], on_y: dict[float, list[Pt]]) -> list[Pt]:
    """p, then every vertex of any room strictly inside p→q in order, then q."""
    if p[1] == q[1]:
        lo, hi = sorted((p[0], q[0]))
        inner = sorted({v for v in on_y.get(p[1], ()) if lo < v[0] < hi}, reverse=q[0] < p[0])
    elif p[0] == q[0]:
        lo, hi = sorted((p[1], q[1]))
        inner = sorted(
            {v for v in on_x.get(p[0], ()) if lo < v[1] < hi},
            key=lambda v: v[1],
            reverse=q[1] < p[1],
        )
    else:
        raise InvalidBuildingError(
            f"room edge {list(p)} → {list(q)} is not axis-aligned; scenes need orthogonal rooms"
        )
    return [p, *inner, q]


def find_interfaces(rooms: Sequence[RoomRings]) -> list[Interface]:
    """Every interface of the floor: one per room–room stretch (``room`` < ``other`` by id, the
    twin is the same stretch reversed) and one per room–outside stretch."""
    rings: dict[str, list[list[Pt]]] = {}
    for r in rooms:
        rings[r.id] = [oriented(r.outer, clockwise=True)] + [
            oriented(h, clockwise=False) for h in r.holes
        ]
    on_x: dict[float, list[Pt]] = defaultdict(list)
    on_y: dict[float, list[Pt]] = defaultdict(list)
    for rs in rings.values():
        for ring in rs:
            for v in ring:
                on_x[v[0]].append(v)
                on_y[v[1]].append(v)

    # Elementary pieces: every ring edge cut at every vertex lying on it, so two rooms that share
    # a stretch produce the very same pieces, reversed.
    pieces: dict[str, list[list[tuple[Pt, Pt]]]] = {}
    owner: dict[tuple[Pt, Pt], str] = {}
    for rid, rs in rings.items():
        pieces[rid] = []
        for ring in rs:
            seq: list[tuple[Pt, Pt]] = []
            for i, p in enumerate(ring):
                pts = _split_edge(p, ring[(i + 1) % len(ring)], on_x, on_y)
                seq.extend(zip(pts, pts[1:], strict=False))
            for piece in seq:
                if piece in owner:
                    raise InvalidBuildingError(
                        f"rooms {owner[piece]!r} and {rid!r} overlap along {list(piece[0])} → "
                        f"{list(piece[1])}"
                    )
                owner[piece] = rid
            pieces[rid].append(seq)

    out: list[Interface] = []
    for rid, seqs in pieces.items():
        for seq in seqs:
            for a, b, other in _runs(seq, owner):
                if other is None or rid < other:
                    out.append(Interface(rid, other, a, b))
    return out


def _runs(
    seq: list[tuple[Pt, Pt]], owner: dict[tuple[Pt, Pt], str]
) -> list[tuple[Pt, Pt, str | None]]:
    """Merge consecutive pieces with the same neighbour and direction into maximal runs."""

    def label(piece: tuple[Pt, Pt]) -> tuple[str | None, Pt]:
        (ax, ay), (bx, by) = piece
        n = math.hypot(bx - ax, by - ay)
        return owner.get((piece[1], piece[0])), (round((bx - ax) / n, 6), round((by - ay) / n, 6))

    labels = [label(p) for p in seq]
    # Start at a piece whose predecessor differs, so no run wraps around the ring's start.
    start = next(i for i in range(len(seq)) if labels[i] != labels[i - 1])
    order = list(range(start, len(seq))) + list(range(start))
    runs: list[tuple[Pt, Pt, str | None]] = []
    prev: tuple[str | None, Pt] | None = None
    for i in order:
        if runs and labels[i] == prev:
            runs[-1] = (runs[-1][0], seq[i][1], runs[-1][2])
        else:
            runs.append((seq[i][0], seq[i][1], labels[i][0]))
        prev = labels[i]
    return runs
