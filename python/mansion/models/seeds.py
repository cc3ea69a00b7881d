"""The seed-planner interface of the cutting node.

In every cut round the solver asks a seed planner where each child room of the parent should
start growing: a point (an approximate centroid) or a box (the paper's LLM prompt asks for
``x=[xmin, xmax], y=[ymin, ymax]``), and optionally the fraction of the parent region it should
take. The solver then perturbs those seeds, grows candidates, filters and scores them.

A planner is any object with ``plan(request: SeedRequest) -> SeedPlan`` (or a plain function of
that signature). ``solve_floor(..., seed_planner=None)`` uses the built-in offline heuristic in
Rust instead. Coordinates are metres, x right, y up, in the footprint's frame.
"""

from __future__ import annotations

import json
from collections.abc import Callable, Mapping
from typing import Any, Protocol, runtime_checkable

from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

from mansion.exceptions import InvalidInputError, PlannerError
from mansion.models import Point, Ring
from mansion.models._validation import describe_validation_error

__all__ = [
    "ChildSeed",
    "FixedSeedPlanner",
    "PlacedRoom",
    "SeedBox",
    "SeedChild",
    "SeedDescendant",
    "SeedPlan",
    "SeedPlanner",
    "SeedRegion",
    "SeedRequest",
    "SeedRequestLayout",
    "planner_callback",
]


# -- the request --------------------------------------------------------------------------------


class SeedRegion(BaseModel):
    """The parent's region being cut: its polygon, area (m²) and size in grid cells."""

    polygon: Ring
    holes: list[Ring] = Field(default_factory=list)
    area: float
    cells: int


class PlacedRoom(BaseModel):
    """A room already realised by an earlier round."""

    id: str
    polygon: Ring
    holes: list[Ring] = Field(default_factory=list)


class SeedRequestLayout(BaseModel):
    """The floor as realised so far."""

    rooms: list[PlacedRoom] = Field(default_factory=list)


class SeedDescendant(BaseModel):
    """A room that a later round will cut out of a child, with its own area in m²."""

    id: str
    area: float


class SeedChild(BaseModel):
    """A child room to place in this round.

    ``target_area`` is the area the child's region must hold (its own area plus that of the rooms
    that will later be cut out of it, listed in ``descendants``); ``own_area`` is the room's own
    area. ``neighbours`` are its neighbours in the room graph.
    """

    id: str
    room_type: str
    target_area: float
    own_area: float
    neighbours: list[str] = Field(default_factory=list)
    descendants: list[SeedDescendant] = Field(default_factory=list)


class SeedRequest(BaseModel):
    """What the solver tells a seed planner about one cut round."""

    round: int
    parent: str
    cell_size: float
    region: SeedRegion
    layout: SeedRequestLayout
    children: list[SeedChild]
    parent_neighbours: list[str] = Field(default_factory=list)


# -- the answer ---------------------------------------------------------------------------------


class SeedBox(BaseModel):
    """An axis-aligned box ``x[0]..x[1]`` × ``y[0]..y[1]`` in metres."""

    model_config = ConfigDict(allow_inf_nan=False)

    x: tuple[float, float]
    y: tuple[float, float]

    @model_validator(mode="after")
    def _check(self) -> SeedBox:
        if self.x[0] > self.x[1] or self.y[0] > self.y[1]:
            raise InvalidInputError(
                f"seed box x={list(self.x)} y={list(self.y)} is inverted; "
                "need x[0] <= x[1] and y[0] <= y[1]"
            )
        return self


class ChildSeed(BaseModel):
    """Where one child starts: exactly one of ``point`` or ``box``; ``fraction`` is the share of
    the parent region it should take (0 < fraction <= 1), or None to use its target area."""

    model_config = ConfigDict(allow_inf_nan=False)

    point: Point | None = None
    box: SeedBox | None = None
    fraction: float | None = None

    @model_validator(mode="after")
    def _check(self) -> ChildSeed:
        if (self.point is None) == (self.box is None):
            raise InvalidInputError("a child seed needs exactly one of 'point' or 'box'")
        if self.fraction is not None and not (0.0 < self.fraction <= 1.0):
            raise InvalidInputError(
                f"seed fraction {self.fraction:g} is outside (0, 1]; it is a share of the "
                "parent region"
            )
        return self

    def to_binding(self) -> dict[str, Any]:
        """The JSON shape the solver reads: ``{"point": [x, y]}`` or ``{"box": {...}}``, plus
        ``"fraction"``."""
        out: dict[str, Any] = {}
        if self.point is not None:
            out["point"] = list(self.point)
        else:
            assert self.box is not None
            out["box"] = {"x": list(self.box.x), "y": list(self.box.y)}
        out["fraction"] = self.fraction
        return out


