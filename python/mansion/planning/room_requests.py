"""Rooms a description asks for: which, how many, and on which floor.

The description is cut into phrases at "with", "and", commas and the like; each phrase that names
a room (:func:`~mansion.planning.room_names.match_room`) becomes a :class:`Placement` with its
count ("two operating theatres") and floor ("on the ground floor", "upstairs", "on every
floor"). A phrase that only names a floor ("the top floor has a gym") gives its floor to the
rooms after it; rooms listed together ("a pharmacy and a cafe on the ground floor") share the
floor said after the last of them. Spatial phrases ("next to the lobby", "in the north-east
corner") are left to the seed step, except that a room by the entrance or the street is on the
ground floor.

Floor numbering: ordinals count floors from the ground, the American way: the first floor *is*
the ground floor (index 0), the second floor the one above it. When the description also names a
ground floor ("a cafe on the ground floor and offices on the first floor"), or says "above
ground", ordinals count the floors above the ground, the British way: the first floor is index
1. "Floor 0" / "level 0" anywhere makes numbered floors ("floor 2") 0-based.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from mansion.planning.bays import BAY_TYPOLOGIES
from mansion.planning.room_names import match_room, singular
from mansion.planning.typologies import TYPOLOGIES

__all__ = ["NUMBER_WORDS", "ORDINALS", "Placement", "family", "parse_count", "read_rooms"]

NUMBER_WORDS = {
    "a": 1, "an": 1, "one": 1, "single": 1, "two": 2, "double": 2, "three": 3, "triple": 3,
    "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8, "nine": 9, "ten": 10, "eleven": 11,
    "twelve": 12, "fifteen": 15, "twenty": 20,
}
ORDINALS = {
    "first": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5, "sixth": 6, "seventh": 7,
    "eighth": 8, "ninth": 9, "tenth": 10,
}

def parse_count(word: str) -> int | None:
    """``"three"`` → 3, ``"12"`` → 12; None for anything else."""
    w = word.lower()
    if w.isdigit():
        return int(w)
    return NUMBER_WORDS.get(w)



@dataclass(frozen=True)
class Placement:
    """A room the description asks for: ``count`` of ``room_type`` on ``floor``.

    ``floor`` is a 0-based index, ``-1`` for the top floor, or None for every floor
    (``per_floor``, from floor ``from_floor`` up) or anywhere (not per floor). An upper-floor
    request ("upstairs", "on the upper floor") is the top floor with ``from_floor`` 1: it needs
    a floor above the ground. ``name`` is the room as asked ("children's reading room"; empty
    when the request uses the type's own name), ``how`` how it was read
    (:func:`~mansion.planning.room_names.match_room`), ``where`` how the floor was read, and
    ``unsupported`` says why the floor asked for cannot be built (a basement).
    """

    room_type: str
    count: int
    floor: int | None
    per_floor: bool = False
    name: str = ""
    phrase: str = ""
    how: str = ""
    where: str = ""
    from_floor: int = 0
    unsupported: str = ""


def family(building_type: str | None) -> str:
    """The palette family of ``building_type`` (``residential``, ``work``, ``public``; ``""``
    when unknown)."""
    if building_type in TYPOLOGIES:
        return TYPOLOGIES[building_type].family
    if building_type in BAY_TYPOLOGIES:
        return BAY_TYPOLOGIES[building_type][0].family
    return ""


_COUNT = r"(\d+|" + "|".join(sorted(NUMBER_WORDS, key=len, reverse=True)) + r"|several|some|a few|multiple|many|a couple of|a pair of)"
_FLOOR_WORD = r"(?:floor|level|storey|story)"
_ORD = r"(" + "|".join(ORDINALS) + r"|\d+(?:st|nd|rd|th))"
#: Cuts between phrases.
_CUT = re.compile(
    r"\s*(?:[,;:.]|\bwith\b|\band\b|\bplus\b|\bincluding\b|\bas well as\b|\bfeaturing\b|"
    r"\bcontaining\b|\bwhich has\b|\bthat has\b|\bhas\b|\bhave\b|\balso\b|\bthere is\b|\bthere are\b)\s*"
)
#: Where a room is (spatial) rather than on which floor: left to the seed step.
_SPATIAL = re.compile(
    r"\b(?:next to|near|beside|by|opposite|behind|facing|adjacent to|close to|overlooking|off|"
    r"at the (?:back|front|rear|end)|in the (?:north|south|east|west|centre|center|middle|corner)|"
    r"along|around|between|facing|towards)\b.*$"
)
_ENTRANCE = re.compile(
    r"\b(?:(?:next to|near|by|beside|at|close to|off|opposite|facing) (?:the )?(?:main |front )?"
    r"(?:entrance|entry|front door|street|lobby|foyer|reception)|in (?:the )?(?:main )?(?:entrance(?: hall)?|lobby|foyer))\b"
)
#: What follows a room's name and is not part of it: "an office for working from home".
_CLAUSE = re.compile(r"\b(?:for|where|which|that|so|to|in which|with room for|big enough)\b.*$")
_NOT_ROOMS = re.compile(
    r"\b(?:elevators?|lifts?|stairs?|stairwells?|staircases?|cores?|storeys?|stories|floors?|"
    r"levels?|m2|m²|sqm|square|metres?|meters?|feet|ft)\b"
)


@dataclass(frozen=True)
class _Where:
    floor: int | None
    per_floor: bool
    where: str
    from_floor: int = 0
    unsupported: str = ""


def _ordinal(word: str) -> int:
    return ORDINALS[word] if word in ORDINALS else int(re.sub(r"\D", "", word))


def _location(seg: str, british: bool, zero_based: bool) -> tuple[_Where | None, str]:
    """The floor ``seg`` names and ``seg`` without it (and without spatial phrases)."""
    found: _Where | None = None
    on = r"(?:(?:on|at|in) )?(?:the |a |an )?"
    rules: list[tuple[str, object]] = [
        (r"\b" + on + r"(?:first )?" + _FLOOR_WORD + r" above (?:the )?ground(?: " + _FLOOR_WORD + r")?\b",
         _Where(1, False, "first floor above ground")),
        (r"\b(?:on|at|in) (?:the )?(?:basement|cellar|lower ground(?: " + _FLOOR_WORD + r")?|underground(?: " + _FLOOR_WORD + r")?)\b|\bbasement\b",
         _Where(0, False, "basement", unsupported="the offline planner builds no basement; it is on the ground floor instead")),
        (r"\b" + on + r"(?:ground|street|entrance|bottom|lowest) " + _FLOOR_WORD + r"\b|\b(?:on|at) ground level\b|\bdownstairs\b",
         _Where(0, False, "ground floor")),
        (r"\b" + on + r"(?:top|uppermost|highest|last) " + _FLOOR_WORD + r"\b|\bon the top\b|\bon the roof\b|\brooftop\b",
         _Where(-1, False, "top floor")),
        (r"\b(?:on|at|in) (?:each|every) upper " + _FLOOR_WORD + r"\b|\b(?:on|at|in) (?:all )?(?:of )?(?:the )?upper " + _FLOOR_WORD + r"s\b",
         _Where(None, True, "every upper floor", from_floor=1)),
        (r"\b" + on + r"(?:upper|higher) " + _FLOOR_WORD + r"\b|\bupstairs\b|\bon the floor above\b",
         _Where(-1, False, "upper floor", from_floor=1)),
        (r"\b(?:per|(?:on |in )?(?:each|every)|on (?:all(?: the)?|all of the)) " + _FLOOR_WORD + r"s?\b|\bon all " + _FLOOR_WORD + r"s\b",
         _Where(None, True, "every floor")),
        (r"\b" + on + _ORD + r" " + _FLOOR_WORD + r"\b", "ordinal"),
        (r"\b(?:on|at|in) " + _FLOOR_WORD + r" (\d+)\b", "number"),
    ]
    for pattern, what in rules:
        m = re.search(pattern, seg)
        if not m:
            continue
        if what == "ordinal":
            n = _ordinal(m.group(1))
            if n == 0:
                found = _Where(0, False, f"{m.group(1)} floor (numbered from 0: the ground floor)")
            elif british:
                found = _Where(n, False, f"{m.group(1)} floor (British numbering: {n} above the ground floor)")
            else:
                found = _Where(n - 1, False, f"{m.group(1)} floor (American numbering: the first floor is the ground floor)")
        elif what == "number":
            n = int(m.group(1))
            if zero_based:
                found = _Where(n, False, f"floor {n} (numbered from 0)")
            elif british:
                found = _Where(n, False, f"floor {n} (British numbering: {n} above the ground floor)")
            else:
                found = _Where(max(n - 1, 0), False, f"floor {n} (American numbering: floor 1 is the ground floor)")
        else:
            found = what  # type: ignore[assignment]
        seg = seg[: m.start()] + " " + seg[m.end():]
        break
    if found is None and _ENTRANCE.search(seg):
        found = _Where(0, False, "ground floor (by the entrance)")
    seg = _CLAUSE.sub("", _SPATIAL.sub("", re.sub(r"\bin (?:the )?(?:main )?(?:entrance(?: hall)?|lobby|foyer)\b", "", seg)))
    return found, " ".join(seg.split())


def _count(room: str) -> tuple[int | None, str]:
    """(count, the room words) of ``room``; count None when there is no room to count."""
    m = re.match(r"^(?:(?:also|then|there (?:is|are)|one|only|just) )?" + _COUNT + r"\s+(.*)$", room)
    if m:
        word, rest = m.group(1), m.group(2)
        n = parse_count(word)
        if n is None:
            n = 2  # several, some, a few, a couple of
        return n, rest
    if re.match(r"^(?:no|without|zero|not)\b", room):
        return None, ""
    # a bare plural ("toilets on each floor") is two; a bare singular ("reception") one
    return (2 if re.search(r"[a-z]s$", room) and not room.endswith("ss") else 1), room


def read_rooms(text: str, building_family: str = "") -> tuple[list[Placement], list[str], str]:
    """The rooms ``text`` (lower case, spaces normalised) asks for, the phrases that named no
    room, and the floor numbering used (see the module doc)."""
    text = re.sub(r"-(?=(?:floor|level|storey|story)\b)", " ", text)
    british = bool(
        re.search(r"\bground (?:floor|level|storey)\b|\babove (?:the )?ground\b|\bbritish\b|\buk numbering\b", text)
    )
    zero_based = bool(re.search(r"\b(?:floor|level) 0\b", text))
    pieces: list[tuple[str, str]] = []  # (phrase, the cut before it)
    pos, cut = 0, ""
    for m in _CUT.finditer(text):
        pieces.append((text[pos:m.start()], cut))
        pos, cut = m.end(), m.group(0).strip()
    pieces.append((text[pos:], cut))
    # the building itself ("a four-storey office building") comes first and is not a room
    parsed: list[tuple[str, _Where | None, int | None, str, str]] = []
    for k, (seg, joint) in enumerate(pieces):
        seg = seg.strip()
        if not seg:
            continue
        where, room = _location(seg, british, zero_based)
        count, words = _count(room) if room else (None, "")
        if k == 0 or (words and _NOT_ROOMS.search(words)):
            words = ""
        parsed.append((seg, where, count, words, joint))
    out: list[Placement] = []
    unknown: list[str] = []
    carried: _Where | None = None
    for i, (seg, where, count, words, _) in enumerate(parsed):
        if not words:
            # "the top floor has a gym": the floor goes to the rooms after it
            carried = where if where is not None else carried
            continue
        if where is None:
            where = carried
        if where is None:
            # "a pharmacy and a cafe on the ground floor": listed rooms share the next floor said
            for seg2, where2, _, words2, joint2 in parsed[i + 1:]:
                if joint2 not in ("and", ",", "") or not words2 or match_room(words2) is None:
                    break
                if where2 is not None:
                    where = where2
                    break
        if count == 0:
            continue  # "0 rooms", like "no restaurant": nothing to build
        match = match_room(words, building_family)
        if match is None or count is None:
            if count is not None:
                unknown.append(words)
            continue
        where = where or _Where(None, False, "any floor")
        name = match.name
        if count > 1:
            head, _, last = name.rpartition(" ")
            name = f"{head} {singular(last)}".strip()
        out.append(Placement(
            room_type=match.room_type, count=count, floor=where.floor, per_floor=where.per_floor,
            name="" if re.sub(r"[^a-z]", "", name) == match.room_type.replace("_", "") else name,
            phrase=seg, how=match.how, where=where.where, from_floor=where.from_floor,
            unsupported=where.unsupported,
        ))
    return out, unknown, "british" if british else "american"
