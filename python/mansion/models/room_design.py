"""The room design table: what a room of each type needs to be usable (issue 14).

Every stage may read it (it lives in ``models``): the planners size rooms from it and fill
:attr:`mansion.models.RoomNode.min_width`, the solver receives those widths through the room graph,
and ``mansion eval realism`` measures generated and real plans against it.

Per room type, a :class:`RoomDesign` gives

- ``min_area`` (m²) and ``min_width`` (m, the narrowest clear width any part of the room may
  have);
- ``max_aspect``: the longest the room's bounding box should be against its width (rooms that
  are rectangles of about this proportion furnish well; circulation is exempt);
- ``corridor``: it needs a door to a corridor or other circulation room (not only through
  another room);
- ``daylight``: it needs a window (an exterior wall);
- ``own_bathroom``: it comes with a bathroom of its own (hotel guest rooms, wards);
- ``circulation``: it is circulation (corridors, halls, lobbies, balconies); such rooms are long
  by nature and, where people pass through them (``through``), take the building type's corridor
  width (:data:`CORRIDOR_WIDTH`, :func:`needed_width`);
- ``through``: circulation people pass through on their way elsewhere (a corridor, a hall, a
  lobby), held to the corridor width; a toilet lobby serves only the WCs cut from it and a balcony
  leads nowhere, so they keep their own table width (a toilet lobby 1.2 m, Approved Document M's
  lobby to a WC; a balcony 1.0 m).

Where the figures come from (the smaller of the usual values, so a compact but real room passes):

- dwellings: the UK Nationally Described Space Standard (2015) — single bedroom >= 7.5 m² and
  2.15 m wide, double bedroom >= 11.5 m² and 2.75 m (main) / 2.55 m wide; Neufert, *Architects'
  Data* (4th ed.), living, kitchen and bathroom chapters (kitchen run + 1.2 m working space, a
  bathroom about 1.7 m × 2.2 m, a WC compartment about 0.9 m × 1.5 m);
- sanitary rooms: ADA 2010 Standards §604 / §603 (a wheelchair WC compartment 1.525 m wide, a
  1.525 m turning circle), ISO 21542:2021 §35 and DIN 18040-1 (an accessible WC about
  1.5 m × 2.2 m clear), Approved Document M;
- offices: Metric Handbook (6th ed.), offices chapter (about 10 m² per cellular office, 2.4 m
  minimum width, phone booths about 1.2 m × 1.2 m);
- schools and kindergartens: UK DfE Building Bulletin 103 (a 30-pupil classroom 55–63 m²,
  practical rooms 80–100 m²), DIN 18040-1;
- health: UK Health Building Note 04-01 (a single bedroom with its ensuite 19 m², the ensuite
  4.5 m²), HBN 00-03 (consulting/examination room 16 m², treatment room 16–20 m², operating theatre
  40–55 m²), the US FGI Guidelines (ward corridors 2.44 m);
- hotels, restaurants, shops, libraries: Metric Handbook chapters on hotels (a standard guest
  room with bathroom 22–28 m², 3.3 m wide), restaurants (a commercial kitchen about a third of
  the dining area), retail and libraries;
- corridor widths: IBC 2021 §1020.2 (44 in = 1.12 m general, 72 in = 1.83 m in schools, 96 in =
  2.44 m in hospitals where beds are moved), ADA §403.5 / ISO 21542 §13 (1.5 m to pass a
  wheelchair), Approved Document M (1.2 m in homes built for access).

Room types are open vocabulary: :func:`room_design` normalises the name ("Master Bedroom 2" →
``master_bedroom``), tries aliases and words it contains, then a close spelling
(:func:`difflib.get_close_matches`), and otherwise gives :data:`DEFAULT_DESIGN`.
"""

from __future__ import annotations

import difflib
import functools
import re
from dataclasses import dataclass

__all__ = [
    "CORRIDOR_TYPES",
    "CORRIDOR_WIDTH",
    "DEFAULT_CORRIDOR_WIDTH",
    "DEFAULT_DESIGN",
    "ELONGATED_ASPECT",
    "ROOM_DESIGN",
    "RoomDesign",
    "SANITARY_TYPES",
    "corridor_width",
    "design_key",
    "needed_width",
    "planned_width",
    "room_design",
]


#: Longest side of a room's bounding box over its shortest beyond which a room that is not
#: circulation counts as elongated (issue 14's measure; the table's ``max_aspect`` is the preferred
#: proportion, this the limit).
ELONGATED_ASPECT = 3.0


