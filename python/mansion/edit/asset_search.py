"""SearchAssets: AI2-THOR's asset database searched by fuzzy lexical matching (rapidfuzz),
filtered by properties.

Each asset is known by its object type's words and its id's ("wine bottle wine bottle 1"); the
query is matched against them with rapidfuzz's token-set ratio (word order and repeats do not
matter: "bottle of wine" and "WineBottle" find Wine_Bottle_1 first), ties broken by ``WRatio``
(which forgives typos) and then by the asset id. The
properties are AI2-THOR's: ``Pickupable`` (the placement annotations, or ``CanPickup``),
``Receptacle``, ``Openable`` (``CanOpen``), and any other secondary property of the asset
database (``isColdSource``, ``CanBeSliced``...).
"""

from __future__ import annotations

import re
from functools import cache
from typing import Any

from rapidfuzz import fuzz, process, utils

from mansion.exceptions import InvalidInputError
from mansion.scene.databases import asset_ids
from mansion.sim.world import props

__all__ = ["asset_properties", "search_assets"]

#: Results scoring below this (0-100) are left out.
MIN_SCORE = 50.0


def _words(name: str) -> str:
    return re.sub(r"(?<=[a-z])(?=[A-Z])|_", " ", name).lower()


def asset_properties(asset_id: str) -> list[str]:
    """The asset's properties in AI2-THOR's words (``Pickupable``, ``Receptacle``, ``Openable``
    and its other secondary properties)."""
    rec = asset_ids()[asset_id]
    p = props(asset_id)
    out = [name for name, has in (("Pickupable", p.pickupable), ("Receptacle", p.receptacle),
                                  ("Openable", p.openable)) if has]
    out += [s for s in rec.get("secondaryProperties", []) if s not in ("Receptacle", "CanOpen", "CanPickup")]
    return out


@cache
def _catalogue() -> tuple[list[str], list[str]]:
    ids = sorted(asset_ids(), key=_natural)
    return ids, [f"{_words(asset_ids()[a]['objectType'])} {_words(a)}" for a in ids]


def _natural(s: str) -> tuple[Any, ...]:
    return tuple(int(t) if t.isdigit() else t.lower() for t in re.split(r"(\d+)", s))


def _has(asset_id: str, wanted: str) -> bool:
    key = wanted.lower()
    aliases = {"canopen": "openable", "canpickup": "pickupable"}
    key = aliases.get(key, key)
    return key in {p.lower() for p in asset_properties(asset_id)}


def search_assets(query: str, top_k: int = 5, properties: list[str] | None = None) -> list[dict[str, Any]]:
    """The ``top_k`` assets best matching ``query`` that have every one of ``properties``; best
    first (ties in the asset id's natural order)."""
    if not query or not query.strip():
        raise InvalidInputError("SearchAssets needs a query (an object type or words such as 'apple')")
    if top_k < 1:
        raise InvalidInputError(f"top_k must be at least 1, not {top_k}")
    ids, texts = _catalogue()
    keep = [i for i, a in enumerate(ids) if all(_has(a, w) for w in properties or [])]
    if not keep:
        raise InvalidInputError(f"no AI2-THOR asset has all of the properties {properties}")
    q = utils.default_process(_words(query))
    choices = [utils.default_process(texts[i]) for i in keep]
    sets = process.cdist([q], choices, scorer=fuzz.token_set_ratio)[0]
    whole = process.cdist([q], choices, scorer=fuzz.WRatio)[0]
    found = sorted(((float(s), float(w), keep[j]) for j, (s, w) in enumerate(zip(sets, whole))
                    if max(s, w) >= MIN_SCORE), key=lambda m: (-round(m[0], 6), -round(m[1], 6), m[2]))
    out = []
    for score, _, i in found[:top_k]:
        a = ids[i]
        p = props(a)
        out.append({"asset_id": a, "object_type": p.object_type, "score": round(score, 1),
                    "size": [round(p.width, 3), round(p.height, 3), round(p.depth, 3)],
                    "properties": asset_properties(a)})
    return out
