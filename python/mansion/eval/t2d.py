"""Tell2Design (T2D) plans and the paper's "MA" protocol: what the solver may see of a real plan.

A plan file (``plans/<id>.json``, see the data set's README) holds pixel geometry of a 256×256
image (x right, y down) and ``label64``, the 64×64 ground-truth label map (row 0 = top). The
protocol hands the solver only:

- the free region: exactly the cells where ``label64 != 0``;
- per room: its type, its seed ``centroid / 4`` and its target area
  ``area_px / Σ area_px · (number of free cells)``;
- the adjacency pairs.

Frames. The solver works in y-up "metres"; here one metre is one cell of the 64 grid
(``CELL_SIZE = 1``). :meth:`Footprint.from_mask` puts the picture's bottom-left corner at the
origin, so mask cell (row r, column c), whose centre is (c + 0.5, r + 0.5) in the mask's y-down
frame, has its centre at (c + 0.5, 64 − r − 0.5) in the solver's frame. A seed (x, y) of the
mask frame is therefore the solver point (x, 64 − y): x unchanged, y mirrored about the grid's
height. :func:`solver_to_mask` maps a solved layout's label grid back the same way.

Nothing else of the plan file (room polygons, bounding boxes, the label map beyond its free mask,
the front door) reaches the solver; :func:`protocol_inputs` is the only bridge, and the tests
check that blanking those fields leaves the inputs unchanged.
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from pydantic import BaseModel, ConfigDict, Field, model_validator

from mansion.exceptions import InvalidInputError
from mansion.models import Footprint, LabelGrid, RoomEdge, RoomGraph, RoomNode
from mansion.models._validation import load_input

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

__all__ = [
    "CELL_SIZE",
    "GRID",
    "HUB_TYPE",
    "ProtocolInputs",
    "T2DPlan",
    "T2DRoom",
    "iter_plans",
    "plan_ids",
    "plans_folder",
    "protocol_inputs",
    "solver_to_mask",
]

#: Side of the evaluation grid, in cells.
GRID = 64
#: Pixels of the 256 image per grid cell.
_PX_PER_CELL = 4.0
#: The solver's cell size for T2D: one "metre" per cell keeps the solver's units equal to cells.
CELL_SIZE = 1.0
#: The room type that is the hub of every T2D plan (each plan has exactly one).
HUB_TYPE = "living_room"


class T2DRoom(BaseModel):
    """One room of a T2D plan (pixels of the 256 image, y down)."""

    model_config = ConfigDict(extra="ignore")

    id: int
    type: str
    area_px: float = Field(gt=0)
    centroid: tuple[float, float]
    # Geometry the protocol withholds from the solver; kept for the gallery and for tests.
    polygon: list[tuple[float, float]] | None = None
    bbox: tuple[float, float, float, float] | None = None


class T2DPlan(BaseModel):
    """One T2D plan file."""

    model_config = ConfigDict(extra="ignore")

    rooms: list[T2DRoom] = Field(min_length=1)
    adjacency: list[tuple[int, int]] = Field(default_factory=list)
    classes: list[str] = Field(min_length=2)
    label64: list[list[int]]

    @model_validator(mode="after")
    def _check(self) -> T2DPlan:
        if len(self.label64) != GRID or any(len(row) != GRID for row in self.label64):
            raise InvalidInputError(f"label64 must be {GRID}×{GRID}")
        ids = [r.id for r in self.rooms]
        if len(set(ids)) != len(ids):
            raise InvalidInputError(f"duplicate room ids in {ids}")
        for a, b in self.adjacency:
            for end in (a, b):
                if end not in ids:
                    raise InvalidInputError(f"adjacency ({a}, {b}) names unknown room {end}")
        for room in self.rooms:
            if room.type not in self.classes[1:]:
                raise InvalidInputError(f"room {room.id} has type {room.type!r}, not in classes")
        hubs = [r.id for r in self.rooms if r.type == HUB_TYPE]
        if len(hubs) != 1:
            raise InvalidInputError(f"expected exactly one {HUB_TYPE}, found {len(hubs)}")
        return self

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> T2DPlan:
        """Read a plan file; problems are :class:`InvalidInputError` naming the file."""
        return load_input(cls, path, "T2D plan")

    def label_array(self) -> npt.NDArray[np.int32]:
        """``label64`` as an int32 array, row 0 = top."""
        import numpy as np

        return np.asarray(self.label64, dtype=np.int32)


def plans_folder(data: str | os.PathLike[str]) -> Path:
    """Where the plan files of a data folder are: ``DIR/plans``, or ``DIR`` itself."""
    d = Path(data)
    plans = d / "plans"
    if plans.is_dir():
        return plans
    if d.is_dir() and any(d.glob("*.json")):
        return d
    raise InvalidInputError(f"no T2D plans in {str(d)!r}: expected a 'plans/' folder of <id>.json files")


def plan_ids(data: str | os.PathLike[str]) -> list[str]:
    """The plan ids of a data folder (``DIR/plans/<id>.json``), in numeric-then-text order."""
    ids = [p.stem for p in plans_folder(data).glob("*.json")]
    return sorted(ids, key=lambda s: (0, int(s), s) if s.isdigit() else (1, 0, s))


def iter_plans(data: str | os.PathLike[str], ids: list[str] | None = None) -> Iterator[tuple[str, T2DPlan]]:
    """Load plans one at a time (all of the folder, or the given ids)."""
    folder = plans_folder(data)
    for pid in plan_ids(data) if ids is None else ids:
        yield pid, T2DPlan.load(folder / f"{pid}.json")


@dataclass(frozen=True)
class ProtocolInputs:
    """Everything the solver is allowed to see of one plan."""

    graph: RoomGraph
    footprint: Footprint
    #: Seed of every room, by node id, in the solver's y-up frame.
    seeds: dict[str, tuple[float, float]]
    #: Node id → the plan's class index of its room type (for scoring the prediction).
    classes: dict[str, int]


def node_id(room: T2DRoom) -> str:
    return f"{room.type}_{room.id}"


def protocol_inputs(plan: T2DPlan) -> ProtocolInputs:
    """The MA protocol's solver inputs for ``plan`` (see the module docstring)."""
    import numpy as np

    labels = plan.label_array()
    mask = labels != 0
    free_cells = int(mask.sum())
    total_px = sum(r.area_px for r in plan.rooms)
    nodes: list[RoomNode] = []
    seeds: dict[str, tuple[float, float]] = {}
    classes: dict[str, int] = {}
    for room in plan.rooms:
        nid = node_id(room)
        nodes.append(
            RoomNode(
                id=nid,
                type="main" if room.type == HUB_TYPE else "Entities",
                room_type=room.type,
                area=room.area_px / total_px * free_cells * CELL_SIZE**2,
            )
        )
        x_mask = room.centroid[0] / _PX_PER_CELL
        y_mask = room.centroid[1] / _PX_PER_CELL
        seeds[nid] = (x_mask * CELL_SIZE, (GRID - y_mask) * CELL_SIZE)
        classes[nid] = plan.classes.index(room.type)
    by_id = {r.id: node_id(r) for r in plan.rooms}
    seen: set[frozenset[str]] = set()
    edges: list[RoomEdge] = []
    for a, b in plan.adjacency:
        key = frozenset((by_id[a], by_id[b]))
        if len(key) == 2 and key not in seen:
            seen.add(key)
            edges.append(RoomEdge(source=by_id[a], target=by_id[b], kind="adjacent"))
    graph = RoomGraph(nodes=nodes, edges=edges)
    footprint = Footprint.from_mask(np.asarray(mask), CELL_SIZE)
    return ProtocolInputs(graph=graph, footprint=footprint, seeds=seeds, classes=classes)


def solver_to_mask(grid: LabelGrid, classes: dict[str, int]) -> npt.NDArray[np.int32]:
    """The solved label grid as a 64×64 class map in the mask's frame (row 0 = top, 0 = none)."""
    import numpy as np

    out = np.zeros((GRID, GRID), dtype=np.int32)
    labels = grid.array()
    lut = np.array([classes.get(i, 0) for i in grid.ids] + [0], dtype=np.int32)
    # Negative labels (outside) index the trailing 0 of the lookup table.
    cls = lut[np.where(labels >= 0, labels, len(grid.ids))]
    c0 = round(grid.origin[0] / CELL_SIZE)
    r0 = round(grid.origin[1] / CELL_SIZE)
    # Grid row r (y up) lies at mask row GRID - 1 - (r0 + r); clip the grid to the 64×64 frame.
    rows = np.arange(grid.rows)
    cols = np.arange(grid.cols)
    mrow = GRID - 1 - (r0 + rows)
    mcol = c0 + cols
    rk = (mrow >= 0) & (mrow < GRID)
    ck = (mcol >= 0) & (mcol < GRID)
    out[np.ix_(mrow[rk], mcol[ck])] = cls[np.ix_(rows[rk], cols[ck])]
    return out