@dataclass(frozen=True)
class RoomDesign:
    """What one room type needs; see the module doc for the fields and their sources."""

    min_area: float
    min_width: float
    max_aspect: float = 2.5
    corridor: bool = False
    daylight: bool = False
    own_bathroom: bool = False
    circulation: bool = False
    through: bool = False


def _room(area: float, width: float, aspect: float = 2.5, *, corridor: bool = False,
          daylight: bool = False, bathroom: bool = False) -> RoomDesign:
    return RoomDesign(area, width, aspect, corridor, daylight, bathroom)


def _circ(area: float, width: float, *, through: bool = True) -> RoomDesign:
    return RoomDesign(area, width, 12.0, circulation=True, through=through)


#: The design table, by canonical room type (the offline planner's vocabulary, the LLM prompts'
#: examples and the RPLAN classes of the reference plans).
ROOM_DESIGN: dict[str, RoomDesign] = {
    # circulation (widths here are floors; corridors take the building type's width)
    "corridor": _circ(4.0, 1.1),
    "ward_corridor": _circ(8.0, 2.4),
    "hallway": _circ(2.5, 1.0),
    "landing": _circ(3.0, 1.1),
    "entrance_hall": _circ(4.0, 1.2),
    "entrance": _circ(2.0, 1.0),
    "foyer": _circ(5.0, 1.5),
    "lobby": _circ(15.0, 2.4),
    "atrium": _circ(30.0, 3.0),
    "concourse": _circ(30.0, 3.0),
    "entrance_vestibule": _circ(4.0, 1.5),
    "toilet_lobby": _circ(2.5, 1.2, through=False),
    # a room's own entrance lobby, with the door of its ensuite (a guest room's, a ward's): no
    # one passes through it to elsewhere (Metric Handbook, hotels: guest room entries 1.1-1.4 m)
    "entry_lobby": _circ(2.0, 1.2, through=False),
    "waiting_area": _circ(10.0, 2.4),
    "back_of_house": _circ(5.0, 1.2),
    "balcony": _circ(2.0, 1.0, through=False),
    # dwelling (NDSS, Neufert)
    "living_room": _room(13.0, 3.0, 2.5, daylight=True),
    "studio_room": _room(13.0, 3.0, 2.5, daylight=True),
    "unit_living": _room(13.0, 3.0, 2.5, daylight=True),
    "family_room": _room(11.0, 2.8, 2.5, daylight=True),
    "dining_room": _room(7.0, 2.4, 2.5, daylight=True),
    "kitchen": _room(5.5, 1.8, 3.0, daylight=True),
    "kitchenette": _room(3.0, 1.5, 3.0),
    "master_bedroom": _room(11.5, 2.75, 2.2, corridor=True, daylight=True),
    "master_room": _room(11.5, 2.75, 2.2, corridor=True, daylight=True),
    "bedroom": _room(7.5, 2.15, 2.2, corridor=True, daylight=True),
    "common_room": _room(7.5, 2.15, 2.2, corridor=True, daylight=True),
    "children_room": _room(7.5, 2.15, 2.2, corridor=True, daylight=True),
    "guest_bedroom": _room(7.5, 2.15, 2.2, corridor=True, daylight=True),
    "bathroom": _room(3.5, 1.5, 2.5, corridor=True),
    "ensuite": _room(3.0, 1.4, 2.5),
    "wc": _room(1.4, 0.9, 2.5, corridor=True),
    "walk_in_closet": _room(2.5, 1.2, 3.0),
    "laundry": _room(3.0, 1.5, 3.0, corridor=True),
    "storage": _room(2.0, 1.0, 3.0),
    "study": _room(6.5, 2.1, 2.5, corridor=True, daylight=True),
    "garage": _room(15.0, 3.0, 2.5),
    "home_gym": _room(9.0, 2.5, 2.5, daylight=True),
    "mail_room": _room(4.0, 1.8, 3.0, corridor=True),
    "bike_storage": _room(6.0, 2.0, 3.0, corridor=True),
    "refuse_room": _room(4.0, 1.8, 3.0, corridor=True),
    # work (Metric Handbook, offices)
    "reception": _room(9.0, 2.4, 3.0),
    "open_office": _room(30.0, 4.0, 3.0, daylight=True),
    "private_office": _room(8.0, 2.4, 2.5, corridor=True, daylight=True),
    "office": _room(8.0, 2.4, 2.5, corridor=True, daylight=True),
    "meeting_room": _room(10.0, 2.7, 2.5, corridor=True),
    "board_room": _room(20.0, 3.6, 2.5, corridor=True, daylight=True),
    "conference_room": _room(20.0, 3.6, 2.5, corridor=True),
    "phone_booth": _room(1.5, 1.2, 2.0),
    "print_room": _room(3.5, 1.5, 3.0),
    "server_room": _room(5.0, 2.0, 3.0, corridor=True),
    "pantry": _room(5.0, 1.8, 3.0, corridor=True),
    "staff_room": _room(9.0, 2.4, 2.5, corridor=True, daylight=True),
    "staff_office": _room(9.0, 2.4, 2.5, corridor=True, daylight=True),
    "head_office": _room(9.0, 2.4, 2.5, corridor=True, daylight=True),
    "management_office": _room(9.0, 2.4, 2.5, corridor=True, daylight=True),
    "back_office": _room(8.0, 2.4, 2.5, corridor=True),
    # sanitary (ADA §604, ISO 21542, DIN 18040-1, Approved Document M)
    "toilet": _room(2.5, 1.2, 3.0, corridor=True),
    "accessible_toilet": _room(3.3, 1.6, 2.0, corridor=True),
    "changing_room": _room(6.0, 2.0, 3.0, corridor=True),
    "washroom": _room(5.0, 1.8, 3.0, corridor=True),
    # health (HBN 04-01, HBN 00-03, FGI Guidelines)
    "ward": _room(14.5, 3.2, 2.0, corridor=True, daylight=True, bathroom=True),
    "nurse_station": _room(6.0, 2.0, 3.0),
    "pharmacy": _room(10.0, 2.7, 3.0, corridor=True),
    "consultation_room": _room(12.0, 3.0, 2.0, corridor=True),
    "treatment_room": _room(12.0, 3.0, 2.0, corridor=True),
    "triage": _room(8.0, 2.6, 2.5, corridor=True),
    "emergency_room": _room(16.0, 3.2, 2.5, corridor=True),
    "imaging_room": _room(16.0, 3.6, 2.0, corridor=True),
    "laboratory": _room(14.0, 3.0, 3.0, corridor=True),
    "operating_theatre": _room(30.0, 5.0, 1.6, corridor=True),
    "recovery_room": _room(14.0, 3.0, 3.0, corridor=True),
    "sterile_store": _room(5.0, 1.8, 3.0, corridor=True),
    "dirty_utility": _room(4.5, 1.8, 3.0, corridor=True),
    "clean_utility": _room(4.5, 1.8, 3.0, corridor=True),
    "sick_room": _room(6.0, 2.2, 2.5, corridor=True),
    # education (BB103, DIN 18040-1)
    "classroom": _room(40.0, 5.4, 2.0, corridor=True, daylight=True),
    "science_lab": _room(50.0, 5.4, 2.0, corridor=True, daylight=True),
    "computer_lab": _room(35.0, 4.8, 2.2, corridor=True, daylight=True),
    "art_room": _room(40.0, 5.4, 2.2, corridor=True, daylight=True),
    "music_room": _room(35.0, 4.8, 2.2, corridor=True, daylight=True),
    "gym": _room(60.0, 6.0, 2.5, corridor=True),
    "assembly_hall": _room(70.0, 6.0, 2.5, corridor=True),
    "canteen": _room(50.0, 5.4, 2.8, corridor=True, daylight=True),
    "group_room": _room(30.0, 4.5, 2.2, corridor=True, daylight=True),
    "sleep_room": _room(18.0, 3.6, 2.5, corridor=True),
    "play_hall": _room(30.0, 4.5, 3.0, daylight=True),
    "cloakroom": _room(5.0, 1.8, 3.0),
    # retail and food (Metric Handbook)
    "sales_floor": _room(100.0, 6.0, 3.0),
    "checkout_area": _room(15.0, 3.0, 4.0),
    "produce_section": _room(30.0, 5.0, 3.0),
    "cold_storage": _room(5.0, 1.8, 3.0, corridor=True),
    "freezer_room": _room(5.0, 1.8, 3.0, corridor=True),
    "warehouse": _room(20.0, 3.6, 3.0, corridor=True),
    "receiving_area": _room(15.0, 3.0, 3.0),
    "bakery": _room(12.0, 3.0, 3.0),
    "butcher_counter": _room(9.0, 2.5, 3.0),
    "shop": _room(20.0, 3.6, 3.0, corridor=True),
    "anchor_store": _room(80.0, 6.0, 3.0, corridor=True),
    "food_court": _room(50.0, 5.0, 3.0),
    "loading_dock": _room(20.0, 3.6, 3.0),
    "cinema": _room(60.0, 6.0, 2.0, corridor=True),
    "dining_hall": _room(40.0, 5.0, 3.0, daylight=True),
    "private_dining_room": _room(12.0, 3.0, 2.5, corridor=True, daylight=True),
    "bar": _room(12.0, 3.0, 3.0),
    "host_stand": _room(4.0, 1.8, 3.0),
    "commercial_kitchen": _room(18.0, 3.6, 3.0),
    "dry_store": _room(4.0, 1.5, 3.0),
    "dishwashing": _room(6.0, 2.0, 3.0),
    "restaurant": _room(40.0, 5.0, 3.0, corridor=True, daylight=True),
    "cafe": _room(18.0, 3.6, 3.0, daylight=True),
    # library
    "circulation_desk": _room(9.0, 2.7, 3.0),
    "reading_room": _room(40.0, 5.0, 2.5, corridor=True, daylight=True),
    "reading_hall": _room(40.0, 5.0, 3.0, daylight=True),
    "stacks": _room(30.0, 4.5, 3.0),
    "children_library": _room(30.0, 4.5, 2.5, corridor=True, daylight=True),
    "study_room": _room(7.5, 2.4, 2.5, corridor=True),
    "archive": _room(12.0, 3.0, 3.0, corridor=True),
    "multimedia_room": _room(20.0, 3.6, 2.5, corridor=True),
    "library": _room(30.0, 4.5, 2.5, corridor=True, daylight=True),
    # hotel (Metric Handbook, hotels)
    "guest_room": _room(16.0, 3.3, 2.2, corridor=True, daylight=True, bathroom=True),
    "suite": _room(30.0, 4.0, 2.2, corridor=True, daylight=True, bathroom=True),
    "housekeeping": _room(6.0, 2.0, 3.0, corridor=True),
    "linen_room": _room(4.0, 1.8, 3.0, corridor=True),
    "lounge": _room(25.0, 4.0, 3.0, daylight=True),
    "luggage_room": _room(4.0, 1.8, 3.0),
    "spa": _room(30.0, 4.5, 2.5, corridor=True),
    "pool_hall": _room(80.0, 6.0, 2.5, corridor=True),
}

