"""The solved floor: room polygons, the label grid they came from, realised adjacencies and the
solver's diagnostics. All lengths in metres, areas in m², x right and y up.

The JSON written by :meth:`FloorLayout.to_json` is the format users keep; it is exactly what the
Rust solver returns, and it round-trips through these models unchanged. Unknown keys are ignored
when reading so that a newer solver's extra fields do not break older readers.
"""

from __future__ import annotations

import math
import os
from pathlib import Path
from typing import TYPE_CHECKING

from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

from mansion._io import atomic_write_text
from mansion.exceptions import InvalidInputError
from mansion.models._validation import describe_validation_error
from mansion.models.footprint import Point, Ring
from mansion.models.graph import NodeType

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

__all__ = [
    "Adjacency",
    "Diagnostics",
    "FloorLayout",
    "LabelGrid",
    "LayoutRoom",
    "RoomEnergy",
    "RoundDiagnostics",
    "RoundEnergy",
]


class LayoutRoom(BaseModel):
    """One realised room (or core) as an orthogonal polygon with optional holes."""

    id: str
    room_type: str
    type: NodeType
    polygon: Ring
    holes: list[Ring] = Field(default_factory=list)
    area: float = Field(description="Realised area in m².")
    target_area: float = Field(description="Area asked for in the room graph, m².")
    centroid: Point

    @property
    def is_core(self) -> bool:
        return self.type in ("stair", "elevator")

    @property
    def area_error(self) -> float | None:
        """Relative area error ``(area − target) / target``; None when there is no target."""
        if self.target_area <= 0:
            return None
        return (self.area - self.target_area) / self.target_area


class LabelGrid(BaseModel):
    """The winning label grid: cell (row r, col c) covers ``[ox + c·s, ox + (c+1)·s] ×
    [oy + r·s, oy + (r+1)·s]``. Row 0 is the BOTTOM row (y up). ``labels[r][c] = k`` means the
    cell belongs to room ``ids[k]``; −1 means outside the free region (any negative: no room)."""

    origin: Point
    cell_size: float = Field(gt=0)
    cols: int = Field(ge=0)
    rows: int = Field(ge=0)
    ids: list[str]
    labels: list[list[int]]

    @model_validator(mode="after")
    def _check_shape(self) -> LabelGrid:
        if len(self.labels) != self.rows:
            raise InvalidInputError(
                f"label grid has {len(self.labels)} rows of labels but rows = {self.rows}"
            )
        n = len(self.ids)
        for r, row in enumerate(self.labels):
            if len(row) != self.cols:
                raise InvalidInputError(
                    f"label grid row {r} has {len(row)} labels but cols = {self.cols}"
                )
            for c, k in enumerate(row):
                if k >= n:
                    raise InvalidInputError(
                        f"label grid cell (row {r}, col {c}) has label {k}, "
                        f"but there are only {n} ids"
                    )
        return self

    def array(self) -> npt.NDArray[np.int32]:
        """The labels as an int32 array of shape (rows, cols), row 0 at the bottom (a copy of
        the one :data:`_ARRAYS` keeps for this grid's labels)."""
        import numpy as np

        found = _ARRAYS.get(id(self.labels))
        if found is None or found[0] is not self.labels or found[1].shape != (self.rows, self.cols):
            found = _known(self.labels, np.asarray(self.labels, dtype=np.int32).reshape(self.rows, self.cols))
        return found[1].copy()

    def relabelled(self, labels: npt.NDArray[np.integer], **update: object) -> LabelGrid:
        """This grid with ``labels`` (an int array of shape (rows, cols)) and the fields of
        ``update``, its :meth:`array` known without reading the lists back."""
        import numpy as np

        lists = labels.tolist()
        grid = self.model_copy(update={**update, "labels": lists})
        _known(lists, np.array(labels, dtype=np.int32))
        return grid

    def room_at(self, x: float, y: float) -> str | None:
        """Id of the room whose cell contains the point (x, y) in metres, or None.

        Cells are half-open, ``[lo, hi)`` on both axes, so a point on a shared cell edge belongs to
        the cell above / to the right.
        """
        c = math.floor((x - self.origin[0]) / self.cell_size)
        r = math.floor((y - self.origin[1]) / self.cell_size)
        if not (0 <= r < self.rows and 0 <= c < self.cols):
            return None
        k = self.labels[r][c]
        return self.ids[k] if k >= 0 else None


