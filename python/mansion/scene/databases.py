"""AI2-THOR's own databases, read from the ``procthor`` package on PyPI (a dependency).

The wheel ships ``procthor/databases/*.json``: the asset database (object types → assets with
bounding boxes), the material database (category → material names the simulator knows), the wall
holes (the hole each door and window asset cuts: size and offset) and the skyboxes. We read the
files directly with :mod:`importlib.resources` instead of importing ``procthor.databases``: that
module imports ``ai2thor`` and ``pandas`` at import time, which we neither need nor install.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from functools import cache
from importlib import resources
from typing import Any

from mansion.exceptions import MansionError

__all__ = [
    "HoleAsset",
    "asset_database",
    "asset_ids",
    "door_assets",
    "hole_asset_position",
    "material_database",
    "material_names",
    "skyboxes",
    "wall_holes",
    "window_assets",
]


@dataclass(frozen=True)
class HoleAsset:
    """A door or window asset and the hole it cuts: ``width`` × ``height`` metres."""

    asset_id: str
    width: float
    height: float


def _load(name: str) -> Any:
    try:
        path = resources.files("procthor") / "databases" / name
        return json.loads(path.read_text(encoding="utf-8"))
    except ModuleNotFoundError as exc:
        raise MansionError(
            "the AI2-THOR databases come from the 'procthor' package: pip install procthor==0.0.1.dev2"
        ) from exc
    except (OSError, ValueError) as exc:
        raise MansionError(f"cannot read procthor/databases/{name}: {exc}") from exc


@cache
def asset_database() -> dict[str, list[dict[str, Any]]]:
    """Object type → list of assets (``assetId``, ``boundingBox``, ...)."""
    return _load("asset-database.json")  # type: ignore[no-any-return]


@cache
def asset_ids() -> dict[str, dict[str, Any]]:
    """Asset id → its asset record, over every object type."""
    return {a["assetId"]: a for assets in asset_database().values() for a in assets}


@cache
def material_database() -> dict[str, list[str]]:
    """Material category ("Wood", "Wall", "Fabric", ...) → material names."""
    return _load("material-database.json")  # type: ignore[no-any-return]


@cache
def material_names() -> frozenset[str]:
    """Every material name the simulator's material database knows."""
    return frozenset(m for names in material_database().values() for m in names)


@cache
def wall_holes() -> dict[str, dict[str, Any]]:
    """Door / window asset id → ``{min, max, offset}`` of the hole it cuts."""
    return _load("wall-holes.json")  # type: ignore[no-any-return]


@cache
def skyboxes() -> tuple[str, ...]:
    """Skybox ids, sorted (so a seed picks the same one whatever the file's order)."""
    return tuple(sorted(_load("skyboxes.json")))


def _hole_assets(prefix: str) -> tuple[HoleAsset, ...]:
    holes = wall_holes()
    out = []
    for asset_id in sorted(holes):
        # Only assets both databases know: the hole from wall-holes, the asset from the asset
        # database, so the simulator can spawn what the hole was cut for.
        if asset_id.startswith(prefix) and asset_id in asset_ids():
            h = holes[asset_id]
            out.append(
                HoleAsset(
                    asset_id,
                    width=h["max"]["x"] - h["min"]["x"],
                    height=h["max"]["y"] - h["min"]["y"],
                )
            )
    return tuple(out)


@cache
def door_assets() -> tuple[HoleAsset, ...]:
    """Doorway assets (single and double leaf), sorted by id."""
    return _hole_assets("Doorway_")


@cache
def window_assets() -> tuple[HoleAsset, ...]:
    """Window assets, sorted by id."""
    return _hole_assets("Window_")


def hole_asset_position(asset_id: str, lo: tuple[float, float]) -> tuple[float, float] | None:
    """ProcTHOR's ``assetPosition`` (x, y) of a door or window asset whose hole starts at ``lo``
    (wall0's frame): the hole's minimum + the asset's offset in the wall-holes database + half
    its bounding box. None for an asset either database lacks."""
    hole = wall_holes().get(asset_id.replace("Doorframe", "Doorway"))
    rec = asset_ids().get(asset_id)
    if hole is None or rec is None:
        return None
    bb, off = rec["boundingBox"], hole["offset"]
    return (lo[0] + off["x"] + bb["x"] / 2, lo[1] + off["y"] + bb["y"] / 2)