#: A room type the table does not know: a small general-purpose room.
DEFAULT_DESIGN = _room(6.0, 2.0, 3.0)

#: Clear corridor width by building type, metres (IBC §1020.2, ADA §403.5, ISO 21542, ADM).
CORRIDOR_WIDTH: dict[str, float] = {
    "studio": 1.1,
    "family_apartment": 1.1,
    "townhouse": 1.1,
    "villa": 1.1,
    "apartment_block": 1.2,
    "office": 1.5,
    "hospital": 2.4,
    "school": 1.8,
    "kindergarten": 1.5,
    "supermarket": 1.5,
    "library": 1.5,
    "restaurant": 1.2,
    "hotel": 1.5,
    "shopping_mall": 2.4,
}
#: A building type not in :data:`CORRIDOR_WIDTH` (a public building in general).
DEFAULT_CORRIDOR_WIDTH = 1.5
#: Room types that are corridors: they take the building type's corridor width (a lobby or an
#: atrium is circulation too, but has widths of its own).
CORRIDOR_TYPES: frozenset[str] = frozenset(
    {"corridor", "ward_corridor", "hallway", "landing", "entrance_hall", "back_of_house"}
)
#: Room types that are sanitary (plumbed, washed down, tiled): a sanitary room is never made part
#: of another kind of room, nor another kind of room part of it (``mansion.building.merge``).
SANITARY_TYPES: frozenset[str] = frozenset(
    {"bathroom", "ensuite", "wc", "toilet", "accessible_toilet", "washroom", "changing_room"}
)

