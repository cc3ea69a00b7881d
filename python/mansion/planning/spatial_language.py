"""Reading where rooms are from plain English: compass positions, relations, sizes, exterior walls.

A description such as "The bathroom is in the northeast corner with the common room to the south
and the living room to the west. It is approximately 12 feet wide by 5 feet deep." becomes a list
of :class:`Statement` about the rooms it is told about:

- ``position``: the subject lies in a part of the plan (a corner, a side, the centre);
- ``relation``: the subject lies north/south/east/west of another room, between two rooms, next to
  one, or across from one;
- ``size``: a width and depth (metres, converted from feet when the text says feet or gives no
  unit, as floor-plan prose in the US style does) or an area;
- ``exterior``: one of the subject's walls is an outside wall.

The reader is a small grammar over a normalised token stream: room mentions become ``R<k>``
tokens, compass words ``D:<dir>`` tokens, and a sentence's subject is the room it opens with (or
the previous subject for "It ..."/"The room ..."). It never guesses a room it was not told about:
:func:`read_description` takes the rooms of the plan (ids and types) and resolves numbered and
ordinal names ("bathroom 2", "the second bedroom", "com 1"), synonyms ("master bedroom", "bath",
"washroom", "lounge") and bare type words ("the common room") against them. Everything it could
not read is kept (:attr:`Reading.unread`) so a caller can say what was ignored.

Pure Python (``re``); the seeds that follow from a reading are :mod:`mansion.planning.spatial_seeds`.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass, field, replace

from mansion.planning.vocabulary import ROOM_SYNONYMS

__all__ = [
    "DIRECTIONS",
    "KnownRoom",
    "Reading",
    "RoomMention",
    "Statement",
    "direction_vector",
    "read_description",
]

#: Compass directions the reader produces, with their unit vector (x east, y north).
DIRECTIONS: dict[str, tuple[int, int]] = {
    "north": (0, 1), "south": (0, -1), "east": (1, 0), "west": (-1, 0),
    "northeast": (1, 1), "northwest": (-1, 1), "southeast": (1, -1), "southwest": (-1, -1),
    "centre": (0, 0),
}
_OPPOSITE = {
    "north": "south", "south": "north", "east": "west", "west": "east",
    "northeast": "southwest", "southwest": "northeast", "northwest": "southeast",
    "southeast": "northwest", "centre": "centre",
}
_FEET = 0.3048


def direction_vector(direction: str) -> tuple[int, int]:
    """The unit step of a direction word of :data:`DIRECTIONS` (``centre`` is (0, 0))."""
    return DIRECTIONS[direction]


@dataclass(frozen=True)
class KnownRoom:
    """A room the reader may resolve mentions to: its id, its type (``"common_room"``,
    ``"pharmacy"``), and optionally a display name."""

    id: str
    room_type: str
    name: str | None = None


@dataclass(frozen=True)
class RoomMention:
    """A room named in the text: its type, the number the text gave it (``bathroom 2``, ``the
    second bedroom``) or None, and the words used."""

    room_type: str
    number: int | None
    words: str

    @property
    def key(self) -> tuple[str, int | None]:
        return (self.room_type, self.number)


@dataclass(frozen=True)
class Statement:
    """One thing the text says about a room.

    ``kind`` is ``position`` (``direction`` is where in the plan), ``relation`` (``relation`` is
    one of ``north_of`` … ``southwest_of``, ``between``, ``next_to``, ``across_from``; ``others``
    the rooms it is relative to), ``size`` (``width``/``depth`` in metres, either may be None;
    ``area`` in m²; ``oriented`` when the text said which is east-west) or ``exterior``
    (``direction`` of the outside wall). ``text`` is the clause it came from.
    """

    subject: RoomMention
    kind: str
    text: str
    direction: str | None = None
    relation: str | None = None
    others: tuple[RoomMention, ...] = ()
    width: float | None = None
    depth: float | None = None
    area: float | None = None
    oriented: bool = False


@dataclass
class Reading:
    """What :func:`read_description` understood: statements about resolved rooms (by room id),
    and what it could not use."""

    #: Statements with their subject resolved, by room id (in the order they were read).
    statements: dict[str, list[Statement]] = field(default_factory=dict)
    #: Clauses the reader found nothing in.
    unread: list[str] = field(default_factory=list)
    #: Statements whose subject or other room is not one of the known rooms (with the reason).
    unresolved: list[tuple[Statement, str]] = field(default_factory=list)
    #: Mention key (type, number) → room id, as resolved.
    resolved: dict[tuple[str, int | None], str] = field(default_factory=dict)

    def about(self, room_id: str) -> list[Statement]:
        return self.statements.get(room_id, [])

    def all(self) -> list[tuple[str, Statement]]:
        return [(rid, s) for rid, ss in self.statements.items() for s in ss]


# -- normalisation ------------------------------------------------------------------------------

_NUMBER_WORDS = {
    "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8,
    "nine": 9, "ten": 10, "eleven": 11, "twelve": 12, "thirteen": 13, "fourteen": 14,
    "fifteen": 15, "sixteen": 16, "seventeen": 17, "eighteen": 18, "nineteen": 19, "twenty": 20,
    "twenty-five": 25, "thirty": 30, "forty": 40, "fifty": 50,
}
_ORDINALS = {"first": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5, "1st": 1, "2nd": 2, "3rd": 3, "4th": 4}

#: Spelling variants folded before anything else reads the text.
_FOLDS: tuple[tuple[str, str], ...] = (
    (r"[’‘`´]|â\x80[\x98\x99]", "'"),
    (r"â\x80[\x9c\x9d]", '"'),
    (r"[“”]", '"'),
    (r"#ref!", " "),
    (r"\bbed\s+rooms?\b", "bedroom"),
    (r"\bbath\s+rooms?\b", "bathroom"),
    (r"\bwash\s+rooms?\b", "washroom"),
    (r"\bliving\s*rooms?\b", "living room"),
    (r"\blivingroom\b", "living room"),
    (r"\bkitchen\s+room\b", "kitchen"),
    (r"\bstore\s*room\b", "storage"),
    (r"\bcomm?on\s*rooms?\b", "common room"),
    (r"\bmaster\s+bed\b", "master bedroom"),
    (r"\bcentral(?:ly)?\b", " centre "),
    (r"\b(?:center|centre|middle)\b", " centre "),
    (r"\b(up\s*side|upside)\b", " upside "),
    (r"\b(down\s*side)\b", " downside "),
    (r"\b(north|south|east|west)side\b", r" \1 side "),
    (r"\b(left\s*side|leftside)\b", " left side "),
    (r"\b(right\s*side|rightside)\b", " right side "),
    (r"\bright\s+(?=next|by|beside|above|below|behind|at|in|on|off|outside|near)", " "),
    (r"\bdog\s*leg\b", " "),
    # "lenght" (70 times in the 500 dev descriptions), "breadth" (a width), "9 feet across and
    # 15 feet deep" (across: wide)
    (r"\b(?:lenght|lenth|legnth|lengh)\b", "length"),
    (r"\bbreadth\b", "width"),
    (r"(\d\s*(?:feet|foot|ft|m|meters?|metres?)\s+)across\b", r"\1wide"),
    # "South est corner": "est" is no word of its own after a compass word
    (r"\b(north|south)\s*-?\s*est\b", r"\1 east"),
    # "Location: East side, Relationship: ...": a label whose room's name was left out (it opens
    # the description of a room the text does not name, :func:`_unnamed_descriptions`)
    # (also after a size the description ends on, "... 5 feet length Localization: east side")
    (r"(^|[.;!?\n]\s*|\b(?:length|width|feet|ft)\s+)(?:location|localization)\s*:\s*(?=(?:north|south|east|west|centr|center|middle)\w*\b)", r"\1. location at "),
    # "Location: Common room 1 is on ...", "Size: It is ...": a heading before a sentence is no
    # part of it (left there, it hides the room that opens the sentence)
    (r"(^|[.;!?\n]\s*)(?:location|position|placement|relationships?|relations?|size|dimensions?|measurements?|area|sides|adjacency|orientation)\s*:", r"\1 "),
    # "the kitchen near room as the balcony", "kitchen opposite as the bedroom": the room named after "as"
    (r"\b(near|opposite|next\s+to|adjacent\s+to)\s+(?:the\s+)?(?:rooms?\s+)?as\b", r"\1"),
    # "the master room in front room as the bathroom": in front of the bathroom
    (r"\bin\s+front\s+(?:of\s+)?(?:the\s+)?(?:rooms?\s+)?as\b", "in front of"),
)

_DIR_WORD = {
    "north": "north", "northern": "north", "northward": "north", "northerly": "north",
    "south": "south", "southern": "south", "southward": "south", "southerly": "south",
    "east": "east", "eastern": "east", "eastward": "east", "easterly": "east",
    "west": "west", "western": "west", "westward": "west", "westerly": "west",
}
_COMPOUND = re.compile(
    r"\b(north|south|east|west|upper|top|lower|bottom)(?:ern|erly|ward)?\s*-?\s*"
    r"(east|west|north|south|left|right)(?:ern|erly|ward)?\b(?!\s*(?:floors?|storeys?|levels?)\b)"
)
_SINGLE = re.compile(r"\b(north|south|east|west)(?:ern|erly|ward|wards)?\b")
# "the top floor", "a lower level" name storeys, not parts of a plan
_SCREEN = re.compile(r"\b(upper|top|lower|bottom|left|right)\b(?!\s*(?:floors?|storeys?|story|stories|levels?|decks?|ground)\b)")


def _compound(a: str, b: str) -> str | None:
    vertical = {"north": "north", "upper": "north", "top": "north", "south": "south", "lower": "south", "bottom": "south"}
    horizontal = {"east": "east", "right": "east", "west": "west", "left": "west"}
    if a in vertical and b in horizontal:
        return vertical[a] + horizontal[b]
    if a in horizontal and b in ("north", "south"):  # "east north corner"
        return b + horizontal[a]
    return None


def _directions(text: str) -> str:
    """Replace compass words by ``D:<direction>`` tokens (screen words too: upper right → NE)."""

    def compound(m: re.Match[str]) -> str:
        d = _compound(m.group(1), m.group(2))
        return m.group(0) if d is None else f" D:{d} "

    text = _COMPOUND.sub(compound, text)
    text = _SINGLE.sub(lambda m: f" D:{_DIR_WORD[m.group(1)]} ", text)
    screen = {"upper": "north", "top": "north", "lower": "south", "bottom": "south", "left": "west", "right": "east"}
    text = _SCREEN.sub(lambda m: f" D:{screen[m.group(1)]} ", text)
    text = re.sub(r"\bcentre\b", " D:centre ", text)
    # "in the back of the house", "the front part of the plan": as drawn, the entrance at the
    # bottom (the front, south) and the back at the top (north), as left and right are west and east
    text = re.sub(
        r"\b(front|back|rear)(?=(?:\s+(?:side|part|portion|end|area|section|half))?\s+of\s+(?:the\s+)?" + _PLACE + r")",
        lambda m: " D:south " if m.group(1) == "front" else " D:north ", text,
    )
    # "below it is the R1", "R1 is directly above it": the side of the room "it" is (read as
    # "D:north of it" is)
    text = re.sub(
        r"\b(above|below|beneath|under|underneath)\s+it\b(?!')",
        lambda m: f" to the D:{'north' if m.group(1) == 'above' else 'south'} of it ", text,
    )
    # "with the R1 on below", "R1 on above": a side named by a preposition standing alone
    text = re.sub(
        r"\b(on|at|to)\s+(?:the\s+)?(above|below|beneath|under|underneath)\b(?!\s*(?:of\b|the\b|its?\b|R\d))",
        lambda m: f" {m.group(1)} D:{'north' if m.group(2) == 'above' else 'south'} ", text,
    )
    return text


#: Room words that misspellings are folded to ("kichen", "commanroom", "livingoom", "balocany").
_SPELLING = {
    "bathroom": "bathroom", "bedroom": "bedroom", "kitchen": "kitchen", "balcony": "balcony",
    "livingroom": "living room", "masterroom": "master room", "commonroom": "common room",
    "living": "living", "master": "master", "common": "common", "dining": "dining",
    "washroom": "washroom", "storage": "storage", "adjacent": "adjacent", "corner": "corner",
}
#: Real words close to a room word that must stay as they are.
_NOT_TYPOS = frozenset({"enter", "centered", "matter", "mister", "later", "comma", "commons", "comment", "storing", "storey", "corners", "corned", "leaving", "giving", "diving", "lining", "mining", "kitten"})


def _fold_spelling(text: str) -> str:
    """Fold misspelt room words to their spelling (rapidfuzz ratio ≥ 85, words of five letters
    or more that are not themselves room words or common look-alikes; or, from six letters, one
    edit away with the first letter right: "livign", "comman", "commom", which the ratio of a
    short word puts under 85)."""
    from rapidfuzz import fuzz, process
    from rapidfuzz.distance import OSA

    choices = list(_SPELLING)

    def fold(m: re.Match[str]) -> str:
        word = m.group(0)
        if len(word) < 5 or word in _SPELLING or word in _NOT_TYPOS or word.endswith("s"):
            return word
        best = process.extractOne(word, choices, scorer=fuzz.ratio, score_cutoff=85)
        if best is None and len(word) >= 6:
            best = next(((c, 0, 0) for c in choices if c[0] == word[0] and OSA.distance(word, c) <= 1), None)
        return _SPELLING[best[0]] if best else word

    return re.sub(r"[a-z]+", fold, text)


def _numbers(text: str) -> str:
    words = "|".join(sorted(_NUMBER_WORDS, key=len, reverse=True))
    text = re.sub(rf"\b({words})\b", lambda m: str(_NUMBER_WORDS[m.group(1)]), text)
    # "12'6"" and "12 ft 6 in" → 12.5
    text = re.sub(r"(\d+)\s*'\s*(\d{1,2})\s*\"", lambda m: f"{int(m.group(1)) + int(m.group(2)) / 12:g}'", text)
    return text


# -- room names ---------------------------------------------------------------------------------

#: Residential room types and the words for them, most specific first. Types not listed here are
#: read through the planner's vocabulary (:data:`ROOM_SYNONYMS`) and their own name.
_RESIDENTIAL: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("master_room", (r"master\s+bedroom", r"master'?s?\s+room", r"main\s+bedroom", r"master\s+suite", r"master")),
    ("common_room", (r"common\s+room", r"community\s+room", r"common", r"comm", r"com", r"guest\s+room", r"kids?'?\s+room", r"children'?s\s+room", r"spare\s+room", r"secondary\s+bedroom")),
    # "room 1", "room 2" with no type word: the numbered bedrooms
    ("bedroom", (r"bedroom", r"bed", r"room(?=\s*-?\s*#?\s*\d{1,2}\b(?!\s*(?:'|\"|x\b|\*|by\b|ft\b|feet\b|foot\b|m\b|sq|square|%|\.\d|/|:\s*\d)))")),
    ("bathroom", (r"bathroom", r"bath", r"comfort\s+room", r"washroom", r"restroom", r"toilet", r"wc", r"lavatory", r"shower\s+room", r"ensuite", r"en\s+suite")),
    ("living_room", (r"living\s+room", r"living\s+area", r"living", r"lounge", r"sitting\s+room", r"family\s+room", r"hall")),
    ("dining_room", (r"dining\s+room", r"dining\s+area", r"dining")),
    ("kitchen", (r"kitchen", r"kitchenette", r"galley")),
    ("balcony", (r"balcony", r"balconies", r"terrace", r"veranda", r"verandah", r"porch", r"patio", r"deck")),
    ("storage", (r"storage(?:\s+room)?", r"store", r"closet", r"pantry", r"utility\s+room")),
)
_ROMAN = {"i": 1, "ii": 2, "iii": 3, "iv": 4}


@dataclass(frozen=True)
class _Lexicon:
    pattern: re.Pattern[str]
    types: dict[str, str]  # lower-case words (spaces normalised) → type


def _lexicon(types: Sequence[str]) -> _Lexicon:
    words: dict[str, str] = {}
    known = set(types)
    # a room type's own name wins over another type's synonym ("pantry" when there is a pantry)
    for kind in sorted(known):
        words[re.escape(kind.replace("_", " ")).replace(r"\ ", r"\s+")] = kind
    for kind, syns in _RESIDENTIAL:
        if kind in known or kind == "bedroom" and ({"master_room", "common_room", "bedroom"} & known):
            for s in syns:
                words.setdefault(s, kind)
    for kind, syns in ROOM_SYNONYMS:
        if kind in known:
            for s in syns:
                words.setdefault(s, kind)
    for kind in known:
        name = re.escape(kind.replace("_", " ")).replace(r"\ ", r"\s+")
        words.setdefault(name, kind)
    # longest alternatives first so "master bedroom" wins over "master"
    alternatives = sorted(words, key=lambda w: (-len(w), w))
    # "balcony 2", "balcony-2", "bath #2", "Balcony 2: south facing" (a label, not a ratio)
    number = r"(?:\s*-?\s*(?:no\.?|#)?\s*(\d{1,2}|i{1,3}|iv)\b(?!\s*(?:'|\"|x\b|\*|:\s*\d|×|by\b|ft\b|feet\b|foot\b|m\b|met|sq|square|%|\.\d|/)))?"
    ordinal = r"(?:\b(first|second|third|fourth|fifth|1st|2nd|3rd|4th|other|another)\s+)?"
    body = "|".join(f"(?:{w})" for w in alternatives)
    pattern = re.compile(ordinal + r"\b(" + body + r")(?:'s)?(?:\b|(?=\d))" + number)
    return _Lexicon(pattern, {w: k for w, k in words.items()})


def _type_of(lex: _Lexicon, word: str) -> str:
    for w, kind in sorted(lex.types.items(), key=lambda kv: -len(kv[0])):
        if re.fullmatch(w.split("(?=")[0], word):
            return kind
    return word


# -- clauses and subjects -----------------------------------------------------------------------

_SUBJECT_LEAD = re.compile(
    # "The D:south facing R0 offers ...": a compass word in front of the room is about it
    # ("This house has a D:north-facing R0": a sentence about the house's room is about the room)
    r"^(?:(?:the|a|an|one|this|that|there|is|are|also|then|and|with|plus|finally|lastly|next|,|:|-|D:\w+|-?facing|"
    r"(?:house|home|apartment|flat|unit)\s+(?:has|features|includes|contains|offers)|"
    r"\d[\d.x*'\"]*(?:\s*(?:x|by|\*)\s*\d[\d.'\"]*)?)\s*)*$"
)
_PRONOUN = re.compile(r"^\s*(?:it|its|it's|this|the\s+room|this\s+room|the\s+size|size|which|they|their)\b")
_PLACE = (
    r"(?:house|home|plan|floor\s*plan|floorplan|floor|apartment|unit|layout|diagram|image|plane|"
    r"building|flat|property|structure|space|map|picture|drawing|residence|dwelling|design|level|storey)"
)
#: A clause that opens with a place of the plan and names the room there after a verb: "in the
#: D:northeast corner is the R2", "the D:south corner of the house has a R5", "on the D:west side
#: of the house you will find the R1", "located at the D:northeast is the R2". A bare "to the
#: D:north is the R2" stays a relation to the previous subject (it is said of that room).
_INVERTED = re.compile(
    r"^\s*(?P<verb>(?:located|situated|placed|positioned)\s+)?(?P<prep>in|on|at|towards?|to|)\s*(?:the\s+)?(?:(?:very|far)\s+)?"
    r"(?:D:\w+(?:\s*(?:and|-|/)\s*D:\w+)*)"
    r"(?P<part>\s+(?:corner|side|part|portion|end|area|section|half|quadrant|wing|edge|region))?"
    r"(?P<place>\s+(?:of|in)\s+(?:the\s+)?" + _PLACE + r")?"
    r"\s*,?\s*(?:is|are|has|have|holds|contains|lies|sits|stands|comes|you\s+will\s+find|you'll\s+find|we\s+find|"
    r"there\s+is|there\s+are|we\s+have|you\s+have)\s+(?:also\s+)?(?:the\s+|a\s+|an\s+|one\s+)?R(?P<room>\d+)\b"
)
_PART = r"(?:corner|side|part|portion|end|area|region|section|half|quadrant|edge|zone|location|most|direction|wing|face|facing|quarter)"
_VERB_AFTER_SUBJECT = re.compile(
    r"^\s*(?:is|are|was|lies|sits|located|situated|placed|positioned|can|could|has|have|takes|"
    r"occupies|covers|extends|juts|at|in|on|location|measures|measuring|size|dominates|fills|"
    r"runs|spans|connects|opens|should|would|will|leads|appears|looks|D:|\(|,|:|-)"
)


@dataclass
class _Clause:
    text: str  # normalised, with R<k> and D:<dir> tokens
    raw: str
    subject: int | None  # index into mentions


def _split_sentences(text: str) -> list[str]:
    # A full stop ends a sentence unless it is inside a number ("5.5") or an abbreviation ("ft.",
    # "10 ft. in length"; "... the middle. In the north ..." is a new sentence).
    parts = re.split(
        r"(?<!\d)\.(?!\d)(?!\s*(?:by|x|wide|long|deep|tall|high|in\b(?!\s+the\b)|and|or|\d)\b)|(?<=\d)\.(?!\d)|[;!?\n]+", text
    )
    return [p.strip() for p in parts if p and p.strip(" ,")]


def read_description(text: str, rooms: Sequence[KnownRoom]) -> Reading:
    """Read the position statements of ``text`` about ``rooms``.

    Never raises for language it does not understand: such clauses land in ``Reading.unread``.
    """
    lex = _lexicon([r.room_type for r in rooms])
    norm = _fold_spelling(text.lower())
    for pat, rep in _FOLDS:
        norm = re.sub(pat, rep, norm)
    norm = _numbers(norm)

    mentions: list[RoomMention] = []

    def mention(m: re.Match[str]) -> str:
        ordinal, word, num = m.group(1), m.group(2), m.group(3)
        kind = _type_of(lex, word)
        number: int | None = None
        if num:
            number = int(num) if num.isdigit() else _ROMAN.get(num)
        elif ordinal and ordinal not in ("other", "another"):
            number = _ORDINALS[ordinal]
        mentions.append(RoomMention(kind, number, m.group(0).strip()))
        return f" R{len(mentions) - 1} "

    tokens = lex.pattern.sub(mention, norm)

    # "common room 1 and 2", "balcony 1&2": the second number names the type's other room
    def numbered(m: re.Match[str]) -> str:
        first = mentions[int(m.group(1))]
        if first.number is None:
            return m.group(0)
        mentions.append(RoomMention(first.room_type, int(m.group(3)), f"{first.words} {m.group(2)} {m.group(3)}"))
        return f"R{m.group(1)} {m.group(2)} R{len(mentions) - 1} "

    tokens = re.sub(r"R(\d+)\s*(and|&|,)\s*(\d)\b(?!\s*(?:'|\"|feet|foot|ft\b|x\b|by\b|m\b|sq|square|%|\.\d|/))", numbered, tokens)
    # "Balcony Room", "com Room", "common room1 Room": the word room after a room's name is part of it
    tokens = re.sub(r"(R\d+)\s*rooms?\b", r"\1", tokens)
    # "R1 and R2 between the room as R3": R3 is between R1 and R2; "R3 is between the room as R1 and R2"
    tokens = re.sub(
        r"((?:the\s+)?R\d+(?:\s*(?:,|and|&)\s*(?:the\s+)?R\d+)+)\s+(?:is\s+|are\s+)?(?:in\s*)?between\s+(?:the\s+)?rooms?\s+as\s+(?:the\s+)?(R\d+)",
        r"\2 is between \1", tokens,
    )
    tokens = re.sub(r"\bbetween\s+(?:the\s+)?rooms?\s+as\b", "between", tokens)
    tokens = _directions(tokens)
    tokens = re.sub(r"[ \t]+", " ", tokens)

    # Sentences, then unpunctuated run-ons split where a new room opens a description
    # ("... size 10*4 feet R3 at D:northwest corner ...").
    clauses: list[_Clause] = []
    subject: int | None = None
    for sentence in _split_sentences(tokens):
        opening: int | None = None  # the subject before the sentence's list of other rooms
        listed = False
        for piece, listed in _run_on_split(sentence):
            before = subject
            if listed and opening is None:
                opening = subject
            elif not listed:
                opening = None
            first = re.search(r"R(\d+)\b", piece)
            # "Occupying most of the west side, the living room ...": the subject follows a
            # leading participle phrase, which is about it
            dangling = re.match(r"\s*(?:[a-z]+ing|located|situated|placed|positioned|set|tucked)\b[^,]*,\s*(?:the\s+|a\s+|an\s+)?R(\d+)\b", piece)
            if dangling:
                subject = int(dangling.group(1))
                clauses.append(_Clause(piece, piece, subject))
                continue
            # "In the D:northeast corner is the R2", "The D:south corner of the house has a R5":
            # a place of the plan, then the room that is there
            inverted = _INVERTED.match(piece)
            if inverted and (
                inverted.group("part") or inverted.group("place") or inverted.group("verb") or inverted.group("prep") == "in"
            ):
                subject = int(inverted.group("room"))
                clauses.append(_Clause(piece, piece, subject))
                continue
            lead = piece[: first.start()] if first else ""
            if first and _SUBJECT_LEAD.match(lead.strip() + " " if lead.strip() else "") and (
                _opens_description(piece[first.end():]) or subject is None
            ):
                subject = int(first.group(1))
            elif first and not lead.strip() and subject is None:
                subject = int(first.group(1))
            else:
                # "Measuring about 10x10 ft, the common room is located ...": a room named with
                # a placing verb after a leading phrase is the subject too
                # ("The size of the R2 is 12 by 6 feet": a sentence about a measure of a room
                # is about that room)
                later = re.search(
                    r"(?:^|,\s*|\bthe\s+)R(\d+)\s+(?:is|are)\s+(?:located|situated|positioned|placed|found|in|on|at)\b"
                    r"|\b(?:location|direction|position|placement)\s+of\s+(?:the\s+)?R(\d+)"
                    r"|^\s*(?:the\s+)?(?:[a-z]+\s+)?(?:size|area|dimensions?|measurements?)\s+of\s+(?:the\s+)?R(\d+)\s+(?:is|are|was|measures)\b(?!\s+(?:the\s+)?R\d)",
                    piece,
                )
                if later:
                    subject = int(later.group(1) or later.group(2) or later.group(3))
            piece = _of_it(piece, subject, before)
            clauses.append(_Clause(piece, piece, subject))
        # "The master is on the east side with the living room at the northwest corner. It is
        # 12 feet wide": the rooms listed after "with" are placed relative to the sentence's
        # subject, and the next sentence's "It" is still that subject
        if listed and opening is not None:
            subject = opening

    _unnamed_descriptions(clauses, mentions, rooms)
    statements: list[Statement] = []
    unread: list[str] = []
    for clause in clauses:
        if clause.subject is None:
            unread.append(_plain(clause.text, mentions))
            continue
        found = _read_clause(clause, mentions)
        if found:
            statements.extend(found)
        elif not _is_filler(clause.text):
            unread.append(_plain(clause.text, mentions))
    return _resolve(_join_sides(statements), unread, mentions, rooms)


def _join_sides(statements: list[Statement]) -> list[Statement]:
    """Join each room's side lengths (size statements with only a width or only a depth, from
    clauses such as "D:north side length is 16 feet. D:east and D:west side length is 8 feet")
    into one oriented size where its first stood: the longest side each way (the room's box is as
    wide as its longest side across)."""
    sides: dict[tuple[str, int | None], list[Statement]] = {}
    for s in statements:
        if s.kind == "size" and s.area is None and (s.width is None) != (s.depth is None):
            sides.setdefault(s.subject.key, []).append(s)
    if not sides:
        return statements
    out: list[Statement] = []
    for s in statements:
        group = sides.get(s.subject.key) if s.kind == "size" else None
        if group is None or not any(s is g for g in group):
            out.append(s)
        elif s is group[0]:
            widths = [g.width for g in group if g.width is not None]
            depths = [g.depth for g in group if g.depth is not None]
            out.append(replace(
                s, width=max(widths, default=None), depth=max(depths, default=None),
                text="; ".join(g.text for g in group),
            ))
    return out


#: A description that opens by placing a room it does not name: "Located in the middle of the
#: D:north side.", "It was placed on the D:northwest side of the plan."
#: ("placed in between the R1 and R2" alone goes on with the description before it)
_UNNAMED_OPENER = re.compile(r"^\s*(?:(?:it\s+(?:is|was)\s+|it'?s\s+)(?:located|locate|placed|situated|positioned)|located|situated|positioned)\b")


#: A label with no room before it: "Location: east side, Relationship: between living and
#: master" (the room's name left out of a list of labelled descriptions)
_UNNAMED_LABEL = re.compile(r"^\s*location\s+at\b")


def _unnamed_descriptions(clauses: list[_Clause], mentions: list[RoomMention], rooms: Sequence[KnownRoom]) -> None:
    """Give the descriptions that never name their room the rooms the text leaves undescribed.

    Some descriptions go through the rooms one after another in alphabetical order of their
    names and leave some of them unnamed ("Located in the middle of the north side. Size is 10 x
    4 sq ft. Located in the south east corner. ... The bathroom is located in ..."), or leave the
    room's name out of a list of labels ("Bathroom 1 location: west side. Location: east side.
    Kitchen location: ..."). When the text opens so, each clause that opens by placing an unnamed
    room ("located ...", "it was placed ...") starts such a description; a label with no room
    starts one anywhere. When there are exactly as many of them as rooms no clause is about, the
    unnamed descriptions take those rooms in alphabetical order, provided the named and the
    unnamed descriptions together then follow that order. Otherwise nothing changes (the clauses
    stay unread, or about the room named before them).
    """
    if not clauses:
        return
    opens_text = clauses[0].subject is None and bool(_UNNAMED_OPENER.match(clauses[0].text) or _UNNAMED_LABEL.match(clauses[0].text))
    if not opens_text and not any(_UNNAMED_LABEL.match(c.text) for c in clauses):
        return
    by_type: dict[str, list[str]] = {}
    for r in rooms:
        by_type.setdefault(r.room_type, []).append(r.id)
    # the text's descriptions in order: a named room's key, or None and an unnamed one's clauses
    order: list[tuple[tuple[str, int | None] | None, list[int]]] = []
    prev: int | None = None
    for i, c in enumerate(clauses):
        opens = bool(_UNNAMED_LABEL.match(c.text) or (opens_text and _UNNAMED_OPENER.match(c.text)))
        if c.subject is not None and c.subject != prev:
            order.append((_canonical(mentions[c.subject], by_type), []))
        elif opens and (c.subject is None or c.subject == prev):
            order.append((None, [i]))
        elif order and order[-1][0] is None:
            order[-1][1].append(i)
        prev = c.subject
    described = {key for key, _ in order if key is not None}
    slots: list[tuple[str, int | None]] = []
    for kind, ids in by_type.items():
        said = {n for k, n in described if k == kind}
        if len(ids) == 1:
            slots += [] if said else [(kind, None)]
        elif None in said:
            return  # "the balcony" said of one of two: which one is left is not known
        else:
            slots += [(kind, n) for n in range(1, len(ids) + 1) if n not in said][: len(ids) - len(said)]
    if len(slots) != sum(key is None for key, _ in order):
        return
    slots.sort(key=lambda k: (k[0], k[1] or 0))
    it = iter(slots)
    keys = [key if key is not None else next(it) for key, _ in order]
    firsts = list(dict.fromkeys(keys))
    if any((a[0], a[1] or 0) > (b[0], b[1] or 0) for a, b in zip(firsts, firsts[1:])):
        return
    for (key, unnamed), (kind, n) in zip(order, keys):
        if key is None:
            mentions.append(RoomMention(kind, n, kind.replace("_", " ")))
            for i in unnamed:
                clauses[i].subject = len(mentions) - 1


#: Words after which a room name continues the clause rather than opening a new description.
_LINKS = frozenset(
    "of off to with and by between from near beside behind inside within outside than as or nor the a an its their his her "
    "into onto toward towards through via is are was were leads opens faces facing overlooks "
    "adjacent adjoining next nearby connects connected accessed accessible entrance bordered "
    "neighbored neighboured followed after before above below under over upside downside , "
    "touches touching touch borders bordering surrounded surrounding joining joins "
    "both all also then while where which that has have had contains containing includes including".split()
)


def _run_on_split(sentence: str) -> list[tuple[str, bool]]:
    """Split a sentence at rooms that open a new description after a size ("... 10*4 feet R3
    at ..."), the mark of descriptions written without full stops, and at a list of other rooms
    ("with the R1 at the D:northwest corner"); each piece with whether it came from such a list."""
    cuts = [m.start() for m in re.finditer(r"(?:\bthe\s+)?R\d+", sentence) if _opens_at(sentence, m.start())]
    # "... 8 x 8 sq ft D:north facing R4 is located ...": the facing word opens R4's description
    for m in re.finditer(r"(?:\bthe\s+)?(?:D:\w+\s+)+facing\s+(?:the\s+)?(R\d+)\b", sentence):
        prev = re.search(r"(\w+)\s*$", sentence[: m.start()])
        if prev and prev.group(1) not in _LINKS and _OPENS.match(sentence[m.start(1):]):
            cuts = [c for c in cuts if c != m.start(1)] + [m.start()]
    # a request's list of rooms: "a clinic with a pharmacy on the east side, and a cafe in ..."
    listed = {m.start() for m in re.finditer(r"(?:\bwith|,\s*(?:and|plus)?|\band)\s+(?=(?:an?|one)\s+R\d|the\s+R\d+\s+(?:in|on|at|along|occupies|takes)\s+(?:the\s+)?(?:D:\w+\s+)+(?:corner|(?:side|part|end|wing)\s+of\s+the\s+" + _PLACE + r"))", sentence)}
    listed -= set(cuts)
    cuts = sorted(set(c for c in [*cuts, *listed] if c > 0))
    if not cuts:
        return [(sentence, False)]
    pieces, start, was_list = [], 0, False
    for c in cuts:
        pieces.append((sentence[start:c], was_list))
        start, was_list = c, c in listed
    pieces.append((sentence[start:], was_list))
    return [(p, flag) for p, flag in pieces if p.strip()]


#: A room that opens a description: "R3 is ...", "R3 was locate(d) ...", "R3 at ...", "R3 D:north
#: ...", "R3 measures ...", "R3: D:north side ..." (a room named as a label).
_OPENS = re.compile(r"(?:the\s+)?R\d+(?:\s+(?:it'?s\s+|it\s+is\s+)?(?:is|was|at|in|on|located|locate|location|lies|sits|measures|measuring|D:)|\s*:(?!\s*\d))")
#: Openers no list of rooms goes on with: "..., R6 measures about", "R6: D:north side".
_OPENS_STRONGLY = re.compile(r"(?:the\s+)?R\d+(?:\s+(?:measures|measuring)\b|\s*:(?!\s*\d)|\s+location\s*:)")
#: Openers that place the room: after another room's name they still start a new description
#: ("... near the R5 the R1 is D:west side ...", "between R2 and R3 R4 is located ...").
_OPENS_PLACING = re.compile(
    r"(?:the\s+R\d+\s+(?:is|at|in|on|located|lies|D:)|R\d+\s+(?:(?:is|are)\s+(?:located|situated|placed|positioned|in|at|on|D:)|located|situated))"
)


def _opens_at(sentence: str, start: int) -> bool:
    """Does the room named at ``start`` open a new description in a run-on sentence? It does when
    an opener follows it (:data:`_OPENS`) and the word before it ends the previous description
    (a size, a room's name before a placing verb, a comma before "measures"), not when that word
    links the room into the clause ("next to the R1 is", "R1 and R2 are")."""
    rest = sentence[start:]
    if not _OPENS.match(rest):
        return False
    head = sentence[:start].rstrip()
    prev = re.search(r"(R\d+|[\w.]+(?:'|\")?|,)$", head)
    if prev is None:
        return False
    word = prev.group(1)
    if word == ",":
        # "Located on the D:north end of the R5, R0 measures ...": a leading phrase about R0
        leading = re.match(r"\s*(?:[a-z]+ing|located|situated|placed|positioned|set|tucked)\b[^,]*,$", head)
        return bool(_OPENS_STRONGLY.match(rest)) and leading is None
    if re.fullmatch(r"R\d+", word):
        return bool(_OPENS_PLACING.match(rest) or _OPENS_STRONGLY.match(rest))
    # "It's roughly 8ft by R2 is in ...": a size left unfinished ends the description
    if word in ("by", "x") and re.search(r"\d\s*(?:'|ft|feet|foot|m)?\s+(?:by|x)$", head):
        return True
    if word in _LINKS:
        return False
    # "is in the R1's D:southwest corner": a part of another room, not a new description
    if word in ("in", "at", "on", "into", "inside", "within") and re.match(r"(?:the\s+)?R\d+(?:\s*'?s|\s+rooms?)?\s+D:\w+\s+" + _OWN_PART, rest):
        return False
    # "the 11x5 bathroom is ...": a size in front of the room is not the end of a description
    return not re.search(r"\b(?:the|a|an)\s+[\d.x*'\"]+\s*$", head)


def _of_it(piece: str, subject: int | None, before: int | None) -> str:
    """Resolve "D:north of it". After another room ("It has R1 to the D:north of it") "it" is the
    subject, and R1 lies D:north of it: the words "of it" go. Said of the subject, "it" is the room
    named last before it in the clause ("R3 is attached to the R1, just D:south of it"), or else,
    in a clause that names a new subject ("The R2 is D:north of it"), the room described before."""
    pattern = r"(D:\w+\b(?:\s+(?:side|part|corner|end))?\s+)(?:of|from)\s+(?:it|this\s+room|that\s+room)\b"
    out, last = [], 0
    for m in re.finditer(pattern, piece):
        head = piece[: m.start()]
        other = re.search(
            r"R(\d+)(?:\s+(?:is|are|lies|lie|sits|located|situated|just|directly|immediately|also|to|on|at|in|the|its))*\s*$", head
        )
        named = [int(k) for k in re.findall(r"R(\d+)", head) if int(k) != subject]
        if other and int(other.group(1)) != subject:
            rep = m.group(1)
        elif named:
            rep = f"{m.group(1)}of R{named[-1]} "
        elif subject is not None and before is not None and subject != before:
            rep = f"{m.group(1)}of R{before} "
        else:
            continue
        out.append(piece[last : m.start()] + rep)
        last = m.end()
    return "".join(out) + piece[last:]


def _opens_description(rest: str) -> bool:
    # A room opening a sentence is its subject ("R2 is ...", "R2 resides ...", "R2 D:south
    # direction"), unless it starts a list or a relation to the previous subject ("R2 and R3 are
    # to the west", "R2 to the north"); "R2, measuring 80 sq ft, is ..." and "R2 or office is ..."
    # open a description.
    if re.match(r"\s*,\s*(?:measuring|being|located|situated|which|approximately|about|roughly|around)\b", rest):
        return True
    return not re.match(r"\s*(?:and|&|,|or(?=\s+(?:the\s+|a\s+|an\s+)?R\d)|as\s+well|to\s+the|to\s+its|on\s+its|is\s+to\s+(?:the|its)\s+D:\w+\b(?!\s+(?:side\s+|part\s+)?(?:of|from)\b)|are\b)", rest)


def _is_filler(text: str) -> bool:
    return not re.search(r"R\d+|D:|\d", text)


def _plain(text: str, mentions: list[RoomMention]) -> str:
    out = re.sub(r"R(\d+)\b", lambda m: mentions[int(m.group(1))].words, text)
    return re.sub(r"D:(\w+)", r"\1", out).strip()


# -- the grammar of one clause ------------------------------------------------------------------

#: Words for a part of a room: "the R1's D:southwest corner", "its D:north side".
_OWN_PART = r"(?:corner|side|part|portion|end|half|area|section|edge)\b"
_ROOMS = r"R\d+(?:\s*(?:,|and|&|as well as|plus)\s*(?:the\s+)?R\d+)*"
_ROOMSEQ = re.compile(r"R(\d+)")
# "\b": a look-ahead after a direction must not see the word's last letters ("D:south of" is no
# "D:sout" followed by "h of")
_D = r"D:(\w+)\b"
# ("D:north, D:east, and D:south": a list with its last comma before "and")
_DD = r"D:(\w+)\b(?:\s*(?:,\s*and|,|and|&|or|/)\s*(?:the\s+)?D:(\w+)\b)*"
_ART = r"(?:\s+(?:the|its|it's|it|his|her|their|a|your|our|my))?"

_SIZE_UNIT = r"(?:'|feet|foot|ft\.?|m|meters?|metres?|mtrs?|\"|inches)?"
_NUM_RE = r"(\d+(?:\.\d+)?)"


def _dirs(m: re.Match[str], text: str) -> list[str]:
    return re.findall(r"D:(\w+)", text[m.start() : m.end()])


def _relation(d: str) -> str:
    return f"{d}_of"


def _read_clause(clause: _Clause, mentions: list[RoomMention]) -> list[Statement]:
    text = clause.text
    assert clause.subject is not None
    subj = mentions[clause.subject]
    out: list[Statement] = []
    used: list[tuple[int, int]] = []

    def free(a: int, b: int) -> bool:
        return all(b <= u0 or a >= u1 for u0, u1 in used)

    def rooms_in(span: str) -> tuple[RoomMention, ...]:
        return tuple(mentions[int(k)] for k in _ROOMSEQ.findall(span) if int(k) != clause.subject)

    def add(kind: str, m: re.Match[str], subject: RoomMention | None = None, **kw: object) -> None:
        used.append((m.start(), m.end()))
        out.append(Statement(subject=subj if subject is None else subject, kind=kind, text=_plain(m.group(0), mentions), **kw))  # type: ignore[arg-type]

    def around(m: re.Match[str], others: Sequence[RoomMention], directions: Sequence[str]) -> None:
        # ``others`` lie on those sides of the subject ("with the R1 to the D:south"); the
        # match's span is read
        used.append((m.start(), m.end()))
        out.extend(
            Statement(subject=o, kind="relation", relation=_relation(d), others=(subj,), text=_plain(m.group(0), mentions))
            for d in directions if d != "centre" for o in others
        )

    # 0. A part of another room or a room set into a corner:
    # - a part of another room, "in the R1's D:southwest corner": the subject lies toward that
    #   side of it (a store in the corner of a bedroom);
    for m in re.finditer(r"\b(?:in|at|on|into|inside|within)\s+(?:the\s+)?(R\d+)(?:\s*'?s|\s+rooms?)?\s+D:(\w+)\s+" + _OWN_PART, text):
        others = rooms_in(m.group(1))
        if others and m.group(2) != "centre":
            add("relation", m, relation=_relation(m.group(2)), others=others)
    # - another room set into a corner, "with the R1 inset at the D:southwest corner": its position;
    for m in re.finditer(r"(R\d+)\s+(?:is\s+|being\s+)?(?:inset|tucked|set)\s+(?:in|at|into)\s+(?:the\s+)?D:(\w+)", text):
        others = rooms_in(m.group(1))
        if others and free(m.start(), m.end()):
            used.append((m.start(), m.end()))
            out.extend(Statement(subject=o, kind="position", direction=m.group(2), text=_plain(m.group(0), mentions)) for o in others)
    # - another room then where it is, "opposite the R1, which is on the D:north side of the plan":
    #   the position of R1, not of the subject;
    for m in re.finditer(
        r"(R\d+)\s*,?\s*which\s+(?:is|lies|sits)\s+(?:located\s+|situated\s+)?(?:in|on|at)\s+(?:the\s+)?(?:" + _DD + r")(?:\s+" + _PART + r")?",
        text,
    ):
        others = rooms_in(m.group(1))
        if others and free(m.start(), m.end()):
            used.append((m.end(1), m.end()))  # the room itself stays free for "opposite the R1"
            out.extend(
                Statement(subject=o, kind="position", direction=d, text=_plain(m.group(0), mentions))
                for o in others for d in _dirs(m, text)
            )
    # 1. "between R1 and R2"
    for m in re.finditer(r"\b(?:in\s+)?between\s+(?:of\s+|in\s+)?(?:the\s+)?(" + _ROOMS + ")", text):
        others = rooms_in(m.group(1))
        # "between the R1 to the D:north, R2 to the D:east, ...": a list of rooms each on its
        # side of the subject (read below), not one room it is next to
        # ("between the R1 on the D:northwest corner of the home, and R2" is a room between two)
        side = re.match(r"\s+(?:is\s+)?(?:to|on|at|in)" + _ART + r"\s+D:\w+\b(?!(?:\s+" + _PART + r")?\s+(?:of|in)\s+(?:the\s+)?" + _PLACE + r")", text[m.end():])
        if len(others) == 1 and side:
            continue
        if others and free(m.start(), m.end()):
            # "R0 has a R1 on its D:north side, in between of R2 and R3": said of R1
            had = re.search(r"\b(?:has|have|contains|includes)\s+(?:a|an|the|one)?\s*R(\d+)\b[^R]*$", text[: m.start()])
            who = mentions[int(had.group(1))] if had and int(had.group(1)) != clause.subject else None
            add("relation", m, subject=who, relation="between" if len(others) > 1 else "next_to", others=tuple(o for o in others if o is not who))

    # 2. The subject relative to another room: "D:west of R1", "to the D:north of R1",
    # "on D:east side of R1", "D:upside of R1", "above R1", "R1's D:north side".
    pat = (
        r"(?:\b(?:to|on|at|in|towards|toward)" + _ART + r"\s+)?(?:" + _DD + r")(?:\s+(?:" + _PART + r"|wall))?\s+(?:of|from)"
        + _ART + r"\s+(" + _ROOMS + r")"
    )
    for m in re.finditer(pat, text):
        others = rooms_in(m.group(m.lastindex or 0))
        if not others or not free(m.start(), m.end()):
            continue
        # "with the R3 to the D:south of the R1": said of R3, not of the subject
        placed = re.search(
            r"(?:^|\bwith\s+|,\s*|\band\s+)(?:the\s+|a\s+|an\s+)?R(\d+)(?:\s+(?:is|are|lies|sits|located|situated|just|directly|immediately|also))*\s*$",
            text[: m.start()],
        )
        who = mentions[int(placed.group(1))] if placed and int(placed.group(1)) != clause.subject else subj
        for d in _dirs(m, text[: m.start(m.lastindex or 0)] + " " * (m.end() - m.start(m.lastindex or 0))):
            add("relation", m, subject=who, relation="between" if d == "centre" else _relation(d), others=others)
    for m in re.finditer(r"\b(above|over|upside of|below|beneath|under|underneath|downside of|behind)\s+(?:the\s+)?(" + _ROOMS + ")", text):
        others = rooms_in(m.group(2))
        if others and free(m.start(), m.end()):
            d = "north" if m.group(1) in ("above", "over", "upside of") else "south"
            if m.group(1) == "behind":
                continue
            add("relation", m, relation=_relation(d), others=others)
    for m in re.finditer(r"\bD:(\w+)\s+(?:of|to)\s+(" + _ROOMS + ")", text):  # "D:east to R1" (loose)
        others = rooms_in(m.group(2))
        if others and free(m.start(), m.end()):
            add("relation", m, relation=_relation(m.group(1)) if m.group(1) != "centre" else "between", others=others)

    # 3. Another room relative to the subject: "with R1 to the D:south", "R1 is to its D:west",
    # "R1 on its D:right", "to the D:north is R1", "D:north is R1", "R1 D:below" (run-on style).
    # "to its D:north is the R1 and the R2 to its D:east": the first room on the first side, the
    # others on the second (not all of them to the D:east, as the list alone reads)
    two_sides = (
        r"\bto" + _ART + r"\s+(?:" + _DD + r")\s+(?:is|are)\s+(?:the\s+|a\s+|an\s+)?(?P<first>R\d+)\s+and\s+(?:the\s+|a\s+|an\s+)?"
        r"(?P<rest>" + _ROOMS + r")(?:\s+(?:is|are|lies|lie|sits))?\s+(?:to|on|at)" + _ART + r"\s+(?:" + _DD + r")(?!\s+(?:of|from)\b)"
    )
    for m in re.finditer(two_sides, text):
        if not free(m.start(), m.end()):
            continue
        for span, d_span in ((m.group("first"), text[m.start() : m.start("first")]), (m.group("rest"), text[m.end("rest") : m.end()])):
            around(m, rooms_in(span), re.findall(r"D:(\w+)", d_span))
    pat_after = (
        r"(" + _ROOMS + r")(?:\s+(?:is|are|lies|lie|sits|located|situated|just|directly|immediately|also|both))*"
        r"(?:\s+(?:to|on|at|in|towards|toward|along)" + _ART + r"(?:\s+both)?|(?P<bare>\s+the))?\s+(?:" + _DD + r")(?!\s+(?:of|from)\b)"
        r"(?:\s+(?:side|end|edge|wall|corner|direction)(?!\s+of\b))?"
    )
    for m in re.finditer(pat_after, text):
        others = rooms_in(m.group(1))
        if not others or not free(m.start(), m.end()):
            continue
        # "bordered by R1 the D:north and R2 to its D:west": a "to" left out, in a list of rooms
        # around the subject only
        if m.group("bare") and (
            not re.search(r"(?:\bby|\bwith|\band|,)\s+(?:the\s+|a\s+|an\s+)?$", text[: m.start()])
            or m.start("bare") != m.end(1)
        ):
            continue
        # "next to the R1 on the D:south end of the plan": a part of the plan, where the subject
        # is (unless R1 was listed, "with the R1 in the D:north part of the house", or is the
        # subject of its own verb, "R1 is in the D:northwest corner of the plan")
        if (
            re.match(r"(?:\s+" + _PART + r")?\s+(?:of|in)\s+(?:the\s+)?" + _PLACE, text[m.end():])
            and not re.search(r"\bwith\s+(?:the\s+|a\s+|an\s+)?$", text[: m.start()])
            and not re.search(r"\b(?:is|are|lies|lie|sits|located|situated)\b", m.group(0))
        ):
            continue
        # "R1 D:north D:corner" style clauses (a room then a position of the plan) are positions
        # of the plan when followed by "of the house": the negative look-ahead handled "of".
        # "with the R1 in the D:west": "in" names a part of the plan too (the room is there as
        # well as to that side of the subject); "to"/"on" only the side of the subject
        inside = re.search(r"\bin(?:\s+(?:the|its|it's|it|his|her|their|a))?\s+D:", m.group(0)) is not None
        for d in _dirs(m, text):
            if d == "centre":
                continue
            for o in others:
                out.append(Statement(subject=o, kind="relation", relation=_relation(d), others=(subj,), text=_plain(m.group(0), mentions)))
                if inside:
                    out.append(Statement(subject=o, kind="position", direction=d, text=_plain(m.group(0), mentions)))
        used.append((m.start(), m.end()))
    # "R1 and R2 are across from it, on its D:south side": they lie on that side of the subject
    for m in re.finditer(
        r"(" + _ROOMS + r")\s+(?:is|are)\s+(?:directly\s+|just\s+)?(?:across\s+from|opposite(?:\s+to)?|next\s+to|beside|adjacent\s+to|near)\s+it\s*,?\s*"
        r"(?:on|to|at)\s+(?:its|it's)\s+(?:" + _DD + r")(?:\s+(?:side|end))?",
        text,
    ):
        others = rooms_in(m.group(1))
        if others and free(m.start(), m.end()):
            around(m, others, _dirs(m, text))
    # "with the R1 above and R2 to the D:west": R1 north of the subject ("above R2" is read above)
    for m in re.finditer(r"(" + _ROOMS + r")(?:\s+(?:is|are|lies|sits|just|directly|immediately))*\s+(above|below|beneath|underneath)\b(?!\s+(?:the\s+|a\s+)?R\d)", text):
        others = rooms_in(m.group(1))
        if others and free(m.start(), m.end()):
            around(m, others, ["north" if m.group(2) == "above" else "south"])
    # "connects to it on the D:northwest with the R1, on the D:east with R2": R1 on that side of
    # the subject, as "on the D:south to the R3" after a verb of connecting ("R0 is on the D:east
    # side with R1 to the D:north" places the subject, and R1 has a side of its own)
    with_side = (
        r"\b(?:on|at)\s+(?:the|its|it's)\s+(?:" + _DD + r")(?:\s+(?:sides?|ends?|walls?))?\s+(?P<link>with|to)\s+(?:the\s+|a\s+|an\s+)?(?P<rooms>" + _ROOMS + r")"
    )
    for m in re.finditer(with_side, text):
        others = rooms_in(m.group("rooms"))
        if not others or not free(m.start(), m.end()):
            continue
        if re.search(r"\b(?:is|are|was|were|located|situated|lies|lie|sits|placed|positioned)\s+$", text[: m.start()]):
            continue
        if m.group("link") == "to" and not re.search(r"\b(?:conn?ects?|conn?ected|conn?ecting|opens?|leads?)\b", text[: m.start()]):
            continue
        if re.match(r"(?:\s+(?:is|are|lies|lie|sits))?\s+(?:(?:to|on|at|in)" + _ART + r"\s+)?D:", text[m.end():]):
            continue
        around(m, others, _dirs(m, text))
    # "surrounded on the D:north and D:east sides by R1": R1 lies on those sides of the subject
    by_sides = r"\b(?:on|to|at)" + _ART + r"\s+(?:" + _DD + r")(?:\s+(?:sides?|ends?|edges?|walls?))?\s+by\s+(?:the\s+)?(" + _ROOMS + ")"
    # ("..., and D:north is the R1": the "to the" left out after a list's comma or "and")
    pat_before = r"(?:\b(?:to|on|at)" + _ART + r"\s+|(?:^|,|\band)\s*)(?:" + _DD + r")(?:\s+(?:side|end|wall))?(?:\s+(?:of|from)\s+(?:it|this\s+room|the\s+room))?\s*(?:,\s*)?(?:is|are|lies|lie|sits|you\s+have|you'll\s+find|there\s+is|there\s+are)\s+(?:the\s+)?(" + _ROOMS + ")"
    # "facing on its D:east the R1": the verb left out after the subject's own side
    on_its = r"\bon\s+(?:its|it|it's|their)\s+(?:" + _DD + r")(?:\s+(?:side|end))?\s+(?:the\s+|a\s+|an\s+)?(" + _ROOMS + ")"
    for pattern in (by_sides, pat_before, on_its):
        for m in re.finditer(pattern, text):
            others = rooms_in(m.group(m.lastindex or 0))
            if not others or not free(m.start(), m.end()):
                continue
            around(m, others, _dirs(m, text))

    # 4. Exterior walls: "D:south wall is exterior", "exterior to the D:north, D:east", "outside
    # wall(s) to the D:east and D:west", "house exterior to the D:west".
    for m in re.finditer(r"(?:" + _DD + r")\s+(?:wall|walls|side)\s+(?:is|are)\s+(?:an?\s+)?(?:the\s+)?(?:exterior|outside|external)", text):
        if free(m.start(), m.end()):
            for d in _dirs(m, text):
                add("exterior", m, direction=d)
    # "is (the) entrance from the D:north side", "the entrance is on the D:west side": the front
    # door is in that wall of the room, an outside wall
    for m in re.finditer(r"\b(?:entrance|entry|front\s+door|main\s+door)\s+(?:is\s+)?(?:from|on|at|to|of)\s+(?:the\s+)?(?:" + _DD + r")\s+(?:side|wall)\b", text):
        if free(m.start(), m.end()):
            for d in _dirs(m, text):
                if d != "centre":
                    add("exterior", m, direction=d)
    # "a small D:south exterior wall", "the D:north and D:east exterior walls", "to the D:west is
    # the house exterior", "exterior walls on the D:east" (each pattern in turn, as the spans it
    # takes are not free for the next)
    for pattern in (
        r"(?:" + _DD + r")\s+(?:exterior|outside|external)\s+walls?\b",
        r"(?:to\s+the\s+)?(?:" + _DD + r")\s+(?:is|are)\s+(?:the\s+)?(?:house\s+|unit\s+|building\s+)?(?:exterior|outside)",
        r"(?:exterior|outside|external)(?:\s+walls?)?(?:\s+(?:is|are|on|to|at|of|both|the))*\s+(?:" + _DD + r")",
    ):
        for m in re.finditer(pattern, text):
            if free(m.start(), m.end()):
                for d in _dirs(m, text):
                    if d != "centre":
                        add("exterior", m, direction=d)

    # 5. Other adjacency words: next to, near, adjacent, beside, across from, opposite, facing.
    adjacency = (
        r"\b(next\s+to|nearby|near\s+by|near\s+to|near|adjacent\s+to|adjacent|adjoining|adjoined\s+by|adjoins|beside|by\s+the\s+side\s+of|"
        r"off(?:\s+of)?|inside(?:\s+of)?|within|"
        r"bordered\s+by|borders|neighbou?red\s+by|shares\s+(?:a\s+)?walls?\s+with|conn?ects?\s+(?:to|with)|conn?ected\s+(?:to|with)|"
        r"attached\s+to|access(?:ed|ible)?\s+(?:from|through|via|by)|touching|opens?\s+(?:in)?to|entrance\s+from|accessible\s+from|"
        r"leads?\s+(?:in)?to|surrounded\s+by|joined\s+to|joins|touches|meets|along\s+with|after|en\s*suite\s+to|"
        r"across\s+from|opposite(?:\s+(?:to|of))?|facing|faces|in\s+front\s+of|overlooks?)"
        r"(?:\s+(?:the|both|all|a|an))*\s+(" + _ROOMS + ")"
    )
    for m in re.finditer(adjacency, text):
        others = rooms_in(m.group(2))
        if not others or not free(m.start(), m.end()):
            continue
        word = m.group(1)
        across = bool(re.match(r"across|opposite|facing|faces|in\s+front|overlook", word))
        add("relation", m, relation="across_from" if across else "next_to", others=others)

    # 6a. Compass words left that are not where the subject is (after the relations, which
    # read "R1 on its D:right side"):
    # - a direction of extent, "the long side running D:north to D:south", "extends from D:east
    #   to D:west": how the room lies, not where;
    # - a part of the subject itself, "its D:northwest corner", "a small portion in the D:northeast
    #   corner", "extensions to the D:west and D:east": where its notches or bays are.
    for pattern in (
        r"(?:\b(?:from|running|runs|run|runing|oriented|extends?|extending|stretch(?:es|ing)?|goes|going|spans?|spanning)\s+(?:\w+\s+){0,2}?)"
        r"D:\w+\s*(?:to|-|/|through|towards?)\s*(?:the\s+)?D:\w+",
        # "at D:east to D:west direction": along that line, not at either end
        r"\b(?:D:east\s+to\s+(?:the\s+)?D:west|D:west\s+to\s+(?:the\s+)?D:east|D:north\s+to\s+(?:the\s+)?D:south|D:south\s+to\s+(?:the\s+)?D:north)\s+direction\b",
        r"\b(?:its|it's|their|his|her)\s+(?:own\s+)?" + _DD + r"\s+" + _OWN_PART,
        # "with the R1 inset to the D:northeast corner": a corner of the subject another room takes
        r"\bR\d+\s+(?:is\s+|being\s+)?(?:inset|tucked|set)\s+(?:to|towards?)\s+(?:the\s+|its\s+)?" + _DD,
        r"\b(?:(?:small|little|tiny|narrow)\s+(?:portions?|parts?|spaces?|areas?|sections?)|extensions?|alcoves?|nooks?"
        r"|knock\s*outs?|notch(?:es)?|cut\s*outs?)\b"
        r"(?:\s+(?:\w+|,)){0,4}?\s+" + _DD,
    ):
        for m in re.finditer(pattern, text):
            if free(m.start(), m.end()):
                used.append((m.start(), m.end()))

    # 6. Positions of the subject in the plan: whatever compass word is left.
    rest = list(text)
    for a, b in used:
        rest[a:b] = " " * (b - a)
    rest_text = "".join(rest)
    # "D:north D:centre" / "D:centre of the D:east portion": a side and its middle
    for m in re.finditer(r"D:(\w+)", rest_text):
        d = m.group(1)
        before = rest_text[max(0, m.start() - 40) : m.start()]
        after = rest_text[m.end() : m.end() + 80]
        # facing/entrance words say where a door or window looks, which is the room's side too;
        # "D:south wall" alone (no exterior word) is a wall of the room, not its position.
        # ("at the D:north wall", "along the D:west wall": the room is at that wall of the plan)
        if (
            re.match(r"\s+(?:wall|walls|door|entrance|entry|window)\b", after)
            and not re.match(r"\s+wall\s+of\s+(?:the\s+)?" + _PLACE, after)
            and not (
                re.match(r"\s+walls?\b", after)
                and re.search(r"\b(?:at|on|along|against|by)\s+(?:the\s+)?(?:very\s+|far\s+)?$", before)
                and not re.search(r"\b(?:door|doorway|entry|entrance|window|opening)\b", rest_text[: m.start()])
            )
        ):
            continue
        if re.search(r"\b(?:door|entry|entrance|window|opening)\s+(?:\w+\s+){0,3}$", before):
            continue
        if re.match(r"\s+(?:of|from)\s+(?:the\s+)?R\d+", after):  # relation left over (e.g. to itself)
            continue
        # "D:south of that is ...": beside something named before, not where the subject is
        if re.match(r"\s+(?:of|from)\s+(?:that|this|which|those|these|them)\b", after):
            continue
        # "to the D:northeast is the main entry alcove": a thing beside the subject (a room there
        # is read as a relation above), not where the subject is
        if re.search(r"\bto\s+(?:the|its|it's|their)\s+$", before) and re.match(r"(?:\s*(?:,\s*and|,|and|&)\s*D:\w+)*\s+(?:is|are|lies|lie|sits)\b", after):
            continue
        # dimensions ("the north and south side length is 3 feet") and doors are not positions
        if re.match(r"(?:\s*(?:and|,|&)\s*D:\w+)*\s+(?:sides?\s+)?(?:length|lenght|width|measures?|dimension)", after):
            continue
        # "the D:north side is 10 feet", "D:west side- 20 feet", "the D:east and D:west are 2
        # feet": the length of a side of the room
        if re.match(r"(?:\s*(?:and|,|&)\s*D:\w+)*(?:\s+(?:sides?|walls?|edges?|ends?))?\s*(?:is|are|measures?|measuring|-|=|:)\s*"
                    r"(?:about\s+|approximately\s+|around\s+|roughly\s+|only\s+)?\d+(?:\.\d+)?\s*(?:'|feet|foot|ft\b|m\b|meters?|metres?|inch)", after):
            continue
        if re.match(r"\s+(?:of|from)\s+(?:the\s+)?(?:main\s+|front\s+)?(?:door|entrance|entry|doorway)", after):
            continue
        if re.match(r"(?:\s*(?:and|,)\s*D:\w+)*\s+(?:facing\s+)?(?:front\s+|main\s+)?(?:door|entrance|entry)", after):
            continue
        out.append(Statement(subject=subj, kind="position", direction=d, text=_plain(text[max(0, m.start() - 20) : m.end() + 25], mentions)))

    # 7. Sizes.
    out.extend(_sizes(text, subj, mentions))
    return _merge_positions(out)


def _merge_positions(found: list[Statement]) -> list[Statement]:
    """Combine a clause's bare position words, room by room: "D:north D:east" → northeast;
    "D:centre" with a side keeps the side; the same direction twice is said once."""
    rooms = list(dict.fromkeys(s.subject for s in found if s.kind == "position"))
    if len(rooms) > 1:
        each = [_merge_positions([s for s in found if s.kind == "position" and s.subject == room]) for room in rooms]
        return [s for s in found if s.kind != "position"] + [s for said in each for s in said]
    positions = [s for s in found if s.kind == "position"]
    if any(s.direction != "centre" for s in positions):
        # "the north centre", "centre of the east side": the middle of a side is that side
        found = [s for s in found if not (s.kind == "position" and s.direction == "centre")]
        positions = [s for s in found if s.kind == "position"]
    if len(positions) < 2:
        return found
    dirs = [s.direction for s in positions]
    kept: list[Statement] = []
    seen: set[str] = set()
    merged: list[str] = []
    i = 0
    while i < len(dirs):
        d = dirs[i]
        if i + 1 < len(dirs):
            combined = _combine(d, dirs[i + 1])
            if combined is not None and positions[i + 1].text.find(positions[i].text[-10:]) >= -1:
                merged.append(combined)
                i += 2
                continue
        merged.append(d)  # type: ignore[arg-type]
        i += 1
    for d, s in zip(merged, positions):
        if d in seen:
            continue
        seen.add(d)
        kept.append(Statement(subject=s.subject, kind="position", direction=d, text=s.text))
    return [s for s in found if s.kind != "position"] + kept


def _combine(a: str | None, b: str | None) -> str | None:
    if a in ("north", "south") and b in ("east", "west"):
        return f"{a}{b}"
    if a in ("east", "west") and b in ("north", "south"):
        return f"{b}{a}"
    return None


def _unit(word: str | None, text: str) -> float:
    w = (word or "").strip().lower()
    if w.startswith("m") and not w.startswith("mm"):
        return 1.0
    if re.search(r"\b(?:metres?|meters?|m2|m²|sq\.?\s*m|square\s+met)", text):
        return 1.0
    return _FEET


#: Whether a width and depth given without words ("10 x 12", "ten feet by five feet") are read
#: as across the plan (east-west) first, as a drawing's dimensions are written.
ORIENT_BY_ORDER = True


def _sizes(text: str, subj: RoomMention, mentions: list[RoomMention]) -> list[Statement]:
    out: list[Statement] = []
    spans: list[tuple[int, int]] = []
    dim = (
        _NUM_RE + r"\s*(" + _SIZE_UNIT + r")\s*(?:(wide|width|in\s+width|long|length|in\s+length|deep|depth|in\s+depth|tall|high|[lw](?=\s))\s*)?"
        r"(?:x|by|\*|:|×|and)\s*(?:a\s+)?" + _NUM_RE + r"\s*(" + _SIZE_UNIT + r")\s*"
        r"(?:(wide|width|in\s+width|long|length|in\s+length|deep|depth|in\s+depth|tall|high|[lw])\b)?"
    )
    for m in re.finditer(dim, text):
        a, b = float(m.group(1)), float(m.group(4))
        if a <= 0 or b <= 0 or a > 300 or b > 300:
            continue
        unit = _unit(m.group(2) or m.group(5), text)
        # "12 ft L by 6 ft W": the letters are the words
        letters = {"l": "long", "w": "wide"}
        first, second = ((g or "").replace("in ", "").strip() for g in (m.group(3), m.group(6)))
        first, second = letters.get(first, first), letters.get(second, second)
        # a floor plan's dimensions are given across the drawing first, then up it ("10 x 12",
        # "12 feet length and 4 feet width"); only the adjectives "wide" against "deep", "long",
        # "tall" turn them round ("4 feet long and 12 feet wide": 12 across)
        swapped = first in ("deep", "depth", "tall", "high", "long") and second in ("wide", "width")
        w, d = (b, a) if swapped else (a, b)
        spans.append((m.start(), m.end()))
        out.append(Statement(subject=subj, kind="size", width=w * unit, depth=d * unit, oriented=ORIENT_BY_ORDER or bool(first or second), text=_plain(m.group(0), mentions)))
    # the length of a side of the room: "the D:north and D:south side length is 3 feet", "D:east
    # wall- 12-feet", "the D:east and D:west are 2 feet": the D:north and D:south sides run across
    # the plan, so their length is the room's width, the D:east and D:west sides' its depth (one
    # axis a clause; :func:`_join_sides` joins a room's clauses into one size)
    side = (
        r"((?:D:\w+)(?:\s*(?:,|and|&)\s*(?:the\s+)?D:\w+)*)(?:\s+(?:sides?|walls?|edges?))?\s*(?:lengths?)?\s*"
        r"(?:is|are|measures?|measuring|-|=|:)\s*(?:about\s+|approximately\s+|around\s+|roughly\s+|only\s+)?"
        + _NUM_RE + r"\s*-?\s*('|\"|(?:feet|foot|ft|m|meters?|metres?|mtrs?)\b)(?!\s*(?:x|by|\*|×)\s*\d)"
    )
    for m in re.finditer(side, text):
        value = float(m.group(2))
        dirs = set(re.findall(r"D:(\w+)", m.group(1)))
        if not 0 < value <= 300 or not dirs <= {"north", "south", "east", "west"}:
            continue
        unit = _unit(m.group(3), text)
        across, up = dirs & {"north", "south"}, dirs & {"east", "west"}
        spans.append((m.start(), m.end()))
        out.append(Statement(
            subject=subj, kind="size", width=value * unit if across else None, depth=value * unit if up else None,
            oriented=True, text=_plain(m.group(0), mentions),
        ))
    if not out:
        # "8 feet in width and 6 feet in length", "10 feet width and 12 feet length"
        pair = re.search(_NUM_RE + r"\s*(" + _SIZE_UNIT + r")\s*(?:in\s+)?(width|wide|length|long)\b.{0,30}?" + _NUM_RE + r"\s*(" + _SIZE_UNIT + r")\s*(?:in\s+)?(width|wide|length|long|depth|deep)\b", text)
        if pair:
            a, b = float(pair.group(1)), float(pair.group(4))
            unit = _unit(pair.group(2) or pair.group(5), text)
            spans.append((pair.start(), pair.end()))
            out.append(Statement(subject=subj, kind="size", width=a * unit, depth=b * unit, oriented=True, text=_plain(pair.group(0), mentions)))
    if not out:
        # the nouns before their numbers: "its length is about 11 feet and width is 6 feet",
        # "a length of 9 feet and width of 8", "the length is 8 feet and the width is 8 feet";
        # the nouns keep their order as above (the first across the drawing)
        said = r"(?:length|width)\s*(?:is|of|was|:|=)?\s*(?:about|approximately|approx\.?|around|roughly|nearly)?\s*"
        nouns = re.search(r"\b" + said + _NUM_RE + r"\s*(" + _SIZE_UNIT + r")\b.{0,40}?\b" + said + _NUM_RE + r"\s*(" + _SIZE_UNIT + r")(?!\w)", text)
        if nouns:
            a, b = float(nouns.group(1)), float(nouns.group(3))
            if 0 < a <= 300 and 0 < b <= 300:
                unit = _unit(nouns.group(2) or nouns.group(4), text)
                spans.append((nouns.start(), nouns.end()))
                out.append(Statement(subject=subj, kind="size", width=a * unit, depth=b * unit, oriented=True, text=_plain(nouns.group(0), mentions)))
    for m in re.finditer(_NUM_RE + r"\s*(?:square|sq\.?|sqrt|sqr)\s*(feet|foot|ft|meters?|metres?|m)\b|" + _NUM_RE + r"\s*(sqft|sq\.?ft|ft2|ft²|m2|m²|sqm)\b", text):
        if any(not (m.end() <= a or m.start() >= b) for a, b in spans):
            continue
        value = float(m.group(1) or m.group(3))
        unit_word = m.group(2) or m.group(4)
        scale = 1.0 if unit_word.startswith("m") or unit_word in ("m2", "m²", "sqm") else _FEET**2
        if value > 0:
            out.append(Statement(subject=subj, kind="size", area=value * scale, text=_plain(m.group(0), mentions)))
    if not out:
        said = re.search(r"\barea\s+(?:is|of)\s+(?:about\s+|approximately\s+|around\s+)?" + _NUM_RE, text)
        if said and float(said.group(1)) > 0:
            out.append(Statement(subject=subj, kind="size", area=float(said.group(1)) * _FEET**2, text=_plain(said.group(0), mentions)))
    return out


# -- resolving mentions to rooms ----------------------------------------------------------------


def _resolve(
    statements: list[Statement], unread: list[str], mentions: list[RoomMention], rooms: Sequence[KnownRoom]
) -> Reading:
    """Map each mention (type, number) to a known room id.

    Numbered mentions of a type take the type's rooms in order; ordinals of "bedroom" count the
    master bedroom first ("the second bedroom" is the first common room); an unnumbered mention
    of a type with several rooms is the first of them not otherwise named. Callers that can tell
    same-type rooms apart by other evidence (areas, adjacency) may re-map
    (:func:`mansion.planning.spatial_seeds.match_rooms`).
    """
    by_type: dict[str, list[str]] = {}
    for r in rooms:
        by_type.setdefault(r.room_type, []).append(r.id)
    keys: list[tuple[str, int | None]] = []
    for m in mentions:
        key = _canonical(m, by_type)
        if key not in keys:
            keys.append(key)
    resolved: dict[tuple[str, int | None], str] = {}
    for kind, ids in by_type.items():
        named = sorted({n for k, n in keys if k == kind and n is not None})
        unnamed = (kind, None) in keys
        # numbers in the text may skip ("bathroom 2" only) or start at 0: rank them
        taken: set[str] = set()
        for rank, n in enumerate(named):
            if rank < len(ids):
                resolved[(kind, n)] = ids[rank]
                taken.add(ids[rank])
        if unnamed:
            rest = [i for i in ids if i not in taken] or ids
            resolved[(kind, None)] = rest[0]
    reading = Reading(unread=unread, resolved=resolved)

    def canon(m: RoomMention) -> RoomMention:
        kind, n = _canonical(m, by_type)
        return RoomMention(kind, n, m.words)

    for s in statements:
        subj = canon(s.subject)
        rid = resolved.get(subj.key)
        if rid is None:
            reading.unresolved.append((s, f"no room of this plan is called {s.subject.words!r}"))
            continue
        others = tuple(canon(o) for o in s.others)
        missing = [o.words for o in others if o.key not in resolved]
        if missing:
            reading.unresolved.append((s, f"no room of this plan is called {', '.join(repr(w) for w in missing)}"))
            continue
        if any(resolved[o.key] == rid for o in others):
            continue  # a room relative to itself: "the master ... bathroom of the master" mixups
        reading.statements.setdefault(rid, []).append(
            Statement(
                subject=subj, kind=s.kind, text=s.text, direction=s.direction, relation=s.relation,
                others=others, width=s.width, depth=s.depth, area=s.area, oriented=s.oriented,
            )
        )
    return reading


def _canonical(m: RoomMention, by_type: dict[str, list[str]]) -> tuple[str, int | None]:
    """A mention's (type, number) among the known types: "bedroom"s become the master or common
    rooms, "second bedroom" counts the master first."""
    kind, n = m.room_type, m.number
    if kind == "bedroom":
        if "common_room" in by_type and "master_room" in by_type:
            if n is not None and re.search(r"\b(second|third|fourth|fifth|2nd|3rd|4th)\b", m.words):
                return ("common_room", n - 1 if n > 1 else None)
            if n is None and re.search(r"\b(other|another)\b", m.words):
                return ("common_room", None)
            return ("common_room", n)
        if "master_room" in by_type:
            return ("master_room", None if len(by_type["master_room"]) == 1 else n)
        if "common_room" in by_type:
            return ("common_room", n)
        if "bedroom" in by_type:
            return ("bedroom", n)
    if kind == "master_room" and len(by_type.get("master_room", [])) == 1:
        return (kind, None)
    if n is not None and len(by_type.get(kind, [])) <= 1:
        n = None  # "bathroom 1" when there is one bathroom
    return (kind, n)

