"""The floor footprint: outline, courtyards (holes), vertical cores and fixed walls, in metres.

Coordinates are x right, y up. The free region the solver partitions is the outline minus the holes
minus the cores. Cores are axis-aligned boxes; each one is matched to the room-graph node with the
same id (type ``stair`` or ``elevator``).
"""

from __future__ import annotations

import math
import os
from collections.abc import Sequence
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

from mansion.exceptions import InvalidInputError
from mansion.models._validation import load_input, validate_input

__all__ = ["Core", "Footprint", "Point", "Ring", "ring_area"]

Point = tuple[float, float]
Ring = list[Point]


def ring_area(ring: Sequence[Sequence[float]]) -> float:
    """Unsigned area of a simple ring (shoelace formula); the ring need not repeat its first point."""
    n = len(ring)
    twice = 0.0
    for i in range(n):
        x0, y0 = ring[i][0], ring[i][1]
        x1, y1 = ring[(i + 1) % n][0], ring[(i + 1) % n][1]
        twice += x0 * y1 - x1 * y0
    return abs(twice) / 2.0


def _positive_size(value: object) -> float:
    try:
        size = float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        size = float("nan")
    if not (math.isfinite(size) and size > 0):
        raise InvalidInputError(f"cell_size must be a finite number > 0, got {value!r}")
    return size


class Core(BaseModel):
    """A vertical core (stair or elevator shaft): the box ``x[0]..x[1]`` × ``y[0]..y[1]``."""

    model_config = ConfigDict(allow_inf_nan=False)

    id: str = Field(min_length=1)
    type: Literal["stair", "elevator"]
    x: tuple[float, float]
    y: tuple[float, float]

    @model_validator(mode="after")
    def _check_box(self) -> Core:
        if not (self.x[0] < self.x[1] and self.y[0] < self.y[1]):
            raise InvalidInputError(
                f"core {self.id!r} has an empty box x={list(self.x)} y={list(self.y)}; "
                "need x[0] < x[1] and y[0] < y[1]"
            )
        return self

    @property
    def area(self) -> float:
        return (self.x[1] - self.x[0]) * (self.y[1] - self.y[0])


class Footprint(BaseModel):
    """The outline of one floor and what is fixed in it.

    ``polygon`` is the outer ring (not closed: the first point is not repeated), ``holes`` are
    courtyards or shafts that belong to no room, ``fixed_walls`` are segments the layout keeps as
    walls (for example load-bearing walls of the floor below).
    """

    model_config = ConfigDict(allow_inf_nan=False)

    polygon: Ring
    holes: list[Ring] = Field(default_factory=list)
    cores: list[Core] = Field(default_factory=list)
    fixed_walls: list[tuple[Point, Point]] = Field(default_factory=list)

    @model_validator(mode="after")
    def _check(self) -> Footprint:
        if len(self.polygon) < 3:
            raise InvalidInputError(
                f"footprint polygon has {len(self.polygon)} vertices; at least 3 are needed"
            )
        for i, hole in enumerate(self.holes):
            if len(hole) < 3:
                raise InvalidInputError(
                    f"footprint hole {i} has {len(hole)} vertices; at least 3 are needed"
                )
        seen: set[str] = set()
        for core in self.cores:
            if core.id in seen:
                raise InvalidInputError(f"duplicate core id {core.id!r} in the footprint")
            seen.add(core.id)
        for i, (a, b) in enumerate(self.fixed_walls):
            if a == b:
                raise InvalidInputError(f"fixed wall {i} has zero length (both ends at {list(a)})")
        return self

    # -- construction helpers ------------------------------------------------------------------

    @classmethod
    def rectangle(cls, width: float, height: float, *, cores: Sequence[Core] = ()) -> Footprint:
        """The ``width`` × ``height`` rectangle with its lower-left corner at the origin."""
        if not (width > 0 and height > 0):
            raise InvalidInputError(
                f"rectangle footprint needs width and height > 0, got {width} × {height}"
            )
        return cls(
            polygon=[(0.0, 0.0), (width, 0.0), (width, height), (0.0, height)],
            cores=list(cores),
        )

    @classmethod
    def from_mask(cls, mask: Any, cell_size: float) -> Footprint:
        """The footprint whose cells are the true cells of a boolean mask.

        ``mask`` is a 2-D boolean array-like in *image* convention: row 0 is the TOP row, as in a
        picture. With ``H`` rows and cell size ``s`` (metres), cell (row ``r``, column ``c``)
        covers x ∈ [c·s, (c+1)·s] and y ∈ [(H−r−1)·s, (H−r)·s] in y-up metres; so the picture's
        bottom-left corner is the origin. The true cells must form one 4-connected piece; false
        cells enclosed by it become holes. Rasterising the result at cell size ``s`` gives back
        exactly the mask.
        """
        import numpy as np

        from mansion._native import native

        s = _positive_size(cell_size)
        arr = np.asarray(mask)
        if arr.ndim != 2 or arr.size == 0:
            raise InvalidInputError(
                f"mask must be a non-empty 2-D array, got shape {tuple(arr.shape)}"
            )
        if arr.dtype != np.bool_:
            if not np.isin(arr, (0, 1)).all():
                raise InvalidInputError("mask must hold booleans (or 0/1 values)")
            arr = arr.astype(bool)
        if not arr.any():
            raise InvalidInputError("mask has no true cell; the footprint would be empty")
        # The core works in y-up grids (row 0 = bottom): flip the picture upside down.
        grid = np.ascontiguousarray(arr[::-1], dtype=np.uint8)
        outer, holes = native().mask_outline(grid)
        return cls(
            polygon=[(i * s, j * s) for i, j in outer],
            holes=[[(i * s, j * s) for i, j in hole] for hole in holes],
        )

    @classmethod
    def parse(cls, data: Footprint | dict[str, Any]) -> Footprint:
        """Validate a Footprint or a plain dict; every problem is an :class:`InvalidInputError`."""
        return validate_input(cls, data, "footprint")

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> Footprint:
        """Read a footprint from a JSON file; every problem is an :class:`InvalidInputError`."""
        return load_input(cls, path, "footprint")

    # -- queries -------------------------------------------------------------------------------

    @property
    def area(self) -> float:
        """Outline area minus the holes, in m²."""
        return ring_area(self.polygon) - sum(ring_area(h) for h in self.holes)

    @property
    def free_area(self) -> float:
        """Area left for rooms: :attr:`area` minus the cores (assumed inside and disjoint)."""
        return self.area - sum(c.area for c in self.cores)

    def core(self, id: str) -> Core:
        """The core with this id; ``KeyError`` if there is none."""
        for core in self.cores:
            if core.id == id:
                return core
        raise KeyError(f"no core {id!r} in the footprint")