#: The arrays of label grids' labels (:meth:`LabelGrid.array`), by the labels' list, which each
#: entry holds so that its id stays its own; at most this many (then the cache starts afresh).
#: The floor's mends read the same grids again and again (ten thousand times on the hundred, a
#: tenth of their time spent reading lists into arrays). A grid's labels are never changed in
#: place (a grid with other labels is a copy).
ARRAYS_CACHE = 1 << 8
_ARRAYS: dict[int, tuple[list[list[int]], npt.NDArray[np.int32]]] = {}


def _known(labels: list[list[int]], array: npt.NDArray[np.int32]) -> tuple[list[list[int]], npt.NDArray[np.int32]]:
    """Keep ``array`` as the array of ``labels`` (:data:`_ARRAYS`)."""
    if len(_ARRAYS) >= ARRAYS_CACHE:
        _ARRAYS.clear()
    _ARRAYS[id(labels)] = (labels, array)
    return labels, array


class Adjacency(BaseModel):
    """Two rooms that share wall: ``contact`` is the total shared length, ``longest`` the longest
    single straight shared segment (both in metres)."""

    a: str
    b: str
    contact: float
    longest: float


class RoomEnergy(BaseModel):
    """The energy terms of one child room of a round's winning candidate (area ratio, seed
    distance min–max normalised and over √area, wall contact, interior corners; see
    :class:`mansion.EnergyWeights`), and ``energy``, that room's total as the solver scored it
    (lower is better)."""

    ratio: float
    seed: float
    drift: float
    wall: float
    corner: float
    energy: float


class RoundEnergy(BaseModel):
    """Total energy of the winning candidate (lower is better) and its per-room terms."""

    total: float
    rooms: dict[str, RoomEnergy] = Field(default_factory=dict)


class RoundDiagnostics(BaseModel):
    """What happened in one cut round (one parent split among its children)."""

    parent: str
    children: list[str]
    retry: int | None = Field(
        description="Index of the retry whose candidates won; None when the fallback won."
    )
    fallback: bool
    widths_relaxed: bool = Field(
        default=False,
        description="No candidate met the round's width rules; for this round only they were "
        "lowered to the floor-wide rule, then to 1.0 m (an agent still passes).",
    )
    relaxed_width: float | None = Field(
        default=None,
        description="The clear width (m) the round's width rules were lowered to, when "
        "``widths_relaxed``.",
    )
    candidates: int = Field(description="Candidates grown in this round, over all retries.")
    rejected: dict[str, int] = Field(
        default_factory=dict, description="Candidates rejected, by reason."
    )
    energy: RoundEnergy
    #: wall-clock time, kept in memory and never written: the same inputs and seed must give the
    #: same bytes (a dataset compares them)
    seconds: float = Field(default=0.0, exclude=True)


class Diagnostics(BaseModel):
    rounds: list[RoundDiagnostics] = Field(
        description="The rounds of the final layout (re-cut rounds replace their earlier tries)."
    )
    fallback_used: bool
    backtracks: int = Field(
        default=0,
        description="Times a round that could not be cut sent the solver back to re-cut the "
        "round that made its region (at most 3 re-cuts per round, 8 per floor).",
    )
    #: the solver's wall-clock time for the floor: in memory only, like the rounds'
    seconds: float = Field(default=0.0, exclude=True)


class FloorLayout(BaseModel):
    """A solved floor."""

    rooms: list[LayoutRoom]
    grid: LabelGrid
    adjacencies: list[Adjacency]
    diagnostics: Diagnostics

    def room(self, id: str) -> LayoutRoom:
        """The room with this id; ``KeyError`` if there is none."""
        for room in self.rooms:
            if room.id == id:
                return room
        raise KeyError(f"no room {id!r} in the layout")

    def adjacency(self, a: str, b: str) -> Adjacency | None:
        """The shared wall of rooms ``a`` and ``b`` (in either order), or None."""
        for adj in self.adjacencies:
            if {adj.a, adj.b} == {a, b}:
                return adj
        return None

    def to_json(self, path: str | os.PathLike[str], *, indent: int | None = 2) -> Path:
        """Write the layout as JSON, atomically (temporary file + rename). Returns the path."""
        return atomic_write_text(path, self.model_dump_json(indent=indent) + "\n")

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> FloorLayout:
        """Read a layout written by :meth:`to_json`."""
        p = Path(path)
        try:
            return cls.model_validate_json(p.read_bytes())
        except ValidationError as exc:
            raise InvalidInputError(
                f"invalid floor layout in {str(p)!r}: {describe_validation_error(exc)}"
            ) from exc
