"""Doors and openings between rooms, and windows in exterior walls.

Doors: every ``access`` edge of the room graph becomes a passage through the longest stretch the
two rooms share. Whether it is a door or an opening (no wall at all) follows ``open_relation``:
a room's relation says how it opens onto the circulation that reaches it, so the edge takes the
relation of its room farther from the hub (both rooms' when they are equally far). Cores always
get doors. A stretch too short for the narrowest door asset becomes an opening, so the passage
the layout promised still exists. Finally every room must be reachable from the hub: a room that
is not (a graph edge whose rooms ended up without a shared wall) gets a door to a reachable
neighbour along their longest shared stretch.

The front door: on the ground floor, a door to the outside through an exterior stretch of the hub
or a lobby, foyer or entrance hall, where the room has an apron inside it; of those places,
instantiation keeps the one whose doorstep reaches most of the floor. Written as ProcTHOR writes
it (``room0 == room1``, ``wall1`` the exterior twin).

Windows: rooms whose type wants daylight get windows on their exterior stretches, one per ~3 m,
sized from the window assets that fit the wall.

Door and window sizes are the holes their AI2-THOR assets cut (``procthor``'s wall-holes
database). Every choice among equally good assets is a stable hash of the building seed and the
element, so scenes are deterministic.
"""

from __future__ import annotations

import hashlib
from collections import deque
from dataclasses import dataclass, field
from typing import Literal

from shapely.geometry import Polygon

from mansion.exceptions import InvalidBuildingError
from mansion.models.building import Floor
from mansion.planning.vocabulary import room_kind
from mansion.scene.databases import HoleAsset, door_assets, window_assets
from mansion.scene.interfaces import Interface

__all__ = ["Feature", "Passage", "PassagePlan", "plan_passages", "wants_windows"]

#: Wall left on each side of a door or window hole when the stretch allows it (m): keeps the
#: hole off the corner so the frame has a wall to sit in.
MARGIN = 0.15
#: Window sill height (m) and the wall kept above the window head.
SILL = 0.9
HEAD_CLEARANCE = 0.25
#: One window per this many metres of exterior wall, at most this many per stretch.
WINDOW_SPACING = 3.0
MAX_WINDOWS_PER_STRETCH = 4
#: Depth kept free in front of a door on both sides (m), so an agent can stand there: the door
#: slides along its stretch (from the middle outward) until both sides have it.
DOOR_APRON = 0.9
#: Stretches at least this long between two big rooms get a double door.
DOUBLE_DOOR_RUN = 3.0
DOUBLE_DOOR_AREA = 60.0

#: Palette roles whose rooms get no windows (bathrooms, stores, plant rooms) — plus the cores.
_DARK_ROLES = frozenset({"wet", "service"})


@dataclass(frozen=True)
class Feature:
    """A door or window hole on one interface: the wall piece [t0, t1] (metres from the
    interface's a) carries the hole [x0, x1] × [y0, y1]."""

    id: str
    kind: Literal["door", "window"]
    interface: int
    t0: float
    t1: float
    x0: float
    x1: float
    y0: float
    y1: float
    asset_id: str
    #: The layout room a door's leaf swings into (None for windows).
    swing: str | None = None


@dataclass(frozen=True)
class Passage:
    """A way between rooms ``a`` and ``b``: a door, or an opening (the walls between them empty)."""

    kind: Literal["door", "opening"]
    a: str
    b: str
    reason: str
    door: str | None = None


#: Front door places weighed per ground floor.
ENTRANCE_OPTIONS = 8
#: Room types a front door may open into when the hub has no exterior wall for one.
ENTRY_TYPES = ("lobby", "entrance_hall", "entrance_vestibule", "foyer", "reception", "hall")


@dataclass
class PassagePlan:
    features: list[Feature] = field(default_factory=list)
    empty: set[int] = field(default_factory=set)
    passages: list[Passage] = field(default_factory=list)
    #: The front door's feature id (ground floors), None when no exterior wall takes one.
    entrance: str | None = None
    #: Where the front door may go, best first (instantiation keeps the one whose doorstep
    #: reaches most of the floor, then drops the windows of its stretch).
    entrance_options: list[Feature] = field(default_factory=list)


def _pick(options: list[HoleAsset], *key: object) -> HoleAsset:
    text = ":".join(map(str, key)).encode()
    h = int.from_bytes(hashlib.blake2b(text, digest_size=4).digest(), "little")
    return options[h % len(options)]


