"""Pictures of a building: one PNG per floor and an overview of every floor side by side."""

from __future__ import annotations

import math
import os
from pathlib import Path

from mansion.models.building import Building
from mansion.plot import draw_layout, layout_bounds, plot_layout, save_figure

__all__ = ["floor_title", "plot_building", "plot_floors"]


def floor_title(building: Building, index: int) -> str:
    floor = building.floors[index]
    kind = building.program.building_type.replace("_", " ")
    copy = f", copy of floor {floor.copy_of}" if floor.copy_of is not None else ""
    return f"{kind}, floor {index}{copy} (seed {building.seed})"


def plot_floors(building: Building, folder: str | os.PathLike[str]) -> list[Path]:
    """``floor_<k>.png`` for every floor, in ``folder``."""
    return [
        plot_layout(f.layout, Path(folder) / f"floor_{f.index}.png", title=floor_title(building, f.index))
        for f in building.floors
    ]


def plot_building(building: Building, path: str | os.PathLike[str]) -> Path:
    """Every floor on one sheet, ground floor first, all at the same scale."""
    from matplotlib.figure import Figure

    boxes = [layout_bounds(f.layout) for f in building.floors]
    bounds = (
        min(b[0] for b in boxes), min(b[1] for b in boxes),
        max(b[2] for b in boxes), max(b[3] for b in boxes),
    )
    n = len(building.floors)
    cols = min(n, 3 if n > 4 else n)
    rows = math.ceil(n / cols)
    width, height = bounds[2] - bounds[0], bounds[3] - bounds[1]
    panel = 5.0
    fig = Figure(figsize=(panel * cols, max(2.5, panel * height / max(width, 1e-6)) * rows + 0.6))
    points_per_metre = 72.0 * 0.8 * panel / max(width, height, 1e-6)
    for i, floor in enumerate(building.floors):
        ax = fig.add_subplot(rows, cols, i + 1)
        copy = f" = floor {floor.copy_of}" if floor.copy_of is not None else ""
        draw_layout(ax, floor.layout, points_per_metre, title=f"floor {floor.index}{copy}", bounds=bounds)
    kind = building.program.building_type.replace("_", " ")
    fig.suptitle(f"{kind}: {building.program.floor_count} floors (seed {building.seed})")
    fig.tight_layout()
    return save_figure(fig, path)
