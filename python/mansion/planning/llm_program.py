"""The LLM building planner's program step: the paper's building-program prompt, checked.

Our geometry code fixes what an LLM should not be trusted with, before the question is asked:
the number of floors and the area (ResolveNumericConstraints, from the arguments, the
description or the building type), every floor's outline (the paper's planner is given the
boundary, "using the first-floor plan as reference"), the core sizes and the palette. The model
then answers the paper's questions: the building's function, the vertical connectivity, where
the cores go, each floor's rooms (hub first, areas, materials) and which floors are copies.

The answer is checked (:func:`program_from_answer`): every floor present once, copies only of a
lower original with the same outline, core types matching the method, room ids unique and never a
core id, room areas adding up to no more than the free area. Problems go back to the model. Core
boxes are then checked by :func:`~mansion.planning.cores.core_problem`; a box that breaks our
rules (not in a corner bounded by two exterior walls, overlapping, cutting the floor into pieces)
is re-placed by :func:`~mansion.planning.cores.place_cores` at the fitting corner nearest to it,
and the reasoning records the move. Room areas are scaled to fill the free area exactly, the hub
taking the circulation reserve, as the offline planner does.
"""

from __future__ import annotations

import json
import random
import re
from dataclasses import dataclass
from typing import Literal

from pydantic import BaseModel, ConfigDict, Field
from shapely.geometry import Polygon

from mansion.agents.llm import AnswerRejected
from mansion.models.building import (
    BuildingCore,
    BuildingProgram,
    ConnectivityMethod,
    FloorCopy,
    FloorProgram,
    Palette,
    ProgramRoom,
)
from mansion.planning.cores import core_problem, place_cores
from mansion.planning.description import Request
from mansion.planning.footprints import Outline
from mansion.planning.program import (
    ProgramOptions,
    connectivity,
    core_requests,
    fit_minimums,
    min_arm,
    resolve_constraints,
    sample_outlines,
)
from mansion.planning.typologies import Typology

__all__ = ["Frame", "ProgramAnswer", "program_from_answer", "prompt_values"]

#: Room areas may add up to this much more than the free area before the answer is refused
#: (they are scaled to fit anyway; far over means the model misread the area).
AREA_SLACK = 1.05
#: ... and must cover at least this share of it.
AREA_FLOOR = 0.5


# -- the answer, as the prompt's output schema --------------------------------------------------


class CoreAnswer(BaseModel):
    id: str = Field(min_length=1)
    type: Literal["stair", "elevator"]
    x: list[float] = Field(min_length=2, max_length=2)
    y: list[float] = Field(min_length=2, max_length=2)


class ConnectivityAnswer(BaseModel):
    method: Literal["stair", "elevator", "stair_and_elevator", "none"]
    cores: list[CoreAnswer] = Field(default_factory=list)
    justification: str = ""


class RoomAnswer(BaseModel):
    id: str = Field(min_length=1)
    function: str = Field(min_length=1)
    area_estimate: float = Field(gt=0.0)
    zone: str | None = None
    floor_material: str = ""
    wall_material: str = ""
    notes: str = ""


class AreaSummary(BaseModel):
    sum_rooms: float | None = None
    reserve_ratio: float | None = None
    fits_within_gfa: bool | None = None
    notes: str = ""


class FloorAnswer(BaseModel):
    """A floor's program, or the paper's ``{"index": k, "copy": j}``."""

    model_config = ConfigDict(populate_by_name=True)

    index: int = Field(ge=0)
    copy_of: int | None = Field(default=None, alias="copy")
    requirement: str = ""
    gross_floor_area: float | None = None
    rooms: list[RoomAnswer] | None = None
    area_summary: AreaSummary | None = None


class ProgramAnswer(BaseModel):
    building_type: str = Field(min_length=1)
    reasoning: str = ""
    vertical_connectivity: ConnectivityAnswer
    floors: list[FloorAnswer] = Field(min_length=1)


# -- what our code decides before asking --------------------------------------------------------


@dataclass(frozen=True)
class Frame:
    """The numeric constraints, outlines, core sizes and palette, fixed before the model is asked."""

    request: Request
    typology: Typology
    floors: int
    area: float
    outlines: list[Outline]
    core_sizes: dict[str, tuple[int, int]]
    method: ConnectivityMethod | None
    palette: Palette
    load_bearing: bool

    @staticmethod
    def resolve(
        request: Request, key: str, typ: Typology, options: ProgramOptions, palette: Palette,
        rng: random.Random,
    ) -> Frame:
        floors, area = resolve_constraints(request, typ, options, rng)
        outlines = sample_outlines(typ, floors, area, options, rng, min_arm=min_arm(typ, key))
        method, _, _ = connectivity(request, typ, floors)
        sizes = {kind: size for _, kind, size in core_requests(typ, 1, 1)}
        load_bearing = typ.load_bearing if options.load_bearing is None else options.load_bearing
        return Frame(request, typ, floors, area, outlines, sizes, method, palette, load_bearing)

    def free_area(self, index: int, cores: list[BuildingCore]) -> float:
        gross = Polygon(*self.outlines[index]).area
        return gross - sum((c.x[1] - c.x[0]) * (c.y[1] - c.y[0]) for c in cores if index in c.floors)


