"""The checks every building passes before it is written.

- each floor's room graph is connected and every room reaches the hub through access edges;
- every core serving a floor is a fixed node of that floor's graph, with a door, reached by an
  access edge, at the very box the building program gives it (so the box is identical on every
  floor it serves);
- every room of every floor is reachable from every floor's hub through doors and openings
  realised in the layouts (shared walls at least ``min_contact`` long) and through the cores.

A failure raises :class:`InvalidBuildingError` naming the floor and the room, edge or core.
"""

from __future__ import annotations

from collections import deque
from typing import TypeVar

from mansion.exceptions import InvalidBuildingError
from mansion.models.building import Building
from mansion.models.graph import RoomGraph

__all__ = ["check_building", "check_graph"]


K = TypeVar("K")


def _reach(start: K, links: dict[K, set[K]]) -> set[K]:
    seen = {start}
    queue = deque([start])
    while queue:
        for nxt in links.get(queue.popleft(), ()):
            if nxt not in seen:
                seen.add(nxt)
                queue.append(nxt)
    return seen


def check_graph(graph: RoomGraph, where: str) -> None:
    """Every room reaches the hub through access edges (adjacent edges give no passage)."""
    links: dict[str, set[str]] = {n.id: set() for n in graph.nodes}
    for e in graph.edges:
        if e.kind == "access":
            links[e.source].add(e.target)
            links[e.target].add(e.source)
    lost = [n.id for n in graph.nodes if n.id not in _reach(graph.hub.id, links)]
    if lost:
        raise InvalidBuildingError(
            f"{where}: rooms {', '.join(map(repr, lost))} are not reached from the hub "
            f"{graph.hub.id!r} through access edges"
        )


def check_building(building: Building, *, min_contact: float = 1.0) -> None:
    """Run every check above; raise :class:`InvalidBuildingError` on the first failure."""
    program = building.program
    links: dict[tuple[int, str], set[tuple[int, str]]] = {}
    for floor in building.floors:
        where = f"floor {floor.index}"
        graph, layout, fp = floor.graph, floor.layout, floor.footprint
        check_graph(graph, where)
        nodes = {n.id: n for n in graph.nodes}
        realised = {r.id for r in layout.rooms}
        missing = sorted(set(nodes) - realised)
        if missing:
            raise InvalidBuildingError(f"{where}: rooms {missing} are missing from the layout")
        for core in program.cores:
            if floor.index not in core.floors:
                continue
            node = nodes.get(core.id)
            if node is None or node.type != core.type:
                raise InvalidBuildingError(f"{where}: core {core.id!r} is not a {core.type} node of the floor's graph")
            if node.open_relation != "door":
                raise InvalidBuildingError(f"{where}: core {core.id!r} must open with a door")
            if not any(e.kind == "access" and core.id in (e.source, e.target) for e in graph.edges):
                raise InvalidBuildingError(f"{where}: no access edge reaches core {core.id!r}")
            try:
                placed = fp.core(core.id)
            except KeyError:
                raise InvalidBuildingError(f"{where}: core {core.id!r} is missing from the footprint") from None
            if (tuple(placed.x), tuple(placed.y)) != (tuple(core.x), tuple(core.y)):
                raise InvalidBuildingError(
                    f"{where}: core {core.id!r} is at x={list(placed.x)} y={list(placed.y)}, "
                    f"not at its box x={list(core.x)} y={list(core.y)} of the other floors"
                )
        for rid in realised:
            links.setdefault((floor.index, rid), set())
        for e in graph.edges:
            if e.kind != "access":
                continue
            adj = layout.adjacency(e.source, e.target)
            if adj is None or adj.contact + 1e-9 < min_contact:
                raise InvalidBuildingError(
                    f"{where}: the door between {e.source!r} and {e.target!r} has no shared wall "
                    f"of {min_contact:g} m in the layout"
                )
            a, b = (floor.index, e.source), (floor.index, e.target)
            links[a].add(b)
            links[b].add(a)
    for core in program.cores:
        served = sorted(core.floors)
        for lo, hi in zip(served, served[1:]):
            a, b = (lo, core.id), (hi, core.id)
            links.setdefault(a, set()).add(b)
            links.setdefault(b, set()).add(a)
    everything: set[tuple[int, str]] = set(links)
    for floor in building.floors:
        hub: tuple[int, str] = (floor.index, floor.graph.hub.id)
        reached: set[tuple[int, str]] = _reach(hub, links)
        lost = everything - reached
        if lost:
            names = ", ".join(f"{r!r} on floor {f}" for f, r in sorted(lost)[:5])
            raise InvalidBuildingError(
                f"from the hub {hub[1]!r} of floor {floor.index}, {len(lost)} rooms cannot be "
                f"reached: {names}"
            )
