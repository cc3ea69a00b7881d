"""The LLM floor planner: the paper's single-floor topology prompt, checked.

The model proposes the bubble graph; our code checks it (:func:`graph_from_answer`): a valid
:class:`RoomGraph` with one ``main``, every core serving the floor present as a fixed node with
its id and type (and no other cores), every room reached from the hub through access edges without
passing through a core (the solver never cuts a room out of a core), and room areas near the free
area. Problems go back to the model. What is ours to decide is then set, not asked: a core node's
area is its box, cores open by a door and the hub is open (the paper's rule), and room areas are
scaled to fill the free area.
"""

from __future__ import annotations

import json
import re
from collections import deque
from typing import Literal

from pydantic import BaseModel, Field, ValidationError
from shapely.geometry import Polygon, box

from mansion.agents.llm import AnswerRejected
from mansion.exceptions import InvalidInputError
from mansion.models._validation import describe_validation_error
from mansion.models.building import BuildingProgram, FloorProgram
from mansion.models.graph import RoomEdge, RoomGraph, RoomNode
from mansion.planning.topology import with_min_widths

__all__ = ["TopologyAnswer", "graph_from_answer", "prompt_values"]

#: Non-core node areas may add up to this share of the free area, either way, before the answer
#: is refused (they are scaled to fit exactly afterwards).
AREA_RANGE = (0.5, 1.2)


class NodeAnswer(BaseModel):
    id: str = Field(min_length=1)
    type: Literal["main", "Entities", "area", "elevator", "stair"]
    area: float = Field(ge=0.0)
    room_type: str | None = None
    floor_material: str = ""
    wall_material: str = ""
    open_relation: Literal["open", "door"] = "door"


class EdgeAnswer(BaseModel):
    source: str = Field(min_length=1)
    target: str = Field(min_length=1)
    kind: Literal["access", "adjacent"] = "access"


class TopologyAnswer(BaseModel):
    nodes: list[NodeAnswer] = Field(min_length=1)
    edges: list[EdgeAnswer] = Field(default_factory=list)


def _free(program: BuildingProgram, floor: FloorProgram) -> tuple[float, Polygon]:
    region = Polygon(floor.outline, floor.holes)
    for c in program.cores:
        if floor.index in c.floors:
            region = region.difference(box(c.x[0], c.y[0], c.x[1], c.y[1]))
    return region.area, region


def prompt_values(program: BuildingProgram, index: int, material_hints: str) -> dict[str, object]:
    """The topology template's placeholders for floor ``index``."""
    floor = program.floor_program(index)
    free, region = _free(program, floor)
    cores = [c for c in program.cores if index in c.floors]
    vtext = "; ".join(f"{c.id} ({c.type}) at x={list(c.x)}, y={list(c.y)}" for c in cores) or "none on this floor"
    rooms = [
        {"id": r.id, "function": r.room_type, "area": r.area, "zone": r.zone,
         "floor_material": r.floor_material, "wall_material": r.wall_material}
        for r in floor.rooms
    ]
    polys = [region] if region.geom_type == "Polygon" else list(getattr(region, "geoms", []))
    layout = [
        {"outline": [list(p) for p in g.exterior.coords[:-1]],
         "holes": [[list(p) for p in h.coords[:-1]] for h in g.interiors]}
        for g in polys
    ]
    return {
        "reasoning": program.reasoning or "(none given)",
        "idx": index,
        "gfa": f"{floor.gross_floor_area:.0f}",
        "free": f"{free:.0f}",
        "requirement": floor.requirement or "(none given)",
        "layout_json": json.dumps(layout),
        "vtext": vtext,
        "rooms_json": json.dumps(rooms),
        "material_hints_text": material_hints,
    }


def _room_type(node: NodeAnswer, program_types: dict[str, str]) -> str:
    if node.room_type:
        return re.sub(r"[^a-z0-9]+", "_", node.room_type.lower()).strip("_") or node.id
    return program_types.get(node.id) or re.sub(r"_\d+$", "", node.id)


def _unreached(graph: RoomGraph) -> list[str]:
    """Rooms not reached from the hub through access edges that do not pass through a core."""
    cores = {n.id for n in graph.nodes if n.is_core}
    links: dict[str, set[str]] = {n.id: set() for n in graph.nodes}
    for e in graph.edges:
        if e.kind == "access":
            links[e.source].add(e.target)
            links[e.target].add(e.source)
    seen = {graph.hub.id}
    queue = deque([graph.hub.id])
    while queue:
        here = queue.popleft()
        if here in cores:
            continue
        for nxt in links[here]:
            if nxt not in seen:
                seen.add(nxt)
                queue.append(nxt)
    return [n.id for n in graph.nodes if n.id not in seen]


def graph_from_answer(answer: TopologyAnswer, program: BuildingProgram, index: int) -> RoomGraph:
    """The checked room graph of floor ``index``; :class:`AnswerRejected` lists what to fix."""
    floor = program.floor_program(index)
    cores = {c.id: c for c in program.cores if index in c.floors}
    program_types = {r.id: r.room_type for r in floor.rooms}
    problems: list[str] = []

    proposed = {n.id: n for n in answer.nodes}
    for cid, core in cores.items():
        node = proposed.get(cid)
        if node is None:
            problems.append(f"core {cid!r} ({core.type}) serves this floor and must be a node with that id")
        elif node.type != core.type:
            problems.append(f"node {cid!r} is the {core.type} core; its type must be {core.type!r}, not {node.type!r}")
    strays = [n.id for n in answer.nodes if n.type in ("stair", "elevator") and n.id not in cores]
    if strays:
        problems.append(
            f"nodes {strays} are stairs/elevators this floor does not have; the only cores are "
            f"{sorted(cores) or 'none'}"
        )
    free, _ = _free(program, floor)
    total = sum(n.area for n in answer.nodes if n.type not in ("stair", "elevator"))
    lo, hi = AREA_RANGE
    if not lo * free <= total <= hi * free:
        problems.append(
            f"the non-core node areas add up to {total:.0f} m2; the free area is {free:.0f} m2, "
            f"keep the sum between {lo * free:.0f} and {hi * free:.0f} m2"
        )
    if problems:
        raise AnswerRejected(problems)

    scale = free / total
    nodes = []
    for n in answer.nodes:
        fixed = cores.get(n.id)
        nodes.append(
            RoomNode(
                id=n.id, type=n.type,
                area=(fixed.x[1] - fixed.x[0]) * (fixed.y[1] - fixed.y[0]) if fixed else n.area * scale,
                room_type=fixed.type if fixed else _room_type(n, program_types),
                floor_material=n.floor_material or None, wall_material=n.wall_material or None,
                open_relation="door" if fixed else "open" if n.type == "main" else n.open_relation,
            )
        )
    try:
        graph = RoomGraph(nodes=nodes, edges=[RoomEdge(**e.model_dump()) for e in answer.edges])
    except ValidationError as exc:
        raise AnswerRejected(describe_validation_error(exc).split("; ")) from exc
    except InvalidInputError as exc:
        raise AnswerRejected([str(exc)]) from exc
    lost = _unreached(graph)
    if lost:
        raise AnswerRejected(
            [f"rooms {lost} are not reached from the hub {graph.hub.id!r} through access edges "
             "(a stair or elevator cannot be passed through on one floor)"]
        )
    return with_min_widths(graph, program.building_type)