def palette_text(palette: Palette) -> str:
    roles = "; ".join(f"{role}: floor {f}, walls {w}" for role, (f, w) in palette.materials.items())
    return f"{palette.name} ({palette.style}; colours: {palette.colour_scheme}). Materials by role: {roles}"


def prompt_values(frame: Frame, description: str, building_type: str) -> dict[str, object]:
    """The building-program template's placeholders."""
    req = frame.request
    outlines = [
        {"index": i, "outline": o[0], "holes": o[1], "gross_area": round(Polygon(*o).area, 1)}
        for i, o in enumerate(frame.outlines)
    ]
    sizes = ", ".join(f"{k} {w} x {d} m" for k, (w, d) in frame.core_sizes.items())
    if frame.floors == 1:
        rule = "a single floor needs no vertical core: method none, no cores"
    else:
        asked = []
        if req.stairs is not None:
            asked.append(f"{req.stairs} stair(s)")
        if req.elevators is not None:
            asked.append(f"{req.elevators} elevator(s)")
        rule = (
            f"{frame.floors} floors need at least one stair or elevator serving every floor; "
            f"our rules of thumb suggest {frame.method}"
            + (f"; the request asks for {' and '.join(asked)}" if asked else "")
        )
    layout = {
        "floors": frame.floors, "area_per_floor": round(frame.area, 1), "core_sizes_m": frame.core_sizes,
        "outlines_differ": len({json.dumps(o) for o in frame.outlines}) > 1,
    }
    return {
        "outlines_json": json.dumps(outlines),
        "floors": frame.floors,
        "area_note": f"about {frame.area:.0f} m2 gross per floor (floor 0 is the ground floor)",
        "building_type": building_type,
        "user_part": description,
        "core_area": sizes,
        "connectivity_rule": rule,
        "palette_text": palette_text(frame.palette),
        "layout_json": json.dumps(layout),
    }


# -- checking the answer ------------------------------------------------------------------------


def _snake(text: str) -> str:
    return re.sub(r"[^a-z0-9]+", "_", text.strip().lower()).strip("_") or "room"


def _structure_problems(answer: ProgramAnswer, frame: Frame) -> list[str]:
    problems: list[str] = []
    indices = [f.index for f in answer.floors]
    if indices != list(range(frame.floors)):
        problems.append(
            f"the building has exactly {frame.floors} floors; list floors with index 0 to "
            f"{frame.floors - 1} in order (got indices {indices})"
        )
        return problems
    for f in answer.floors:
        if f.copy_of is not None:
            src = f.copy_of
            if src >= f.index or answer.floors[src].copy_of is not None:
                problems.append(f"floor {f.index} copies floor {src}; a copy must name an original floor below it")
            elif frame.outlines[src] != frame.outlines[f.index]:
                problems.append(
                    f"floor {f.index} cannot copy floor {src}: their outlines differ; give floor {f.index} its own rooms"
                )
            continue
        if not f.rooms:
            problems.append(f"floor {f.index} has no rooms; list its rooms, the circulation hub first")
            continue
        ids = [r.id for r in f.rooms]
        dupes = sorted({i for i in ids if ids.count(i) > 1})
        if dupes:
            problems.append(f"floor {f.index}: room ids {dupes} are used more than once")
    vc = answer.vertical_connectivity
    if frame.floors == 1:
        return problems
    if vc.method == "none" or not vc.cores:
        problems.append(f"a {frame.floors}-floor building needs stairs or elevators; give the method and the cores")
        return problems
    kinds = {c.type for c in vc.cores}
    wanted = {"stair": {"stair"}, "elevator": {"elevator"}, "stair_and_elevator": {"stair", "elevator"}}[vc.method]
    if kinds != wanted:
        problems.append(f"method {vc.method} needs cores of types {sorted(wanted)}, got {sorted(kinds)}")
    core_ids = [c.id for c in vc.cores]
    if len(set(core_ids)) != len(core_ids):
        problems.append(f"core ids must be unique, got {core_ids}")
    for f in answer.floors:
        clash = sorted({r.id for r in f.rooms or []} & set(core_ids))
        if clash:
            problems.append(f"floor {f.index}: room ids {clash} are core ids; rename the rooms")
    return problems


