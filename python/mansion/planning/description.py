"""Reading a plain-language request: building type, floors, area, cores and room specifics.

This is the offline half of the paper's ``ResolveNumericConstraints`` plus the facts the offline
planner needs from the text. It understands ordinary phrasings ("a four-storey hospital",
"4-story", "two elevators", "three classrooms per floor", "a gym on the top floor", "450 m² per
floor") and leaves everything it cannot read to the planner's defaults, so an unusual sentence
still yields a building. An LLM planner reads the same text itself and may ignore this module.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from mansion.planning.vocabulary import BUILDING_KEYWORDS, ROOM_SYNONYMS

__all__ = ["Placement", "Request", "parse_description", "parse_count"]

_NUMBER_WORDS = {
    "a": 1, "an": 1, "one": 1, "single": 1, "two": 2, "double": 2, "three": 3, "triple": 3,
    "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8, "nine": 9, "ten": 10, "eleven": 11,
    "twelve": 12, "fifteen": 15, "twenty": 20,
}
_ORDINALS = {
    "first": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5, "sixth": 6, "seventh": 7,
    "eighth": 8, "ninth": 9, "tenth": 10,
}
_NUM = r"(\d+|" + "|".join(sorted(_NUMBER_WORDS, key=len, reverse=True)) + r")"
_STOREYS = r"(?:storey|story|stories|storeys|floor|floors|level|levels)"


def parse_count(word: str) -> int | None:
    """``"three"`` → 3, ``"12"`` → 12; None for anything else."""
    w = word.lower()
    if w.isdigit():
        return int(w)
    return _NUMBER_WORDS.get(w)


@dataclass(frozen=True)
class Placement:
    """A room the description asks for: ``count`` of ``room_type`` on ``floor``.

    ``floor`` is a 0-based index, ``-1`` for the top floor, or None for "every floor"
    (``per_floor``) or "somewhere" (not per floor).
    """

    room_type: str
    count: int
    floor: int | None
    per_floor: bool = False


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


def _room_type(phrase: str) -> str | None:
    phrase = phrase.strip()
    for room_type, words in ROOM_SYNONYMS:
        for w in words:
            if re.search(r"\b" + w + r"s?$", phrase):
                return room_type
    return None


def _floor_ref(ref: str) -> int | None:
    ref = ref.strip()
    if ref in ("top", "upper most", "uppermost", "highest", "last"):
        return -1
    if ref in ("ground", "bottom", "entrance", "street"):
        return 0
    if ref in _ORDINALS:
        return _ORDINALS[ref] - 1
    m = re.fullmatch(r"(\d+)(?:st|nd|rd|th)?", ref)
    if m:
        return int(m.group(1)) - 1
    return None


# A room phrase never contains a count word, so the count next to the room is the one read
# ("two elevators and a pharmacy on the ground floor": one pharmacy, not two).
_ROOM_PHRASE = (
    r"((?:(?!\b(?:" + "|".join(sorted(_NUMBER_WORDS, key=len, reverse=True)) + r"|\d+)\b)[a-z' -])+?)"
)


def _placements(text: str) -> list[Placement]:
    out: list[Placement] = []
    taken: list[tuple[int, int]] = []
    floor_ref = r"(top|ground|bottom|uppermost|highest|last|" + "|".join(_ORDINALS) + r"|\d+(?:st|nd|rd|th)?)"
    patterns = [
        # "a gym on the top floor", "two wards on the 3rd floor"
        (_NUM + r" " + _ROOM_PHRASE + r" on (?:the )?" + floor_ref + r" (?:floor|storey|story|level)", False),
        # "a gym on floor 3"
        (_NUM + r" " + _ROOM_PHRASE + r" on (?:floor|level) (\d+)", False),
        # "three classrooms per floor", "a pantry on every floor", "toilets on each floor"
        (_NUM + r" " + _ROOM_PHRASE + r" (?:per|on (?:each|every|all)) (?:floor|storey|story|level)s?", True),
    ]
    for pattern, per_floor in patterns:
        for m in re.finditer(r"\b" + pattern, text):
            if any(a < m.end() and m.start() < b for a, b in taken):
                continue
            count = parse_count(m.group(1))
            phrase = m.group(2)
            # Keep only the last words of a long phrase: "with a big gym" -> "big gym".
            words = phrase.split()
            room_type = None
            for k in range(min(3, len(words)), 0, -1):
                room_type = _room_type(" ".join(words[-k:]))
                if room_type:
                    break
            if room_type is None:
                # An unknown room is still honoured under its own name.
                room_type = re.sub(r"[^a-z0-9]+", "_", " ".join(words[-2:])).strip("_")
                room_type = re.sub(r"(?<!s)s$", "", room_type)
            if count is None or not room_type:
                continue
            floor = None if per_floor else _floor_ref(m.group(3))
            if not per_floor and floor is None:
                continue
            out.append(Placement(room_type, count, floor, per_floor))
            taken.append((m.start(), m.end()))
    return out


def parse_description(text: str) -> Request:
    """Read what ``text`` states about the building; see :class:`Request`."""
    low = " ".join(text.lower().replace("-", " - ").split()).replace(" - ", "-")
    area_per_floor, total = _area(low)
    return Request(
        text=text,
        building_type=_building_type(low),
        floors=_floors(low),
        area_per_floor=area_per_floor,
        total_area=total,
        elevators=_counts(low, r"(?:elevators?|lifts?)\b"),
        stairs=_counts(low, r"(?:stairs?|stairwells?|staircases?|stair cores?)\b"),
        placements=_placements(low),
    )
