"""Naming rooms: from the words of a request ("a children's reading room", "a staff kitchen",
"a home cinema", "two operating theaters") to a room type the planners and the design table know.

The reading goes from the most to the least certain, and says which step answered:

1. ``synonym``: the last words of the phrase match a known way of naming a type
   (:data:`~mansion.planning.vocabulary.ROOM_SYNONYMS`, or a type's own name: "reading room",
   "nap room", "operating theatre");
2. ``spelling``: they are a close spelling of one (rapidfuzz, for "operating theater",
   "clasroom", "pharmacie");
3. ``head noun``: the phrase's head noun (its last word) names a kind of room
   (:data:`HEAD_NOUNS`: "a wine *cellar*" is a store, "a staff *kitchen*" a kitchen);
4. ``named``: the head noun only says it is a room ("a quiet *room*", "a prayer *space*"): the
   room keeps its own name and the general room's size.

A phrase with none of these ("two elevators", "a red roof", "large windows") is not a room.
In a home (the residential family), a room that public buildings size for a crowd takes its
domestic counterpart (:data:`HOME_COUNTERPARTS`: a home cinema is a family-room-sized media
room, a home gym a home gym, a home office a study), so a villa's "cinema" is not 60 m².
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from rapidfuzz import fuzz, process

from mansion.models.room_design import room_design
from mansion.planning.vocabulary import ROOM_SYNONYMS, ROOMS

__all__ = ["HEAD_NOUNS", "HOME_COUNTERPARTS", "RoomMatch", "match_room", "singular", "slug"]

#: Head nouns (a phrase's last word) that say which kind of room it is.
HEAD_NOUNS: dict[str, str] = {
    "kitchen": "kitchen", "kitchenette": "kitchenette", "pantry": "pantry", "office": "office",
    "lab": "laboratory", "laboratory": "laboratory", "studio": "art_room", "workshop": "art_room",
    "theatre": "assembly_hall", "theater": "assembly_hall", "auditorium": "assembly_hall",
    "cinema": "cinema", "hall": "assembly_hall", "lounge": "lounge", "bar": "bar", "pub": "bar",
    "cafe": "cafe", "café": "cafe", "canteen": "canteen", "cafeteria": "canteen",
    "restaurant": "restaurant", "shop": "shop", "store": "shop", "boutique": "shop",
    "salon": "shop", "kiosk": "shop", "library": "library", "gym": "gym", "pool": "pool_hall",
    "spa": "spa", "sauna": "spa", "bathroom": "bathroom", "toilet": "toilet",
    "toilets": "toilet", "closet": "walk_in_closet", "wardrobe": "walk_in_closet",
    "cellar": "storage", "storeroom": "storage", "depot": "storage", "nursery": "children_room",
    "playroom": "play_hall", "clinic": "consultation_room", "surgery": "operating_theatre",
    "garage": "garage", "den": "family_room", "conservatory": "family_room",
    "sunroom": "family_room", "bedroom": "bedroom", "suite": "suite", "ward": "ward",
    "classroom": "classroom", "dormitory": "bedroom", "laundry": "laundry", "archive": "archive",
    "gallery": "lounge", "chapel": "lounge", "boardroom": "board_room", "dining": "dining_room",
    "parking": "garage", "carport": "garage", "butcher": "butcher_counter",
    "deli": "butcher_counter", "counter": "butcher_counter", "desk": "reception",
    "pharmacy": "pharmacy", "dispensary": "pharmacy", "bakery": "bakery",
}

#: Head nouns that only say "a room": the room keeps its own name.
ROOM_WORDS = frozenset(
    {"room", "area", "space", "corner", "zone", "nook", "alcove", "centre", "center", "station", "bay", "unit", "lab"}
)

#: Rooms of a home sized like their public namesakes' counterparts (see the module doc).
HOME_COUNTERPARTS: dict[str, str] = {
    "gym": "home_gym", "cinema": "family_room", "assembly_hall": "family_room",
    "lounge": "family_room", "bar": "family_room", "pool_hall": "family_room", "spa": "bathroom",
    "library": "study", "reading_room": "study", "play_hall": "children_room",
    "art_room": "study", "music_room": "family_room", "office": "study", "private_office": "study",
    "open_office": "study", "restaurant": "dining_room", "canteen": "dining_room",
    "cafe": "dining_room", "dining_hall": "dining_room", "commercial_kitchen": "kitchen",
    "pantry": "kitchen", "guest_room": "guest_bedroom", "suite": "master_bedroom",
    "ward": "guest_bedroom", "classroom": "study", "shop": "study", "toilet": "wc",
    "meeting_room": "study", "conference_room": "family_room", "board_room": "family_room",
    "laboratory": "study", "sleep_room": "bedroom", "computer_lab": "study",
}
#: Largest minimum area (m²) a room may have in a home before it takes its counterpart.
HOME_MAX_MIN_AREA = 16.0

_FILLER = re.compile(
    r"\b(?:big|small|large|little|spacious|generous|cosy|cozy|new|modern|bright|nice|separate|"
    r"dedicated|proper|extra|additional|shared|own|its|their|his|her|the|an?)\b"
)


@dataclass(frozen=True)
class RoomMatch:
    """A phrase read as a room: the ``room_type`` built, the ``name`` as the request gave it
    (without counts and size words) and ``how`` it was read (see the module doc)."""

    room_type: str
    name: str
    how: str


def slug(text: str) -> str:
    """``"children's reading room"`` → ``children_reading_room``."""
    return re.sub(r"[^a-z0-9]+", "_", re.sub(r"'s\b|s'", "", text.lower())).strip("_")


def singular(word: str) -> str:
    """``studies`` → ``study``, ``theatres`` → ``theatre``, ``benches`` → ``bench``."""
    if word.endswith("ies") and len(word) > 4:
        return word[:-3] + "y"
    if re.search(r"(?:ch|sh|x|ss)es$", word):
        return word[:-2]
    if word.endswith("s") and not word.endswith("ss") and len(word) > 3:
        return word[:-1]
    return word


def _synonym(words: list[str]) -> str | None:
    """The type whose synonym (or own name) the last words are, longest match first ("laundry
    room" is a laundry when no type is called that)."""
    found = _synonym_of(words)
    if found is None and len(words) > 1 and words[-1] in ROOM_WORDS:
        found = _synonym_of(words[:-1])
    return found


def _synonym_of(words: list[str]) -> str | None:
    for k in range(min(4, len(words)), 0, -1):
        tail = " ".join(words[-k:])
        for room_type, names in ROOM_SYNONYMS:
            for w in names:
                if re.fullmatch(r"(?:" + w + r")(?:e?s)?", tail):
                    return room_type
        key = tail.replace(" ", "_")
        for cand in (key, key[:-1] if key.endswith("s") else key):
            if cand in ROOMS:
                return cand
    return None


def _choices() -> dict[str, str]:
    """Plain names (no regular-expression syntax) of every type, for close spellings."""
    out = {t.replace("_", " "): t for t in ROOMS}
    for room_type, names in ROOM_SYNONYMS:
        for w in names:
            if re.fullmatch(r"[a-z' -]+", w):
                out.setdefault(w, room_type)
    return out


_CHOICES = _choices()


def _spelling(words: list[str]) -> str | None:
    for k in range(min(3, len(words)), 0, -1):
        tail = " ".join(words[-k:])
        if len(tail) < 5:
            continue
        best = process.extractOne(tail, list(_CHOICES), scorer=fuzz.ratio, score_cutoff=86)
        if best is not None:
            return _CHOICES[best[0]]
    return None


def match_room(phrase: str, family: str = "") -> RoomMatch | None:
    """The room ``phrase`` names (None: it names no room), sized for a building of ``family``
    (``residential`` homes take :data:`HOME_COUNTERPARTS`)."""
    name = " ".join(_FILLER.sub(" ", phrase.lower()).split())
    words = re.findall(r"[a-zé&-]+", re.sub(r"'s\b|s'", "", name))
    if not words:
        return None
    words[-1] = singular(words[-1]) if _synonym(words) is None else words[-1]
    room_type, how = _synonym(words), "synonym"
    if room_type is None:
        room_type, how = _spelling(words), "spelling"
    if room_type is None:
        head = words[-1]
        if head in HEAD_NOUNS:
            room_type, how = HEAD_NOUNS[head], "head noun"
        elif head in ROOM_WORDS and len(words) > 1 or any(
            head.endswith(w) and len(head) > len(w) + 2 for w in ROOM_WORDS
        ):
            return RoomMatch(slug(" ".join(words)), name, "named")
    if room_type is None:
        return None
    if family == "residential" and (room_type in HOME_COUNTERPARTS or room_design(room_type).min_area > HOME_MAX_MIN_AREA):
        room_type = HOME_COUNTERPARTS.get(room_type, "family_room")
    return RoomMatch(room_type, name, how)
