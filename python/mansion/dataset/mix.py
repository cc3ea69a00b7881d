"""The dataset's mix: which building each index of a dataset is.

The paper's MansionWorld mixes residential (50 %), office (30 %) and public (20 %) buildings of
2–10 floors. A *category* of the mix maps onto the building types the offline planner knows
(:data:`CATEGORIES`); building ``i`` of a dataset with seed ``S`` gets its category, type and
floor count from ``(S, i)`` alone, never from the dataset's size or the order buildings finish
in, so the same command gives the same dataset whatever the worker count or engine, and a larger
``--n`` extends a dataset without changing the buildings it already has.

Categories are drawn with a golden-ratio sequence (``frac(offset + i·φ)``) rather than
independently: every prefix of the dataset then follows the mix within about ``log n / n``
(1,000 buildings land within a few buildings of 500 / 300 / 200), which independent draws would
miss by ±15.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass

from mansion.building.steps import derived_seed
from mansion.exceptions import InvalidInputError
from mansion.planning.program import MAX_FLOORS, typology

__all__ = [
    "CATEGORIES",
    "TALL_TYPES",
    "BuildingSpec",
    "building_spec",
    "describe",
    "floor_range",
    "parse_floors",
    "parse_mix",
]

#: The building types of each category of the mix (every type the offline planner knows).
CATEGORIES: dict[str, tuple[str, ...]] = {
    "residential": ("apartment_block", "townhouse", "villa", "family_apartment", "studio"),
    "office": ("office",),
    "public": (
        "hospital", "school", "kindergarten", "supermarket", "library", "restaurant", "hotel",
        "shopping_mall",
    ),
}

#: Types whose programs stack to any height (corridor floors repeated, cores added with height):
#: they take every floor count up to the planner's maximum, beyond their usual range.
TALL_TYPES = frozenset({"apartment_block", "office", "hotel", "hospital"})

_PHI = (math.sqrt(5.0) - 1.0) / 2.0

_WORDS = ("one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten")


@dataclass(frozen=True)
class BuildingSpec:
    """What building ``index`` of a dataset is; everything its job needs besides the settings."""

    index: int
    id: str
    seed: int
    category: str
    building_type: str
    floors: int
    description: str


def parse_mix(text: str) -> dict[str, float]:
    """``"residential=0.5,office=0.3,public=0.2"`` → shares summing to 1 (given shares are
    normalised; a category left out gets none)."""
    shares: dict[str, float] = {}
    for part in text.split(","):
        if not part.strip():
            continue
        name, sep, value = part.partition("=")
        name = name.strip().lower()
        if not sep:
            raise InvalidInputError(f"mix entry {part.strip()!r} is not NAME=SHARE (e.g. office=0.3)")
        if name not in CATEGORIES:
            raise InvalidInputError(f"unknown mix category {name!r}; choose from {', '.join(CATEGORIES)}")
        if name in shares:
            raise InvalidInputError(f"mix category {name!r} is given twice")
        try:
            share = float(value)
        except ValueError:
            raise InvalidInputError(f"mix share of {name!r} is not a number: {value.strip()!r}") from None
        if not math.isfinite(share) or share < 0:
            raise InvalidInputError(f"mix share of {name!r} must be a number >= 0, got {value.strip()!r}")
        shares[name] = share
    total = sum(shares.values())
    if total <= 0:
        raise InvalidInputError(f"the mix {text!r} has no positive share")
    # keep the categories' canonical order, so equal mixes written differently are equal
    return {c: shares[c] / total for c in CATEGORIES if shares.get(c, 0.0) > 0}


def parse_floors(text: str) -> tuple[int, int]:
    """``"2-10"`` → (2, 10); ``"4"`` → (4, 4)."""
    lo, sep, hi = text.partition("-")
    try:
        low, high = int(lo), int(hi) if sep else int(lo)
    except ValueError:
        raise InvalidInputError(f"floors must be N or LOW-HIGH (e.g. 2-10), got {text!r}") from None
    if not 1 <= low <= high <= MAX_FLOORS:
        raise InvalidInputError(f"floors must lie within 1-{MAX_FLOORS} with LOW <= HIGH, got {text!r}")
    return low, high


def floor_range(building_type: str) -> tuple[int, int]:
    """The floor counts a dataset gives ``building_type``: its usual range, up to the planner's
    maximum for :data:`TALL_TYPES`."""
    low, high = typology(building_type).floors
    return low, MAX_FLOORS if building_type in TALL_TYPES else high


def describe(building_type: str, floors: int) -> str:
    """The request the planner reads: ``"a seven-storey apartment block"``."""
    noun = building_type.replace("_", " ")
    return f"a {_WORDS[floors - 1]}-storey {noun}"


def _category(mix: dict[str, float], u: float) -> str:
    edge = 0.0
    for name, share in mix.items():
        edge += share
        if u < edge:
            return name
    return next(reversed(mix))  # u within rounding of 1


def building_spec(seed: int, index: int, mix: dict[str, float], floors: tuple[int, int]) -> BuildingSpec:
    """Building ``index`` of the dataset with seed ``seed``: seed ``seed + index``, its category
    from the mix, a floor count drawn uniformly from ``floors``, and a type of the category that
    usually has that many floors (any type of the category when none does)."""
    offset = random.Random(derived_seed(seed, "dataset", "mix")).random()
    category = _category(mix, (offset + index * _PHI) % 1.0)
    rng = random.Random(derived_seed(seed, "dataset", index))
    count = rng.randint(*floors)
    fitting = [t for t in CATEGORIES[category] if floor_range(t)[0] <= count <= floor_range(t)[1]]
    building_type = rng.choice(fitting or list(CATEGORIES[category]))
    return BuildingSpec(
        index=index, id=f"{index:05d}", seed=seed + index, category=category,
        building_type=building_type, floors=count, description=describe(building_type, count),
    )
