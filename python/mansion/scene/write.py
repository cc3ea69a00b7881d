"""Writing a building's scenes: ``floor_<k>.json`` per floor and ``manifest.json``."""

from __future__ import annotations

import os
from pathlib import Path

from mansion.models.building import Building
from mansion.scene.instantiate import BuildingScenes, build_scenes, floor_file

__all__ = ["save_scenes", "write_scenes"]


def write_scenes(
    building: Building, folder: str | os.PathLike[str], *, objects: bool = True
) -> Path:
    """Write every floor's house JSON (furnished unless ``objects`` is False) and the manifest
    into ``folder``; returns the manifest.

    The manifest is written last, so a folder with a manifest always has all its floors.
    """
    return save_scenes(build_scenes(building, objects=objects), folder)


def save_scenes(scenes: BuildingScenes, folder: str | os.PathLike[str]) -> Path:
    """Write scenes already built (:func:`build_scenes`) into ``folder``, the manifest last;
    returns the manifest."""
    out = Path(folder)
    for house, floor in zip(scenes.houses, scenes.manifest.floors, strict=True):
        house.to_json(out / floor_file(floor.index))
    return scenes.manifest.to_json(out / "manifest.json")
