"""The chief designer: one material palette per building, and a room card per room.

The paper picks the building's visual style once, before any floor is planned, so that every
floor matches; each room's card then draws its floor and wall materials from that palette by the
room's role (wet rooms get tiles whatever the style). Palettes are grouped by the building family
they suit; the seed picks one.
"""

from __future__ import annotations

import random

from mansion.models.building import Palette
from mansion.planning.vocabulary import room_kind

__all__ = ["PALETTES", "choose_palette", "room_materials"]

_ROLES = (
    "circulation", "living", "kitchen", "bedroom", "wet", "service", "work", "public",
    "clinical", "learning", "sport", "retail",
)


def _palette(name: str, style: str, colours: str, **materials: tuple[str, str]) -> Palette:
    base = {
        "circulation": ("polished concrete, light grey", "painted plaster, white"),
        "living": ("oak parquet, matte", "painted plaster, warm white"),
        "kitchen": ("porcelain tile, light grey", "ceramic tile splashback, white"),
        "bedroom": ("oak parquet, matte", "painted plaster, soft beige"),
        "wet": ("non-slip ceramic tile, grey", "glazed ceramic tile, white"),
        "service": ("sealed concrete", "painted blockwork, light grey"),
        "work": ("carpet tiles, charcoal", "painted drywall, white"),
        "public": ("terrazzo, speckled grey", "painted plaster, white"),
        "clinical": ("sheet vinyl, pale blue, coved", "hygienic wall cladding, white"),
        "learning": ("linoleum, sage green", "painted drywall, pale yellow"),
        "sport": ("sprung hardwood, maple", "painted blockwork, white"),
        "retail": ("large-format porcelain tile, white", "painted drywall, white"),
    }
    base.update(materials)
    assert set(base) == set(_ROLES)
    return Palette(name=name, style=style, colour_scheme=colours, materials=base)


#: Palettes by building family.
PALETTES: dict[str, tuple[Palette, ...]] = {
    "residential": (
        _palette(
            "scandinavian", "Scandinavian: pale timber, white walls, soft textiles",
            "white, birch, pale grey, muted green",
            living=("white-oiled oak planks", "painted plaster, white"),
            bedroom=("white-oiled oak planks", "painted plaster, pale grey"),
            circulation=("white-oiled oak planks", "painted plaster, white"),
        ),
        _palette(
            "warm_modern", "Warm modern: walnut, stone and warm neutrals",
            "walnut, sand, cream, bronze",
            living=("walnut herringbone parquet", "lime plaster, sand"),
            bedroom=("walnut planks, matte", "painted plaster, cream"),
            circulation=("limestone tile, honed", "lime plaster, sand"),
            kitchen=("limestone tile, honed", "cream zellige tile"),
        ),
        _palette(
            "industrial_loft", "Industrial loft: concrete, brick and black steel",
            "grey, brick red, black",
            living=("polished concrete, dark grey", "exposed brick, red"),
            bedroom=("reclaimed pine planks", "painted brick, white"),
            circulation=("polished concrete, dark grey", "exposed brick, red"),
        ),
    ),
    "work": (
        _palette(
            "corporate_neutral", "Corporate neutral: carpet tiles, glass and grey",
            "graphite, white, steel blue",
        ),
        _palette(
            "biophilic", "Biophilic: timber, plants, daylight tones",
            "oak, moss green, off-white",
            work=("cork tiles, natural", "timber slat panelling, oak"),
            circulation=("oak planks, brushed", "painted plaster, off-white"),
            public=("oak planks, brushed", "living green wall panels"),
        ),
        _palette(
            "tech_loft", "Tech loft: exposed concrete, bright accent colours",
            "concrete grey, signal orange, white",
            work=("polished concrete, sealed", "painted blockwork, white with orange accents"),
            circulation=("polished concrete, sealed", "exposed concrete, board-formed"),
        ),
    ),
    "public": (
        _palette(
            "civic_bright", "Civic bright: durable light surfaces, clear colour coding",
            "white, sky blue, sunflower yellow",
        ),
        _palette(
            "calm_natural", "Calm natural: linoleum, timber trims, soft greens",
            "sage, birch, cream",
            circulation=("linoleum, warm grey", "painted plaster, cream with birch trim"),
            public=("linoleum, warm grey", "birch veneer panels"),
        ),
        _palette(
            "contemporary_stone", "Contemporary stone: terrazzo and white oak",
            "terrazzo grey, white oak, charcoal",
            circulation=("terrazzo, large aggregate, grey", "painted plaster, white"),
            retail=("terrazzo, large aggregate, grey", "white oak panelling"),
            public=("terrazzo, large aggregate, grey", "white oak panelling"),
        ),
    ),
}


def choose_palette(family: str, rng: random.Random) -> Palette:
    """The chief designer's one choice for the building."""
    return rng.choice(PALETTES[family])


def room_materials(palette: Palette, room_type: str) -> tuple[str, str]:
    """(floor, wall) materials of a room of ``room_type`` under ``palette``."""
    return palette.materials[room_kind(room_type).role]
