"""The export stage: a generated building as one 3D file for Blender (glTF) or Isaac Sim (USD),
with the stairs and elevators AI2-THOR has no asset for, and a 3D picture of it.

Writing needs the ``export`` extra (``pip install 'mansion[export]'``: trimesh and usd-core).
This module stays light (the command line imports it for the format names); the geometry is
built in :mod:`mansion.export.building`.
"""

from __future__ import annotations

import os
from pathlib import Path

from mansion.exceptions import MansionError
from mansion.export.formats import FORMATS, ExportFormat, export_format, register
from mansion.export.model import BuildingModel, Look, Node

__all__ = [
    "FORMATS",
    "BuildingModel",
    "ExportFormat",
    "Look",
    "Node",
    "building_model",
    "export_building",
    "export_format",
    "register",
]


def building_model(building: str | os.PathLike[str]) -> BuildingModel:
    """The model of a building folder (see :func:`mansion.export.building.building_model`)."""
    from mansion.export.building import building_model as build

    return build(building)


def export_building(building: str | os.PathLike[str], fmt: str, out: str | os.PathLike[str]) -> Path:
    """Write the building folder ``building`` to ``out`` in format ``fmt`` (see :data:`FORMATS`)."""
    writer = export_format(fmt, out)
    if writer.folder is not None:
        return writer.folder(building, out)
    assert writer.write is not None
    model = building_model(building)
    try:
        return writer.write(model, out)
    except ModuleNotFoundError as exc:
        raise MansionError(
            f"--format {fmt} needs the {exc.name!r} package: pip install 'mansion[export]'"
        ) from exc