def wants_windows(room_type: str, node_type: str) -> bool:
    """Rooms get daylight unless they are cores or their type is a wet or service room."""
    if node_type in ("stair", "elevator"):
        return False
    return room_kind(room_type).role not in _DARK_ROLES


def _depths(floor: Floor) -> dict[str, int]:
    graph = floor.graph
    links: dict[str, list[str]] = {n.id: [] for n in graph.nodes}
    for e in graph.edges:
        if e.kind == "access":
            links[e.source].append(e.target)
            links[e.target].append(e.source)
    depth = {graph.hub.id: 0}
    queue = deque([graph.hub.id])
    while queue:
        u = queue.popleft()
        for v in links[u]:
            if v not in depth:
                depth[v] = depth[u] + 1
                queue.append(v)
    return depth


def _is_open(floor: Floor, a: str, b: str, depth: dict[str, int]) -> bool:
    na, nb = floor.graph.node(a), floor.graph.node(b)
    if na.is_core or nb.is_core:
        return False
    da, db = depth.get(a, 1 << 30), depth.get(b, 1 << 30)
    if da == db:
        return na.open_relation == "open" and nb.open_relation == "open"
    return (nb if db > da else na).open_relation == "open"


class _Planner:
    def __init__(
        self, floor: Floor, interfaces: list[Interface], owner: dict[str, str],
        parts: dict[str, Polygon], seed: int, ceiling: float,
    ):
        self.floor, self.interfaces, self.seed, self.ceiling = floor, interfaces, seed, ceiling
        self.owner, self.parts = owner, parts
        self.plan = PassagePlan()
        self.depth = _depths(floor)
        self.areas = {r.id: r.area for r in floor.layout.rooms}
        self.doors = 0
        # The parts of one room (a room with a hole, cut in two) are open to each other.
        for i, f in enumerate(interfaces):
            if f.other is not None and owner[f.room] == owner[f.other]:
                self.plan.empty.add(i)
        # the interfaces each pair of layout rooms shares, in order: asked for every passage
        self.pairs: dict[frozenset[str], list[int]] = {}
        for i, f in enumerate(interfaces):
            if f.other is not None:
                self.pairs.setdefault(frozenset((owner[f.room], owner[f.other])), []).append(i)
        # each part grown by 1e-6 (the aprons' tolerance), once: every door candidate asks
        self.grown: dict[str, Polygon] = {}

    def shared(self, a: str, b: str) -> list[int]:
        return list(self.pairs.get(frozenset((a, b)), ()))

    def _grown(self, room: str) -> Polygon:
        grown = self.grown.get(room)
        if grown is None:
            grown = self.grown[room] = self.parts[room].buffer(1e-6)
        return grown

    def _apron_centre(self, f: Interface, width: float, margin: float, outside: bool = False) -> float | None:
        """Where along ``f`` a door ``width`` wide goes: nearest the middle with an apron on both
        sides (``outside``: on the room's side only); None when no place has them."""
        lo, hi = width / 2 + margin, f.length - width / 2 - margin
        nx, ny = f.left_normal
        steps = max(0, int((hi - lo) / 0.05))
        candidates = sorted((lo + (hi - lo) * k / steps if steps else (lo + hi) / 2
                             for k in range(steps + 1)), key=lambda t: abs(t - f.length / 2))
        sides = ((f.room, -1.0),) if outside else ((f.room, -1.0), (f.other, 1.0))
        for t in candidates:
            a, b = f.at(t - width / 2), f.at(t + width / 2)
            ok = True
            for room, sign in sides:
                d = sign * DOOR_APRON
                apron = Polygon([a, b, (b[0] + nx * d, b[1] + ny * d), (a[0] + nx * d, a[1] + ny * d)])
                if room is None or not self._grown(room).covers(apron):
                    ok = False
                    break
            if ok:
                return t
        return None

    def front_door(self) -> None:
        """Where a door to the outside may go on the ground floor: exterior stretches of a lobby,
        foyer, entrance hall or vestibule (else of the hub, else of a circulation room, else of
        any room but a core) where the room has an apron inside, longest first; the building's
        way in. An entry room comes before the hub: a townhouse's front door had opened into its
        living room (the hub) beside the entrance hall, a supermarket's into the sales floor
        beside its vestibule, wherever the hub's doorstep reached more of the floor."""
        if self.floor.index != 0:
            return
        hub = self.floor.graph.hub.id
        entry = {n.id for n in self.floor.graph.nodes if n.room_type in ENTRY_TYPES}
        options = [d for d in door_assets() if "Double" not in d.asset_id and d.height < self.ceiling]
        if not options:
            return
        asset = _pick(options, self.seed, self.floor.index, "entrance")
        circulation = {n.id for n in self.floor.graph.nodes
                       if not n.is_core and room_kind(n.room_type).role == "circulation"}
        # an entry room (lobby, foyer, entrance hall, vestibule), else the hub, else any
        # circulation room, else any room but a core
        tiers = [entry, {hub}, circulation, {n.id for n in self.floor.graph.nodes if not n.is_core}]
        for tier in tiers:
            self._entrance_options(tier, asset)
            if self.plan.entrance_options:
                return

    def _entrance_options(self, rooms: set[str], asset: HoleAsset) -> None:
        ranked = sorted(
            (i for i, f in enumerate(self.interfaces)
             if f.other is None and self.owner[f.room] in rooms
             and f.length >= asset.width + 2 * MARGIN),
            key=lambda i: (-self.interfaces[i].length, i),
        )
        for i in ranked:
            f = self.interfaces[i]
            mid = self._apron_centre(f, asset.width, MARGIN, outside=True)
            if mid is None:
                continue
            x0, x1 = mid - asset.width / 2, mid + asset.width / 2
            door_id = f"door|{self.floor.index}|entrance"
            self.plan.entrance_options.append(
                Feature(door_id, "door", i, x0 - MARGIN, x1 + MARGIN, x0, x1, 0.0, asset.height,
                        asset.asset_id, swing=self.owner[f.room])
            )
            if len(self.plan.entrance_options) >= ENTRANCE_OPTIONS:
                return

    def swing_into(self, a: str, b: str) -> str:
        """Which of the two rooms a door's leaf swings into: a stair or lift core (the way out,
        as egress doors open), else the room farther from the hub (a room off a corridor opens
        inward and the corridor stays clear), else the smaller room."""
        for r in (a, b):
            if self.floor.graph.node(r).is_core:
                return r
        da, db = self.depth.get(a, 1 << 30), self.depth.get(b, 1 << 30)
        if da != db:
            return a if da > db else b
        return min((a, b), key=lambda r: (self.areas.get(r, 0.0), r))

    def _door_asset(self, f: Interface, a: str, b: str) -> HoleAsset | None:
        fits = [d for d in door_assets() if d.width <= f.length and d.height < self.ceiling]
        if not fits:
            return None
        singles = [d for d in fits if "Double" not in d.asset_id]
        doubles = [d for d in fits if "Double" in d.asset_id]
        big = min(self.areas.get(a, 0.0), self.areas.get(b, 0.0)) >= DOUBLE_DOOR_AREA
        lift = any(self.floor.graph.node(r).type == "elevator" for r in (a, b))
        wide = doubles and f.length >= DOUBLE_DOOR_RUN and (big or lift)
        return _pick(doubles if wide else singles or fits, self.seed, self.floor.index, a, b)

    def door(self, a: str, b: str, reason: str) -> None:
        """A door between ``a`` and ``b`` where both sides are walkable: on the longest stretch
        they share that has an apron on both sides of the door, else the longest stretch."""
        runs = sorted(self.shared(a, b), key=lambda k: (-self.interfaces[k].length, k))
        choice = None
        for k in runs:
            f = self.interfaces[k]
            asset = self._door_asset(f, a, b)
            if asset is None:
                continue
            margin = min(MARGIN, (f.length - asset.width) / 2)
            t = self._apron_centre(f, asset.width, margin)
            if t is not None:
                choice = (k, asset, margin, t)
                break
        if choice is None:
            i = runs[0]
            f = self.interfaces[i]
            asset = self._door_asset(f, a, b)
            if asset is None:
                # The layout promised a passage here but no door asset fits: leave the wall out.
                self.plan.empty.add(i)
                self.plan.passages.append(Passage("opening", a, b, f"{reason}; too short for a door"))
                return
            margin = min(MARGIN, (f.length - asset.width) / 2)
            choice = (i, asset, margin, f.length / 2)
        i, asset, margin, mid = choice
        x0, x1 = mid - asset.width / 2, mid + asset.width / 2
        self.doors += 1
        door_id = f"door|{self.floor.index}|{self.doors}"
        self.plan.features.append(
            Feature(door_id, "door", i, x0 - margin, x1 + margin, x0, x1, 0.0, asset.height,
                    asset.asset_id, swing=self.swing_into(a, b))
        )
        self.plan.passages.append(Passage("door", a, b, reason, door_id))

    def passage(self, a: str, b: str, opening: bool, reason: str) -> bool:
        runs = self.shared(a, b)
        if not runs:
            return False
        if opening:
            self.plan.empty.update(runs)
            self.plan.passages.append(Passage("opening", a, b, reason))
        else:
            self.door(a, b, reason)
        return True

    def reach(self) -> set[str]:
        links: dict[str, set[str]] = {}
        for p in self.plan.passages:
            links.setdefault(p.a, set()).add(p.b)
            links.setdefault(p.b, set()).add(p.a)
        seen = {self.floor.graph.hub.id}
        queue = deque(seen)
        while queue:
            for v in links.get(queue.popleft(), ()):
                if v not in seen:
                    seen.add(v)
                    queue.append(v)
        return seen

    def connect_all(self) -> None:
        rooms = [r.id for r in self.floor.layout.rooms]
        while True:
            seen = self.reach()
            lost = [r for r in rooms if r not in seen]
            if not lost:
                return
            best: tuple[float, str, str] | None = None
            for i, f in enumerate(self.interfaces):
                if f.other is None or i in self.plan.empty:
                    continue
                a, b = self.owner[f.room], self.owner[f.other]
                if (a in seen) == (b in seen):
                    continue
                key = (f.length, a, b)
                if best is None or key > best:
                    best = key
            if best is None:
                raise InvalidBuildingError(
                    f"floor {self.floor.index}: rooms {', '.join(map(repr, lost))} share no wall "
                    f"with any room reached from the hub {self.floor.graph.hub.id!r}"
                )
            _, a, b = best
            self.door(a, b, "so the hub reaches every room")

    def windows(self, ceiling: float) -> None:
        nodes = {n.id: n for n in self.floor.graph.nodes}
        tall = ceiling - SILL - HEAD_CLEARANCE
        usable = [w for w in window_assets() if "Bay" not in w.asset_id and w.height <= tall]
        for i, f in enumerate(self.interfaces):
            node = nodes.get(self.owner[f.room])
            if f.other is not None or node is None or not wants_windows(node.room_type, node.type):
                continue
            n = min(MAX_WINDOWS_PER_STRETCH, int(f.length // WINDOW_SPACING))
            if n == 0 and f.length >= 1.5:
                n = 1
            if n == 0:
                continue
            bay = f.length / n
            fits = [w for w in usable if w.width + 2 * MARGIN <= bay]
            if not fits:
                continue
            # The widest asset that fits, then one of that width class by hash: rooms of a
            # building look alike without being identical.
            widest = max(w.width for w in fits)
            asset = _pick([w for w in fits if w.width >= widest - 0.35], self.seed, f.room)
            for k in range(n):
                mid = (k + 0.5) * bay
                x0, x1 = mid - asset.width / 2, mid + asset.width / 2
                margin = min(MARGIN * 2, (bay - asset.width) / 2)
                self.plan.features.append(
                    Feature(
                        f"window|{self.floor.index}|{f.room}|{i}|{k}", "window", i,
                        x0 - margin, x1 + margin, x0, x1, SILL, SILL + asset.height,
                        asset.asset_id,
                    )
                )


def plan_passages(
    floor: Floor, interfaces: list[Interface], owner: dict[str, str], parts: dict[str, Polygon],
    *, seed: int, ceiling: float,
) -> PassagePlan:
    """Doors, openings and windows of one floor. ``owner`` maps each part (the interfaces'
    rooms) to its layout room; ``parts`` gives each part's polygon."""
    p = _Planner(floor, interfaces, owner, parts, seed, ceiling)
    for e in floor.graph.edges:
        if e.kind == "access":
            p.passage(e.source, e.target, _is_open(floor, e.source, e.target, p.depth), "graph edge")
    p.connect_all()
    p.front_door()
    p.windows(ceiling)
    return p.plan
