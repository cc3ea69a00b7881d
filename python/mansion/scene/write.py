"""Writing a building's scenes: ``floor_<k>.json`` per floor and ``manifest.json``."""

from __future__ import annotations

import os
from pathlib import Path

from mansion.models.building import Building
from mansion.scene.instantiate import build_scenes, floor_file

__all__ = ["write_scenes"]


def write_scenes(
    building: Building, folder: str | os.PathLike[str], *, objects: bool = True
) -> Path:
    """Write every floor's house JSON (furnished unless ``objects`` is False) and the manifest
    into ``folder``; returns the manifest.

    The manifest is written last, so a folder with a manifest always has all its floors.
    """
    out = Path(folder)
    scenes = build_scenes(building, objects=objects)
    for house, floor in zip(scenes.houses, scenes.manifest.floors, strict=True):
        house.to_json(out / floor_file(floor.index))
    return scenes.manifest.to_json(out / "manifest.json")
