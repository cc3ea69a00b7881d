"""SearchAssets: AI2-THOR's asset database searched by fuzzy lexical matching (rapidfuzz),
filtered by properties.

Each asset is known by its object type's words and its id's ("wine bottle wine bottle 1"); the
query is matched against them with rapidfuzz's token-set ratio (word order and repeats do not
matter: "bottle of wine" and "WineBottle" find Wine_Bottle_1 first), ties broken by ``WRatio``
(which forgives typos) and then by the asset id. The
properties are AI2-THOR's: ``Pickupable`` (the placement annotations, or ``CanPickup``),
``Receptacle``, ``Openable`` (``CanOpen``), and any other secondary property of the asset
database (``isColdSource``, ``CanBeSliced``...).

Semantic search is optional and off by default: given an *embedder* (texts -> one vector per
text), the assets are ranked by the cosine between the query's vector and each asset's words
("something cold to drink" can then find a wine bottle, which no spelling does).
:func:`sentence_embedder` builds one from a sentence-transformers model (the ``semantic`` extra;
the model is downloaded by that library on first use); any callable of the same shape works.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Sequence
from functools import cache
from typing import Any

import numpy as np
from rapidfuzz import fuzz, process, utils

from mansion.exceptions import InvalidInputError
from mansion.scene.databases import asset_ids
from mansion.sim.world import props

__all__ = ["DEFAULT_EMBEDDING_MODEL", "Embedder", "asset_properties", "search_assets", "sentence_embedder"]

#: Results scoring below this (0-100) are left out.
MIN_SCORE = 50.0

#: Texts -> an array of one vector per text (any dimension): a semantic search's embedding model.
Embedder = Callable[[Sequence[str]], Any]

#: The sentence-transformers model :func:`sentence_embedder` loads unless told otherwise (or
#: ``$MANSION_EMBEDDING_MODEL``): small (80 MB), general English sentences.
DEFAULT_EMBEDDING_MODEL = "sentence-transformers/all-MiniLM-L6-v2"


def sentence_embedder(model: str | None = None) -> Embedder:
    """An embedder from a sentence-transformers model (the ``semantic`` extra): ``model``, else
    ``$MANSION_EMBEDDING_MODEL``, else :data:`DEFAULT_EMBEDDING_MODEL`."""
    try:
        from sentence_transformers import SentenceTransformer  # type: ignore[import-not-found]  # the semantic extra
    except ImportError:
        raise InvalidInputError("semantic asset search needs sentence-transformers: pip install 'mansion[semantic]'") from None
    name = model or os.environ.get("MANSION_EMBEDDING_MODEL") or DEFAULT_EMBEDDING_MODEL
    try:
        st = SentenceTransformer(name)
    except Exception as exc:  # the library raises OSError, ValueError, HTTP errors...: say which model
        raise InvalidInputError(f"cannot load the embedding model {name!r}: {exc}") from None
    return lambda texts: st.encode(list(texts), normalize_embeddings=True)


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


def _unit_rows(vectors: Any, n: int) -> np.ndarray:
    a = np.asarray(vectors, dtype=np.float64)
    if a.ndim != 2 or a.shape[0] != n:
        raise InvalidInputError(f"the embedder gave an array of shape {a.shape} for {n} texts (want one row per text)")
    norms = np.linalg.norm(a, axis=1, keepdims=True)
    return a / np.where(norms > 0, norms, 1.0)


#: the catalogue's vectors per embedder (embedding 1,653 texts once per process, not per query)
_VECTORS: dict[int, tuple[Embedder, np.ndarray]] = {}


def _catalogue_vectors(embedder: Embedder) -> np.ndarray:
    hit = _VECTORS.get(id(embedder))
    if hit is None or hit[0] is not embedder:
        texts = _catalogue()[1]
        hit = (embedder, _unit_rows(embedder(texts), len(texts)))
        _VECTORS[id(embedder)] = hit
    return hit[1]


def search_assets(query: str, top_k: int = 5, properties: list[str] | None = None,
                  embedder: Embedder | None = None) -> list[dict[str, Any]]:
    """The ``top_k`` assets best matching ``query`` that have every one of ``properties``; best
    first (ties in the asset id's natural order). With ``embedder``, ranked by meaning (cosine of
    the embeddings, as a score of 0-100) instead of spelling."""
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
    if embedder is not None:
        cos = _catalogue_vectors(embedder)[keep] @ _unit_rows(embedder([_words(query)]), 1)[0]
        # the spelling score only breaks ties between equally close meanings
        found = sorted(((100.0 * float(c), float(s), keep[j]) for j, (c, s) in enumerate(zip(cos, sets))),
                       key=lambda m: (-round(m[0], 6), -round(m[1], 6), m[2]))
    else:
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
