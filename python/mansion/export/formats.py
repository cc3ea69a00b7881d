"""Export formats by name: ``mansion export --format NAME`` looks its writer up here."""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from mansion.exceptions import InvalidInputError
from mansion.export.model import BuildingModel

__all__ = ["FORMATS", "ExportFormat", "export_format", "register"]


@dataclass(frozen=True)
class ExportFormat:
    name: str
    suffixes: tuple[str, ...]
    write: Callable[[BuildingModel, str | os.PathLike[str]], Path] | None
    description: str
    #: a format written from the building folder itself (house JSONs, not the 3D model) into a
    #: folder (``suffixes`` empty): ``folder(building, out)``
    folder: Callable[[str | os.PathLike[str], str | os.PathLike[str]], Path] | None = None


FORMATS: dict[str, ExportFormat] = {}


def register(fmt: ExportFormat) -> ExportFormat:
    FORMATS[fmt.name] = fmt
    return fmt


def _gltf(model: BuildingModel, path: str | os.PathLike[str]) -> Path:
    from mansion.export.gltf import write_gltf

    return write_gltf(model, path)


def _usd(model: BuildingModel, path: str | os.PathLike[str]) -> Path:
    from mansion.export.usd import write_usd

    return write_usd(model, path)


def _mansionworld(building: str | os.PathLike[str], out: str | os.PathLike[str]) -> Path:
    from mansion.export.mansionworld import write_mansionworld

    return write_mansionworld(building, out)


register(ExportFormat("gltf", (".glb",), _gltf, "binary glTF 2.0 (Blender, three.js, any glTF viewer)"))
register(ExportFormat("usd", (".usd", ".usda", ".usdc"), _usd, "OpenUSD with physics colliders (NVIDIA Isaac Sim)"))
register(ExportFormat("mansionworld", (), None, "a folder in the MANSION authors' layout (their MansionGym, MansionWorld)",
                      folder=_mansionworld))


def export_format(name: str, out: str | os.PathLike[str]) -> ExportFormat:
    """The format called ``name``, checked against the file name it is to write."""
    fmt = FORMATS.get(name)
    if fmt is None:
        raise InvalidInputError(f"unknown export format {name!r}; known: {', '.join(sorted(FORMATS))}")
    suffix = Path(out).suffix.lower()
    if fmt.folder is not None:
        if suffix == ".json" or Path(out).is_file():
            raise InvalidInputError(f"--format {name} writes a folder, not the file {str(out)!r}")
        return fmt
    if suffix not in fmt.suffixes:
        raise InvalidInputError(f"--format {name} writes {' or '.join(fmt.suffixes)} files, not {str(out)!r}")
    return fmt