def _cores(answer: ProgramAnswer, frame: Frame, rng: random.Random) -> tuple[list[BuildingCore], list[str]]:
    """The cores, each where the model put it if our rules allow, else re-placed nearby."""
    if frame.floors == 1:
        return [], []
    served = list(range(frame.floors))
    accepted: list[BuildingCore] = []
    moved: list[tuple[str, str, tuple[float, float]]] = []
    notes: list[str] = []
    for c in answer.vertical_connectivity.cores:
        proposal = BuildingCore(
            id=c.id, type=c.type, x=(min(c.x), max(c.x)), y=(min(c.y), max(c.y)), floors=served
        )
        why = core_problem(proposal, frame.core_sizes[c.type], frame.outlines, accepted)
        if why is None:
            accepted.append(proposal)
        else:
            moved.append((c.id, c.type, ((proposal.x[0] + proposal.x[1]) / 2, (proposal.y[0] + proposal.y[1]) / 2)))
            notes.append(why)
    if moved:
        placed = place_cores(
            frame.outlines, [(cid, kind, frame.core_sizes[kind]) for cid, kind, _ in moved], served, rng,
            placed_cores=accepted, near={cid: p for cid, _, p in moved},
        )
        by_id = {c.id: c for c in [*accepted, *placed]}
        order = [c.id for c in answer.vertical_connectivity.cores]
        accepted = [by_id[cid] for cid in order]
        notes = [f"{n}; re-placed at x={list(by_id[cid].x)}, y={list(by_id[cid].y)}" for n, (cid, _, _) in zip(notes, moved)]
    return accepted, notes


def _floor_program(f: FloorAnswer, frame: Frame, cores: list[BuildingCore]) -> tuple[FloorProgram | None, str | None]:
    rooms = f.rooms or []
    free = frame.free_area(f.index, cores)
    total = sum(r.area_estimate for r in rooms)
    if total > free * AREA_SLACK or total < free * AREA_FLOOR:
        return None, (
            f"floor {f.index}: the rooms add up to {total:.0f} m2 but the free area (gross minus "
            f"cores) is {free:.0f} m2; keep the sum between {AREA_FLOOR * free:.0f} and {free:.0f} m2"
        )
    scale = free / total
    # No room below its type's minimum area (the room design table): the difference comes from
    # the rooms above theirs; a program that cannot hold its rooms at their minimum goes back.
    types = [_snake(r.function) for r in rooms]
    _, areas, missing = fit_minimums(
        [(t, r.area_estimate * scale) for t, r in zip(types, rooms)], free, []
    )
    if missing > 0:
        return None, (
            f"floor {f.index}: at their minimum areas the rooms need {missing:.0f} m2 more than the "
            f"free area of {free:.0f} m2; drop, merge or move rooms to another floor"
        )
    program_rooms = [
        ProgramRoom(
            id=r.id, room_type=_snake(r.function), area=round(areas[i], 2),
            zone=r.zone or None, floor_material=r.floor_material, wall_material=r.wall_material,
            notes=r.notes if i else (r.notes or "circulation hub"),
        )
        for i, r in enumerate(rooms)
    ]
    outline = frame.outlines[f.index]
    return FloorProgram(
        index=f.index, requirement=f.requirement, outline=outline[0], holes=outline[1],
        gross_floor_area=Polygon(*outline).area, rooms=program_rooms,
        reserve_ratio=round(min(1.0, program_rooms[0].area / free), 4),
    ), None


def program_from_answer(answer: ProgramAnswer, frame: Frame, rng: random.Random) -> BuildingProgram:
    """The checked :class:`BuildingProgram`; :class:`AnswerRejected` lists what the model must fix."""
    problems = _structure_problems(answer, frame)
    if problems:
        raise AnswerRejected(problems)
    cores, moves = _cores(answer, frame, rng)
    floors: list[FloorProgram | FloorCopy] = []
    for f in answer.floors:
        if f.copy_of is not None:
            floors.append(FloorCopy(index=f.index, copy=f.copy_of))
            continue
        program, problem = _floor_program(f, frame, cores)
        if problem is not None:
            problems.append(problem)
        elif program is not None:
            floors.append(program)
    if problems:
        raise AnswerRejected(problems)
    method = None if frame.floors == 1 else answer.vertical_connectivity.method
    reasoning = answer.reasoning.strip()
    if moves:
        reasoning += " [Cores moved by the geometry check: " + " | ".join(moves) + "]"
    return BuildingProgram(
        building_type=_snake(answer.building_type), reasoning=reasoning, floor_count=frame.floors,
        area_per_floor=frame.area, method=method,  # type: ignore[arg-type]
        cores=cores, floors=floors, load_bearing_walls=frame.load_bearing,
    )