#: Other names of table entries (after normalisation).
_ALIASES: dict[str, str] = {
    "living": "living_room", "lounge_room": "living_room", "sitting_room": "living_room",
    "main_bedroom": "master_bedroom", "double_bedroom": "master_bedroom",
    "single_bedroom": "bedroom", "kids_room": "children_room", "nursery": "children_room",
    "shower_room": "bathroom", "restroom": "toilet", "lavatory": "toilet", "water_closet": "wc",
    "disabled_toilet": "accessible_toilet", "hall": "hallway", "passage": "corridor",
    "circulation": "corridor", "stair_hall": "landing", "vestibule": "entrance_vestibule",
    "closet": "storage", "store": "storage", "storeroom": "storage", "utility_room": "laundry",
    "home_office": "study", "workspace": "open_office", "cabin": "private_office",
    "patient_room": "ward", "inpatient_room": "ward", "exam_room": "consultation_room",
    "examination_room": "consultation_room", "operating_room": "operating_theatre",
    "hotel_room": "guest_room", "cafeteria": "canteen", "auditorium": "assembly_hall",
    "terrace": "balcony", "veranda": "balcony", "loggia": "balcony",
}

#: Words that decide a room's entry when its whole name is unknown, most telling first.
_WORDS: tuple[tuple[str, str], ...] = (
    ("corridor", "corridor"), ("hallway", "hallway"), ("lobby", "lobby"), ("foyer", "foyer"),
    ("accessible", "accessible_toilet"), ("toilet", "toilet"), ("wc", "wc"), ("ensuite", "ensuite"),
    ("bathroom", "bathroom"), ("shower", "bathroom"), ("bedroom", "bedroom"), ("kitchen", "kitchen"),
    ("ward", "ward"), ("classroom", "classroom"), ("lab", "laboratory"), ("office", "office"),
    ("meeting", "meeting_room"), ("storage", "storage"), ("store", "storage"), ("stor", "storage"),
    ("closet", "storage"), ("balcony", "balcony"), ("living", "living_room"),
    ("dining", "dining_room"), ("booth", "phone_booth"), ("suite", "suite"), ("shop", "shop"),
)


