"""Reading a plain-language request: building type, floors, area, cores and room specifics.

This is the offline half of the paper's ``ResolveNumericConstraints`` plus the facts the offline
planner needs from the text. It understands ordinary phrasings ("a four-storey hospital",
"4-story", "two elevators", "three classrooms per floor", "a gym on the top floor", "450 m² per
floor") and leaves everything it cannot read to the planner's defaults, so an unusual sentence
still yields a building. The rooms it asks for, their counts and floors are read by
:mod:`mansion.planning.room_requests`. An LLM planner reads the same text itself and may ignore
this module.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from mansion.planning.room_requests import NUMBER_WORDS as _NUMBER_WORDS
from mansion.planning.room_requests import Placement, family, parse_count, read_rooms
from mansion.planning.vocabulary import BUILDING_KEYWORDS

__all__ = ["Placement", "Request", "parse_description", "parse_count"]

_NUM = r"(\d+|" + "|".join(sorted(_NUMBER_WORDS, key=len, reverse=True)) + r")"
_STOREYS = r"(?:storey|story|stories|storeys|floor|floors|level|levels)"


@dataclass
class Request:
    """What the description says, each field None when it does not say."""

    text: str
    building_type: str | None = None
    floors: int | None = None
    area_per_floor: float | None = None
    total_area: float | None = None
    elevators: int | None = None
    stairs: int | None = None
    placements: list[Placement] = field(default_factory=list)
    #: Phrases after "with"/"and" that name no room the planner knows (reported, never dropped).
    unknown: list[str] = field(default_factory=list)
    #: How ordinal floors were read: ``american`` (the first floor is the ground floor, the
    #: default) or ``british`` (the description also names a ground floor, or says "above ground").
    numbering: str = "american"


def _building_type(text: str) -> str | None:
    # Earliest mention wins ("an office above a supermarket" is an office); among keywords at the
    # same place the longer one wins ("apartment block" over "apartment").
    best: tuple[int, int, str] | None = None
    for key, words in BUILDING_KEYWORDS:
        for w in words:
            m = re.search(r"\b" + w + r"\b", text)
            if m and (best is None or (m.start(), -len(w)) < (best[0], best[1])):
                best = (m.start(), -len(w), key)
    return None if best is None else best[2]


def _floors(text: str) -> int | None:
    m = re.search(_NUM + r"[- ]?" + _STOREYS + r"\b", text)
    if m and not re.match(r"\s*(?:of|per)\b", text[m.end():]):
        n = parse_count(m.group(1))
        # "a floor" / "one floor plan" mean one floor only when said with storey words.
        if n is not None and not (m.group(1) in ("a", "an") and "storey" not in m.group(0)):
            return n
    if re.search(r"\b(bungalow|single[- ]storey|single[- ]story|one[- ]level)\b", text):
        return 1
    if re.search(r"\bduplex\b", text):
        return 2
    if re.search(r"\btriplex\b", text):
        return 3
    return None


def _area(text: str) -> tuple[float | None, float | None]:
    m = re.search(
        r"(\d+(?:\.\d+)?)\s*(?:m2|m²|sqm|sq\.? ?m|square met(?:re|er)s?)(\s*(?:per|each|a|every) (?:floor|storey|story|level))?",
        text,
    )
    if not m:
        return None, None
    value = float(m.group(1))
    return (value, None) if m.group(2) else (None, value)


def _counts(text: str, pattern: str) -> int | None:
    if re.search(r"\b(?:no|without(?: an?)?|zero) " + pattern, text):
        return 0
    m = re.search(r"\b" + _NUM + r" " + pattern, text)
    if m:
        return parse_count(m.group(1))
    if re.search(r"\b(?:with|has|have|and|plus)\b[^.,;]*\b" + pattern, text):
        return 1
    return None


def parse_description(text: str) -> Request:
    """Read what ``text`` states about the building; see :class:`Request`."""
    low = " ".join(text.lower().replace("-", " - ").split()).replace(" - ", "-")
    area_per_floor, total = _area(low)
    building = _building_type(low)
    placements, unknown, numbering = read_rooms(low, family(building))
    return Request(
        text=text,
        building_type=building,
        floors=_floors(low),
        area_per_floor=area_per_floor,
        total_area=total,
        elevators=_counts(low, r"(?:elevators?|lifts?)\b"),
        stairs=_counts(low, r"(?:stairs?|stairwells?|staircases?|stair cores?)\b"),
        placements=placements,
        unknown=unknown,
        numbering=numbering,
    )
