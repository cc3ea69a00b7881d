"""Room cards' material descriptions → names from AI2-THOR's material database.

A room card says what its floor and walls look like in words ("white-oiled oak planks",
"glazed ceramic tile, white"), drawn from the building's palette. The simulator wants one of its
own material names ("WhiteWood", "bathroomTilesGrey"). We read each material name as words
(``WoodFloorsCrossRED`` → wood, floors, cross, red), translate the description into the same
vocabulary (oak → wood + light, terrazzo → marble + tiles, ...) and take the best overlap: the
kind of surface counts most, then colour. Ties go to a stable hash of the description, so the
same card always gets the same material and different cards with equal scores spread out.
"""

from __future__ import annotations

import hashlib
import re
from dataclasses import dataclass
from functools import cache

from mansion.scene.databases import material_database

__all__ = ["MaterialMatch", "floor_material", "wall_material"]

#: Description word → words that occur in material names (surface kinds).
_KIND: dict[str, tuple[str, ...]] = {
    "oak": ("wood", "light"), "birch": ("wood", "white"), "maple": ("wood", "light"),
    "pine": ("wood", "planks"), "walnut": ("wood", "dark"), "teak": ("wood", "orange"),
    "cherry": ("wood", "red"), "timber": ("wood",), "wood": ("wood",), "wooden": ("wood",),
    "hardwood": ("wood",), "parquet": ("wood", "floors"), "herringbone": ("wood", "cross"),
    "plank": ("wood", "planks"), "planks": ("wood", "planks"), "laminate": ("wood", "smooth"),
    "bamboo": ("wood", "tan"), "cork": ("wood", "tan"), "reclaimed": ("wood", "worn"),
    "concrete": ("concrete",), "screed": ("concrete",), "cement": ("concrete",),
    "terrazzo": ("marble", "tiles"), "marble": ("marble",), "granite": ("granite",),
    "limestone": ("marble", "cream"), "stone": ("granite", "marble"), "slate": ("tiles", "dark"),
    "travertine": ("marble", "cream"),
    "tile": ("tiles",), "tiles": ("tiles",), "tiled": ("tiles",), "ceramic": ("ceramic", "tiles"),
    "porcelain": ("porcelain", "tiles"), "mosaic": ("tiles", "small"), "zellige": ("tiles",),
    "subway": ("subway", "tiles"), "terracotta": ("tiles", "orange"), "quarry": ("tiles", "red"),
    "vinyl": ("floor", "grey"), "linoleum": ("floor",), "rubber": ("floor", "grey"),
    "epoxy": ("concrete", "smooth"), "resin": ("concrete", "smooth"),
    "carpet": ("carpet",), "carpeted": ("carpet",), "rug": ("carpet",), "hotel": ("hotel",),
    "plaster": ("drywall", "plaster"), "drywall": ("drywall",), "paint": ("drywall",),
    "painted": ("drywall",), "render": ("plaster",), "blockwork": ("concrete", "boards"),
    "brick": ("brick", "bricks"), "bricks": ("brick", "bricks"), "panelling": ("panel",),
    "panels": ("panel",), "cladding": ("panel", "pvc"), "hygienic": ("pvc",),
    "wallpaper": ("drywall", "tiled"), "kitchen": ("kitchen",), "bathroom": ("bathroom",),
    "splashback": ("tiles",), "glazed": ("tiles",), "slat": ("wood",),
}

#: Colour words (and their name spellings).
_COLOUR: dict[str, tuple[str, ...]] = {
    "white": ("white", "pure"), "off-white": ("eggshell", "white"), "ivory": ("eggshell", "cream"),
    "cream": ("cream", "creame", "eggshell", "beige"), "beige": ("beige", "tan", "sand"),
    "sand": ("sand", "tan", "beige"), "tan": ("tan",), "grey": ("grey", "gray"),
    "gray": ("grey", "gray"), "charcoal": ("dark", "grey", "black"), "graphite": ("dark", "grey"),
    "black": ("black", "dark"), "dark": ("dark",), "light": ("light", "white"),
    "pale": ("pale", "light", "white"), "red": ("red",), "brick": ("red",), "pink": ("pink", "rose"),
    "rose": ("rose", "pink"), "orange": ("orange",), "yellow": ("yellow",),
    "green": ("green",), "sage": ("green",), "moss": ("green",), "olive": ("green",),
    "blue": ("blue",), "navy": ("blue", "dark"), "turquoise": ("turquoise", "blue"),
    "brown": ("brown",), "warm": ("orange", "tan", "cream"), "natural": ("tan", "wood"),
    "honed": ("smooth",), "polished": ("smooth", "glossy"), "smooth": ("smooth",),
    "matte": ("dull",), "speckled": ("granite",),
}

#: Materials in the "Wall" category that are object finishes, not room surfaces.
_NOT_SURFACES = re.compile(r"Pot$|Shard|Countertop|Counters|Cabinet|Porcelain_(Red|Yellow|Turquoise)")


@dataclass(frozen=True)
class MaterialMatch:
    name: str
    score: float


def _words(name: str) -> frozenset[str]:
    spaced = re.sub(r"([a-z])([A-Z])", r"\1 \2", name)
    spaced = re.sub(r"([A-Z]+)([A-Z][a-z])", r"\1 \2", spaced)
    return frozenset(w.lower() for w in re.split(r"[^A-Za-z]+", spaced) if w)


@cache
def _candidates(surface: str) -> tuple[tuple[str, frozenset[str]], ...]:
    db = material_database()
    if surface == "floor":
        names = list(db["Wood"]) + [
            m for m in db["Wall"]
            if re.search(r"Tile|Floor|Concrete|Marble|Granite|Porcelain", m, re.I)
        ] + [m for m in db["Fabric"] if re.search(r"Carpet", m, re.I)]
        names = [m for m in names if not re.search(r"Cabinet|Counter|Wicker|RobinEgg", m)]
    else:
        names = list(db["Wall"])
    return tuple((m, _words(m)) for m in sorted(set(names)) if not _NOT_SURFACES.search(m))


def _stable(text: str) -> float:
    return int.from_bytes(hashlib.blake2b(text.encode(), digest_size=4).digest(), "little") / 2**32


def _match(description: str, surface: str, default: str) -> MaterialMatch:
    tokens = [t for t in re.split(r"[^a-z\-]+", description.lower()) if t]
    kinds = {w for t in tokens for w in _KIND.get(t, ())}
    colours = {w for t in tokens for w in _COLOUR.get(t, ())}
    best: tuple[float, float, str] | None = None
    for name, words in _candidates(surface):
        score = 3.0 * len(kinds & words) + 1.0 * len(colours & words)
        key = (score, _stable(f"{description}|{name}"), name)
        if best is None or key > best:
            best = key
    if best is None or best[0] == 0.0:
        return MaterialMatch(default, 0.0)
    return MaterialMatch(best[2], best[0])


@cache
def floor_material(description: str) -> MaterialMatch:
    """The floor material best matching ``description`` (a room card's floor text)."""
    return _match(description, "floor", "WoodFloorsCross")


@cache
def wall_material(description: str) -> MaterialMatch:
    """The wall material best matching ``description`` (a room card's wall text)."""
    return _match(description, "wall", "WallDrywallWhite")