@functools.lru_cache(maxsize=4096)
def design_key(room_type: str) -> str | None:
    """The table entry ``room_type`` maps to, or None (then :data:`DEFAULT_DESIGN` applies).
    Cached: the mends ask it of the same few names a hundred thousand times per hundred
    buildings (0.75 s of 45 s).

    The name is lower-cased, separators become ``_``, a trailing count ("bedroom_2") and a
    plural ``s`` go; then exact names, aliases, contained words and close spellings are tried.
    """
    name = re.sub(r"[^a-z0-9]+", "_", room_type.lower()).strip("_")
    name = re.sub(r"(_\d+)+$", "", name)
    for cand in (name, name[:-1] if name.endswith("s") else name):
        if cand in ROOM_DESIGN:
            return cand
        if cand in _ALIASES:
            return _ALIASES[cand]
    words = name.split("_")
    for word, key in _WORDS:
        if word in words or (len(word) > 3 and word in name):
            return key
    close = difflib.get_close_matches(name, [*ROOM_DESIGN, *_ALIASES], n=1, cutoff=0.85)
    if close:
        return _ALIASES.get(close[0], close[0])
    return None


def room_design(room_type: str) -> RoomDesign:
    """The design entry for an open-vocabulary room type (:data:`DEFAULT_DESIGN` if unknown)."""
    key = design_key(room_type)
    return ROOM_DESIGN[key] if key is not None else DEFAULT_DESIGN


def corridor_width(building_type: str | None) -> float:
    """The clear corridor width of ``building_type`` in metres."""
    if building_type is None:
        return DEFAULT_CORRIDOR_WIDTH
    return CORRIDOR_WIDTH.get(building_type, DEFAULT_CORRIDOR_WIDTH)


def needed_width(room_type: str, building_type: str | None) -> float:
    """The clear width a room of ``room_type`` keeps everywhere, in metres: circulation people
    pass through (``through``), its building type's corridor width; any other room's, and a toilet
    lobby's or a balcony's, the table's. What the mends hold rooms to and what ``mansion eval
    realism`` judges; the planners ask the solver for :func:`planned_width`.

    Measured and left: judging only corridors (:data:`CORRIDOR_TYPES`) at the corridor width and
    other circulation (a lobby, an atrium) at its own table width, and planning them so, left
    308 rooms of the offline hundred below their width against 345 judged at the corridor width;
    but it judges lobbies and atriums people cross by less than the corridors that lead to them."""
    design = room_design(room_type)
    if design.circulation and design.through:
        return corridor_width(building_type)
    return design.min_width


def planned_width(room_type: str, building_type: str | None) -> float:
    """The clear width the solver's repair brings a finished room of ``room_type`` up to
    (``RoomNode.clear_width``): :func:`needed_width`, but every circulation room's its building
    type's corridor width. A toilet lobby planned only as wide as it needs (1.2 m, 1.5 m on the
    grid) leaves its WCs arms 1 m wide: on the offline hundreds, 1 and 2 more slivers and one more
    room without a usable square on the second (toilet lobbies judged at their own width either
    way: 281 / 298 rooms below their width planned so, 280 / 299 planned at the corridor width)."""
    if room_design(room_type).circulation:
        return corridor_width(building_type)
    return needed_width(room_type, building_type)
