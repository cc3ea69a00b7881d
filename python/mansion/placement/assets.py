"""AI2-THOR's asset database, read from the ``procthor`` package (``procthor/databases/``).

Nothing is copied into this repository: the JSON files are read where pip installed them, through
:mod:`importlib.resources` (which imports only ``procthor/__init__.py``, a version string). Used:
``asset-database.json`` (assets per object type with bounding boxes), ``receptacles.json`` (which
small object types AI2-THOR scenes put on which receptacles, with frequencies) and
``placement-annotations.json`` (``onFloor``, ``isKinematic``).
"""

from __future__ import annotations

import json
import random
from dataclasses import dataclass
from functools import cache
from importlib import resources
from typing import Any

from mansion.exceptions import InvalidInputError

__all__ = ["Asset", "AssetDatabase", "FRONT_TYPES", "TABLES", "TUCKABLE", "database"]

#: Types used from one side: the agent must reach their front (doors, drawers, shelves, screens).
FRONT_TYPES = frozenset({
    "ClothesDryer", "CounterTop", "Desk", "Dresser", "Fridge", "Safe", "ShelvingUnit", "Sofa",
    "TVStand", "Television", "Toilet", "WashingMachine",
})
#: Seats that may be pushed under their table (the collision count exempts them).
TUCKABLE = frozenset({"Chair", "Stool"})
#: What a tuckable seat may be pushed under.
TABLES = frozenset({"Desk", "DiningTable", "CoffeeTable", "SideTable", "CounterTop"})


@dataclass(frozen=True)
class Asset:
    asset_id: str
    object_type: str
    width: float
    depth: float
    height: float


def _load(name: str) -> Any:
    try:
        path = resources.files("procthor") / "databases" / name
        return json.loads(path.read_text())
    except (ModuleNotFoundError, FileNotFoundError) as exc:  # a broken install
        raise InvalidInputError(
            f"AI2-THOR's {name} is not available ({exc}); install the `procthor` package"
        ) from exc


class AssetDatabase:
    """Assets by object type, receptacle relations and per-type annotations."""

    def __init__(self) -> None:
        raw = _load("asset-database.json")
        self.assets: dict[str, list[Asset]] = {
            t: sorted(
                (
                    Asset(a["assetId"], t, a["boundingBox"]["x"], a["boundingBox"]["z"], a["boundingBox"]["y"])
                    for a in entries
                ),
                key=lambda a: a.asset_id,
            )
            for t, entries in raw.items()
        }
        self.receptacles: dict[str, dict[str, float]] = {
            r: {t: v["p"] for t, v in children.items()} for r, children in _load("receptacles.json").items()
        }
        ann = _load("placement-annotations.json")
        self.on_floor: dict[str, bool] = ann["onFloor"]
        self.kinematic: dict[str, bool] = ann["isKinematic"]
        self.pickupable: dict[str, bool] = ann["isPickupable"]
        self._small: dict[str, tuple[tuple[str, ...], tuple[float, ...]]] = {}
        # the assets of a type that fit a top (long side, short side): every draw asks again
        self._fits: dict[tuple[str, float, float], list[Asset]] = {}

    @property
    def types(self) -> list[str]:
        return sorted(self.assets)

    def floor_types(self) -> list[str]:
        return sorted(t for t, v in self.on_floor.items() if v and t in self.assets)

    def choose(
        self,
        object_type: str,
        rng: random.Random,
        max_width: float | None = None,
        max_depth: float | None = None,
    ) -> Asset:
        """A random asset of the type within the size limits (the smallest one if none is)."""
        pool = self.assets.get(object_type)
        if not pool:
            raise InvalidInputError(f"AI2-THOR has no asset of type {object_type!r}")
        fits = [
            a for a in pool
            if (max_width is None or a.width <= max_width) and (max_depth is None or a.depth <= max_depth)
        ]
        if not fits:
            return min(pool, key=lambda a: a.width * a.depth)
        return rng.choice(fits)

    def small_for(self, receptacle: str, n: int, top: tuple[float, float], rng: random.Random) -> list[Asset]:
        """``n`` small objects AI2-THOR scenes put on this receptacle type, drawn by frequency,
        each small enough for the top (``top`` = width, depth)."""
        if receptacle not in self._small:  # the draw's types and weights, once per receptacle
            weights = {
                t: p for t, p in self.receptacles.get(receptacle, {}).items()
                if t in self.assets and self.pickupable.get(t, False) and not self.on_floor.get(t, False)
            }
            pairs = sorted(weights.items())
            self._small[receptacle] = (tuple(t for t, _ in pairs), tuple(p for _, p in pairs))
        types, probs = self._small[receptacle]
        out: list[Asset] = []
        if not types:
            return out
        for _ in range(n * 3):
            if len(out) == n:
                break
            t = rng.choices(types, probs)[0]
            fit = self._fitting(t, max(top), min(top))
            if fit:
                out.append(rng.choice(fit))
        return out

    def _fitting(self, object_type: str, long: float, short: float) -> list[Asset]:
        key = (object_type, long, short)
        fit = self._fits.get(key)
        if fit is None:
            fit = self._fits[key] = [
                a for a in self.assets[object_type]
                if max(a.width, a.depth) <= long and min(a.width, a.depth) <= short
            ]
        return fit


@cache
def database() -> AssetDatabase:
    return AssetDatabase()