class SeedPlan(BaseModel):
    """A seed for every child of the round, by child id, and optionally one for the parent (the
    part of the parent region the parent room itself keeps).

    ``descendant_seeds`` optionally places rooms that later rounds will cut out of a child (ids
    from :attr:`SeedChild.descendants`): the child's region then grows this round from its own
    seed and theirs at once, each with its own area, so it takes the shape of the rooms it will
    hold rather than one blob around a single point."""

    model_config = ConfigDict(allow_inf_nan=False)

    seeds: dict[str, ChildSeed]
    parent_seed: Point | None = None
    descendant_seeds: dict[str, Point] = Field(default_factory=dict)

    def to_binding_json(self) -> str:
        """The plan as the JSON string the Rust solver expects back from a planner callback."""
        return json.dumps(
            {
                "seeds": {cid: seed.to_binding() for cid, seed in self.seeds.items()},
                "parent_seed": None if self.parent_seed is None else list(self.parent_seed),
                "descendant_seeds": {k: list(p) for k, p in self.descendant_seeds.items()},
            }
        )


# -- planners -----------------------------------------------------------------------------------


@runtime_checkable
class SeedPlanner(Protocol):
    """Anything that proposes a seed plan for a cut round."""

    def plan(self, request: SeedRequest) -> SeedPlan: ...


class FixedSeedPlanner:
    """A planner that answers from fixed points, one per room id: where each room's centroid
    should be.

    Each child gets its own point; the parent gets its own point as its ``parent_seed`` when
    present. With ``descendants=True`` (the default) the plan also carries the points of the
    rooms later rounds will cut out of each child, so the child's region grows from all of them
    (see :class:`SeedPlan`). A child without a point is an error (raised as
    :class:`PlannerError` by the solver).
    """

    def __init__(
        self, points: Mapping[str, tuple[float, float]], *, descendants: bool = True
    ) -> None:
        self.points: dict[str, tuple[float, float]] = {
            k: (float(p[0]), float(p[1])) for k, p in points.items()
        }
        self.descendants = descendants

    def plan(self, request: SeedRequest) -> SeedPlan:
        missing = [c.id for c in request.children if c.id not in self.points]
        if missing:
            names = ", ".join(repr(m) for m in missing)
            raise PlannerError(
                f"FixedSeedPlanner has no point for {names} (round {request.round}, "
                f"parent {request.parent!r})"
            )
        later = (
            {d.id: self.points[d.id] for c in request.children for d in c.descendants if d.id in self.points}
            if self.descendants
            else {}
        )
        return SeedPlan(
            seeds={c.id: ChildSeed(point=self.points[c.id]) for c in request.children},
            parent_seed=self.points.get(request.parent),
            descendant_seeds=later,
        )

    def __repr__(self) -> str:
        return f"FixedSeedPlanner({self.points!r}, descendants={self.descendants})"


PlanFunction = Callable[[SeedRequest], "SeedPlan | Mapping[str, Any]"]


def planner_callback(planner: SeedPlanner | PlanFunction) -> Callable[[str], str]:
    """Wrap a planner as the ``Callable[[str], str]`` that ``mansion._core.solve_floor`` calls.

    The callback parses the request JSON into a :class:`SeedRequest`, calls the planner, checks
    the plan (a :class:`SeedPlan` or a dict of that shape) gives exactly one seed per child, and
    returns it as JSON. Any exception inside the planner becomes a :class:`PlannerError` carrying
    the original message (the original stays chained as ``__cause__``).
    """
    plan_fn: Callable[[SeedRequest], Any]
    if isinstance(planner, SeedPlanner):
        plan_fn = planner.plan
    elif callable(planner):
        plan_fn = planner
    else:
        raise InvalidInputError(
            f"seed_planner must have a plan(request) method or be callable, "
            f"got {type(planner).__name__}"
        )
    name = type(planner).__name__ if isinstance(planner, SeedPlanner) else getattr(
        planner, "__name__", type(planner).__name__
    )

    def callback(request_json: str) -> str:
        try:
            request = SeedRequest.model_validate_json(request_json)
        except ValidationError as exc:
            raise PlannerError(
                f"the solver sent a malformed seed request: {describe_validation_error(exc)}"
            ) from exc
        where = f"round {request.round}, parent {request.parent!r}"
        try:
            raw = plan_fn(request)
        except PlannerError:
            raise
        except Exception as exc:
            raise PlannerError(f"seed planner {name} failed in {where}: {exc}") from exc
        try:
            plan = raw if isinstance(raw, SeedPlan) else SeedPlan.model_validate(raw)
        except ValidationError as exc:
            raise PlannerError(
                f"seed planner {name} returned an invalid plan in {where}: "
                f"{describe_validation_error(exc)}"
            ) from exc
        wanted = [c.id for c in request.children]
        unknown = [cid for cid in plan.seeds if cid not in wanted]
        if unknown:
            names = ", ".join(repr(u) for u in unknown)
            raise PlannerError(
                f"seed planner {name} gave seeds for {names}, which are not children in {where} "
                f"(children: {', '.join(repr(w) for w in wanted)})"
            )
        missing = [cid for cid in wanted if cid not in plan.seeds]
        if missing:
            names = ", ".join(repr(m) for m in missing)
            raise PlannerError(f"seed planner {name} gave no seed for {names} in {where}")
        return plan.to_binding_json()

    return callback
