"""Names the offline planner reads and writes: building types, room types and their rules of thumb.

``ROOMS`` holds, per room type, a typical area in m² (from common design guides: a single hospital
ward about 20 m², a classroom about 55 m², an office pantry about 12 m²) and the palette role its
materials come from. It is also how a room named in the description ("a gym on the top floor")
gets a sensible size.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["BUILDING_KEYWORDS", "ROOMS", "ROOM_SYNONYMS", "RoomKind", "room_kind"]

#: (building type, keywords as regular expressions), most specific first.
BUILDING_KEYWORDS: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("shopping_mall", ("shopping mall", "mall", r"shopping cent(?:re|er)", "plaza", "arcade")),
    ("supermarket", ("supermarket", "grocery(?: store)?", "hypermarket", "food market")),
    ("kindergarten", ("kindergarten", "nursery school", "preschool", "pre-school", "day ?care")),
    ("school", ("school", "academy", "college")),
    ("hospital", ("hospital", "clinic", "medical cent(?:re|er)", "infirmary")),
    ("library", ("library", "libraries")),
    ("restaurant", ("restaurant", "bistro", "cafe", "café", "diner", "eatery")),
    ("hotel", ("hotel", "hostel", "inn", "motel", "guest ?house")),
    ("office", ("office(?: building| block| tower)?", "offices", "headquarters", "coworking", "workplace")),
    (
        "apartment_block",
        (
            "apartment (?:block|building|tower|complex)",
            "residential (?:block|building|tower)",
            "apartments",
            "flats",
            "block of flats",
            "condominiums?",
            "condos?",
            "dormitory",
        ),
    ),
    ("villa", ("villa", "mansion", "manor", "detached house", "country house", "estate")),
    ("townhouse", ("townhouse", "town house", "terraced house", "row house", "duplex", "maisonette", "triplex", "house")),
    ("studio", ("studio(?: apartment| flat)?", "bedsit")),
    ("family_apartment", ("apartment", "flat", "home", "family apartment", "condo unit")),
)


@dataclass(frozen=True)
class RoomKind:
    """Rules of thumb for one room type: typical area (m²), palette role, open to its parent."""

    area: float
    role: str
    open: bool = False


#: Room types, their typical area, material role and openness. Roles name palette entries.
ROOMS: dict[str, RoomKind] = {
    # circulation
    "corridor": RoomKind(30, "circulation", True),
    "entrance_hall": RoomKind(30, "circulation", True),
    "lobby": RoomKind(60, "circulation", True),
    "landing": RoomKind(8, "circulation", True),
    "hallway": RoomKind(8, "circulation", True),
    "foyer": RoomKind(12, "circulation", True),
    "atrium": RoomKind(80, "circulation", True),
    "concourse": RoomKind(60, "circulation", True),
    "toilet_lobby": RoomKind(4, "wet", True),
    "waiting_area": RoomKind(30, "circulation", True),
    # dwelling
    "living_room": RoomKind(28, "living", True),
    "studio_room": RoomKind(22, "living", True),
    "dining_room": RoomKind(14, "living", True),
    "kitchen": RoomKind(11, "kitchen"),
    "kitchenette": RoomKind(6, "kitchen", True),
    "bedroom": RoomKind(12, "bedroom"),
    "master_bedroom": RoomKind(17, "bedroom"),
    "children_room": RoomKind(11, "bedroom"),
    "guest_bedroom": RoomKind(12, "bedroom"),
    "bathroom": RoomKind(6, "wet"),
    "ensuite": RoomKind(5, "wet"),
    "wc": RoomKind(2.5, "wet"),
    "walk_in_closet": RoomKind(5, "bedroom"),
    "laundry": RoomKind(5, "service"),
    "storage": RoomKind(5, "service"),
    "study": RoomKind(10, "work"),
    "family_room": RoomKind(20, "living"),
    "garage": RoomKind(32, "service"),
    "home_gym": RoomKind(16, "sport"),
    "mail_room": RoomKind(8, "service"),
    "bike_storage": RoomKind(14, "service"),
    "refuse_room": RoomKind(6, "service"),
    "unit_living": RoomKind(24, "living", True),
    # work
    "reception": RoomKind(20, "public"),
    "open_office": RoomKind(60, "work", True),
    "private_office": RoomKind(12, "work"),
    "meeting_room": RoomKind(16, "work"),
    "board_room": RoomKind(30, "work"),
    "phone_booth": RoomKind(3, "work"),
    "print_room": RoomKind(6, "service"),
    "server_room": RoomKind(9, "service"),
    "pantry": RoomKind(12, "kitchen"),
    "office": RoomKind(14, "work"),
    "staff_room": RoomKind(14, "work"),
    # sanitary
    "toilet": RoomKind(7, "wet"),
    "accessible_toilet": RoomKind(5, "wet"),
    "changing_room": RoomKind(12, "wet"),
    # health
    "ward": RoomKind(24, "clinical"),
    "nurse_station": RoomKind(12, "clinical", True),
    "pharmacy": RoomKind(22, "clinical"),
    "consultation_room": RoomKind(16, "clinical"),
    "treatment_room": RoomKind(16, "clinical"),
    "triage": RoomKind(12, "clinical"),
    "emergency_room": RoomKind(30, "clinical"),
    "imaging_room": RoomKind(28, "clinical"),
    "laboratory": RoomKind(24, "clinical"),
    "operating_theatre": RoomKind(40, "clinical"),
    "recovery_room": RoomKind(24, "clinical"),
    "sterile_store": RoomKind(10, "service"),
    "dirty_utility": RoomKind(7, "service"),
    "clean_utility": RoomKind(7, "service"),
    "ward_corridor": RoomKind(25, "circulation", True),
    # education
    "classroom": RoomKind(56, "learning"),
    "science_lab": RoomKind(70, "learning"),
    "computer_lab": RoomKind(60, "learning"),
    "art_room": RoomKind(60, "learning"),
    "music_room": RoomKind(50, "learning"),
    "gym": RoomKind(90, "sport"),
    "assembly_hall": RoomKind(120, "public"),
    "canteen": RoomKind(90, "public"),
    "staff_office": RoomKind(18, "work"),
    "head_office": RoomKind(14, "work"),
    "group_room": RoomKind(45, "learning"),
    "sleep_room": RoomKind(30, "bedroom"),
    "play_hall": RoomKind(60, "learning", True),
    "cloakroom": RoomKind(10, "service"),
    "washroom": RoomKind(12, "wet"),
    "sick_room": RoomKind(8, "clinical"),
    # retail and food
    "sales_floor": RoomKind(250, "retail", True),
    "checkout_area": RoomKind(35, "retail", True),
    "entrance_vestibule": RoomKind(12, "circulation", True),
    "produce_section": RoomKind(60, "retail", True),
    "cold_storage": RoomKind(20, "service"),
    "freezer_room": RoomKind(14, "service"),
    "warehouse": RoomKind(50, "service"),
    "receiving_area": RoomKind(30, "service"),
    "bakery": RoomKind(25, "kitchen"),
    "butcher_counter": RoomKind(18, "kitchen"),
    "back_of_house": RoomKind(12, "service", True),
    "shop": RoomKind(45, "retail"),
    "anchor_store": RoomKind(160, "retail"),
    "food_court": RoomKind(120, "public", True),
    "management_office": RoomKind(18, "work"),
    "loading_dock": RoomKind(40, "service"),
    "cinema": RoomKind(120, "public"),
    "dining_hall": RoomKind(90, "public", True),
    "private_dining_room": RoomKind(22, "public"),
    "bar": RoomKind(25, "public"),
    "host_stand": RoomKind(10, "public", True),
    "commercial_kitchen": RoomKind(40, "kitchen"),
    "dry_store": RoomKind(8, "service"),
    "dishwashing": RoomKind(10, "kitchen"),
    # library
    "circulation_desk": RoomKind(20, "public", True),
    "reading_room": RoomKind(90, "learning"),
    "stacks": RoomKind(80, "learning"),
    "children_library": RoomKind(60, "learning"),
    "study_room": RoomKind(12, "learning"),
    "archive": RoomKind(30, "service"),
    "reading_hall": RoomKind(70, "learning", True),
    "multimedia_room": RoomKind(40, "learning"),
    # hotel
    "guest_room": RoomKind(24, "bedroom"),
    "suite": RoomKind(45, "bedroom"),
    "housekeeping": RoomKind(10, "service"),
    "linen_room": RoomKind(8, "service"),
    "lounge": RoomKind(50, "public"),
    "restaurant": RoomKind(80, "public"),
    "luggage_room": RoomKind(8, "service"),
    "back_office": RoomKind(16, "work"),
    "spa": RoomKind(60, "sport"),
    "conference_room": RoomKind(50, "work"),
    "cafe": RoomKind(40, "public"),
}

#: How a description names room types, as regular expressions (a plural ``s`` is allowed).
ROOM_SYNONYMS: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("gym", ("gym", "gymnasium", "fitness (?:room|cent(?:re|er)|studio)", "sports hall")),
    ("home_gym", ("home gym",)),
    ("pharmacy", ("pharmacy", "pharmacie", "dispensary", "drugstore")),
    ("classroom", ("classroom", "class room", "class")),
    ("science_lab", ("science lab", "laboratory classroom", "lab")),
    ("computer_lab", ("computer lab", "computer room", "it room")),
    ("ward", ("ward", "patient room", "inpatient room")),
    ("operating_theatre", ("operating theat(?:re|er)", "operating room", "surgery")),
    ("meeting_room", ("meeting room", "conference room", "meeting space")),
    ("board_room", ("board ?room",)),
    ("private_office", ("private office", "cabin")),
    ("open_office", ("open office", "open-plan office", "open plan office", "workspace")),
    ("kitchen", ("kitchen",)),
    ("dining_room", ("dining room", "dining area")),
    ("living_room", ("living room", "lounge room", "sitting room")),
    ("master_bedroom", ("master bedroom", "main bedroom")),
    ("bedroom", ("bedroom",)),
    ("bathroom", ("bathroom", "shower room")),
    ("toilet", ("toilet", "restroom", "washroom", "wc", "lavatory")),
    ("garage", ("garage", "car port", "carport")),
    ("study", ("study", "home office")),
    ("library", ("library",)),
    ("reading_room", ("reading room",)),
    ("study_room", ("study room", "group study room")),
    ("cafe", ("cafe", "café", "coffee shop", "coffee bar")),
    ("canteen", ("canteen", "cafeteria", "lunch room")),
    ("restaurant", ("restaurant",)),
    ("bar", ("bar",)),
    ("food_court", ("food court", "food hall")),
    ("cinema", ("cinema", "movie theat(?:re|er)")),
    ("anchor_store", ("anchor store", "department store", "supermarket", "hypermarket", "grocery(?: store)?")),
    ("bike_storage", ("bike (?:store|storage|room|shed|parking)", "bicycle (?:store|storage|room|shed|parking)")),
    ("shop", ("shop", "store", "boutique", "retail unit")),
    ("guest_room", ("guest room", "hotel room")),
    ("suite", ("suite",)),
    ("spa", ("spa", "wellness")),
    ("pool_hall", ("pool",)),
    ("laundry", ("laundry", "utility room")),
    ("storage", ("storage", "store room", "storeroom")),
    ("server_room", ("server room", "data room")),
    ("recovery_room", ("recovery room", "icu", "intensive care(?: unit)?", "high dependency unit")),
    ("nurse_station", ("nurse station", "nurses station", "nursing station")),
    ("emergency_room", ("emergency (?:room|department)", "a&e", "er")),
    ("imaging_room", ("imaging", "x-ray room", "radiology", "mri room")),
    ("consultation_room", ("consultation room", "consulting room", "exam room", "examination room")),
    ("cold_storage", ("cold storage", "cold room", "refrigerated room")),
    ("checkout_area", ("checkout", "checkouts", "cash desk", "till")),
    ("bakery", ("bakery",)),
    ("play_hall", ("play ?room", "play hall", "playroom", "play (?:area|space|zone)")),
    ("group_room", ("group room",)),
    ("sleep_room", ("sleep(?:ing)? room", "nap room")),
    ("art_room", ("art room", "art studio")),
    ("music_room", ("music room",)),
    ("assembly_hall", ("assembly hall", "auditorium", "hall")),
    ("staff_room", ("staff room", "teachers' room", "teacher room")),
    ("lounge", ("lounge",)),
    ("conference_room", ("conference hall",)),
    ("archive", ("archive",)),
)


def room_kind(room_type: str) -> RoomKind:
    """The rules of thumb for ``room_type``; an unknown type is a 20 m² room of the ``public``
    role, so a room the description invents still gets a size and materials."""
    return ROOMS.get(room_type, RoomKind(20.0, "public"))
