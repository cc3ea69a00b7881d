"""Room programs of the building types the offline planner knows, as small data tables.

A :class:`Typology` gives a building type's usual height and floor size, its footprint shapes, when
it needs an elevator, and a :class:`FloorTemplate` per floor role (ground, upper, top). A template
lists the floor's hub (the first room of the program, where the cut rounds start) and its rooms:
fixed rooms, and *fill* rooms repeated until the floor's area is used (wards, classrooms, shops,
guest rooms). A room may belong to a *zone*: a department hanging off one sub-hub (the emergency
department off the lobby, a ward corridor with its wards, a toilet lobby with its toilets), which
keeps each cut round small and each room reachable. Areas are rules of thumb (see
:mod:`mansion.planning.vocabulary`); the planner scales them to the floor.

Residential and office towers are *bay* typologies (:mod:`mansion.planning.bays`): every floor is
the same corridor with the same structural bays, so the walls of one floor can carry the next.
"""

from __future__ import annotations

from dataclasses import dataclass, field

__all__ = ["FloorTemplate", "Rm", "TYPOLOGIES", "Typology", "Zone"]


@dataclass(frozen=True)
class Rm:
    """A room rule: ``count`` rooms of ``room_type`` (area: the vocabulary's unless given).

    ``fill`` rooms are repeated to use the floor's remaining area (at least ``count``);
    ``optional`` rooms are dropped first when the floor is too small; ``zone`` names the
    template zone they hang off (None: off the floor's hub).
    """

    room_type: str
    count: int = 1
    area: float | None = None
    fill: bool = False
    optional: bool = False
    zone: str | None = None


@dataclass(frozen=True)
class Zone:
    """A department: its sub-hub room type, the sub-hub's area, and how many rooms it may hold
    before it is split into wings."""

    id: str
    hub: str
    hub_area: float | None = None


@dataclass(frozen=True)
class FloorTemplate:
    hub: str
    rooms: tuple[Rm, ...]
    zones: tuple[Zone, ...] = ()
    #: (room type, room type) pairs that must share a wall (both present on the floor).
    adjacent: tuple[tuple[str, str], ...] = ()
    #: Laid out whole as a double-loaded corridor with its rooms in bays on both sides where the
    #: floor's shape allows (:mod:`mansion.building.banks`; a hotel's guest-room floors, a
    #: school's classroom floors, a hospital's ward floors), else by the cut rounds.
    banks: bool = False
    #: With ``banks``: each bay depth tried as a racetrack too (banks along two opposite facades,
    #: a corridor along each, the rooms without daylight between them; a hospital's ward floors
    #: on deep plates), the layout keeping most rooms, then with the least corridor, kept.
    racetrack: bool = False


@dataclass(frozen=True)
class Typology:
    key: str
    family: str  # palette family: residential | work | public
    floors: tuple[int, int]  # usual number of floors (inclusive range)
    area: tuple[float, float]  # usual gross area per floor, m²
    ground: FloorTemplate
    upper: FloorTemplate | None = None
    top: FloorTemplate | None = None
    shapes: tuple[str, ...] = ("rectangle",)
    #: How the outline changes with height: uniform, setback, podium, garage.
    stacks: tuple[str, ...] = ("uniform",)
    #: Most floors served by stairs alone; above this an elevator is added.
    stair_only_floors: int = 2
    #: Share of a floor's free area held back for circulation when the program counts how many
    #: fill rooms (wards, guest rooms, classrooms, shops) the floor takes; the corridors are then
    #: planned as length × width and the rooms share what they leave. Public types hold back what
    #: their layouts realise as circulation: with the earlier ranges (hospital 0.18–0.25, school
    #: and hotel 0.16–0.24, library 0.14–0.2, supermarket 0.12–0.16, mall 0.2–0.25) the offline
    #: hundred's circulation came out well above the plan (median share of the free area planned
    #: / realised: hospital 0.27 / 0.38, school 0.23 / 0.30, hotel 0.17 / 0.26), because growth
    #: leaves the hub every cell no room reached, and the rooms of over-full floors ended short,
    #: wards and guest rooms below their minimums. The old ranges × 1.6 take fewer fill rooms
    #: (hospital rooms 862 → 741 on the hundred) at sizes the layout reaches: rooms below their
    #: minimum area 4.3 → 3.1 %, below their width 18.3 → 16.1 % (issue 14). Homes keep theirs
    #: (their circulation came out within 4 points of the plan).
    reserve: tuple[float, float] = (0.14, 0.22)
    load_bearing: bool = False
    #: Identical upper floors are written as copies of the first one.
    copies: bool = False
    description: str = ""
    notes: dict[str, str] = field(default_factory=dict)


_TOILETS = (
    Rm("toilet", 2, zone="toilets"),
    Rm("accessible_toilet", zone="toilets"),
)
_TOILET_ZONE = Zone("toilets", "toilet_lobby", 4.0)

STUDIO = Typology(
    "studio", "residential", (1, 1), (28, 45),
    FloorTemplate(
        "studio_room",
        (Rm("kitchenette"), Rm("bathroom", area=4.5), Rm("storage", area=2.5, optional=True),
         Rm("hallway", area=4.0, optional=True)),
    ),
    shapes=("rectangle",),
    reserve=(0.12, 0.14),
    description="one main room with a kitchenette, a bathroom and storage",
)

FAMILY_APARTMENT = Typology(
    "family_apartment", "residential", (1, 1), (75, 130),
    FloorTemplate(
        "living_room",
        (
            Rm("kitchen", zone="dining"),
            Rm("master_bedroom", zone="sleeping"), Rm("bedroom", zone="sleeping"),
            Rm("children_room", zone="sleeping", optional=True),
            Rm("bathroom", zone="sleeping"), Rm("wc", optional=True),
            Rm("storage", optional=True), Rm("study", optional=True),
        ),
        (Zone("dining", "dining_room"), Zone("sleeping", "hallway", 7.0)),
        adjacent=(("kitchen", "dining_room"),),
    ),
    shapes=("rectangle", "l_shape"),
    reserve=(0.12, 0.16),
    description="living room hub, kitchen off the dining room, bedrooms off a hallway",
)

TOWNHOUSE = Typology(
    "townhouse", "residential", (2, 3), (55, 90),
    FloorTemplate(
        "living_room",
        (Rm("entrance_hall" , area=6.0), Rm("kitchen", zone="dining"), Rm("wc"),
         Rm("storage", optional=True), Rm("laundry", optional=True)),
        (Zone("dining", "dining_room"),),
        adjacent=(("kitchen", "dining_room"),),
    ),
    upper=FloorTemplate(
        "landing",
        (Rm("master_bedroom"), Rm("bedroom"), Rm("children_room", optional=True),
         Rm("bathroom"), Rm("storage", optional=True)),
    ),
    top=FloorTemplate(
        "landing",
        (Rm("bedroom"), Rm("study"), Rm("bathroom"), Rm("storage", optional=True)),
    ),
    shapes=("rectangle",),
    stacks=("uniform", "setback"),
    stair_only_floors=3,
    reserve=(0.12, 0.16),
    description="narrow house: living and kitchen below, bedrooms above",
)

VILLA = Typology(
    "villa", "residential", (2, 3), (130, 230),
    FloorTemplate(
        "foyer",
        (Rm("living_room"), Rm("kitchen", zone="dining"), Rm("garage"),
         Rm("guest_bedroom", optional=True), Rm("wc"), Rm("laundry"), Rm("study", optional=True),
         Rm("storage", optional=True)),
        (Zone("dining", "dining_room"),),
        adjacent=(("kitchen", "dining_room"),),
    ),
    upper=FloorTemplate(
        "landing",
        (Rm("master_bedroom", zone="master_suite", area=20), Rm("ensuite", zone="master_suite"),
         Rm("walk_in_closet", zone="master_suite"), Rm("bedroom", 2), Rm("bathroom"),
         Rm("family_room", optional=True), Rm("children_room", optional=True),
         Rm("storage", optional=True)),
        (Zone("master_suite", "hallway", 4.0),),
    ),
    top=FloorTemplate(
        "landing",
        (Rm("family_room"), Rm("home_gym", optional=True), Rm("guest_bedroom"), Rm("bathroom"),
         Rm("storage", optional=True)),
    ),
    shapes=("rectangle", "l_shape"),
    stacks=("garage",),
    stair_only_floors=3,
    reserve=(0.12, 0.18),
    description="foyer hub, living and dining below with a protruding garage, suites above",
)

HOSPITAL = Typology(
    "hospital", "public", (2, 6), (380, 500),
    FloorTemplate(
        "lobby",
        (
            Rm("reception"), Rm("pharmacy"),
            Rm("triage", zone="emergency"), Rm("emergency_room", zone="emergency"),
            Rm("treatment_room", 2, zone="emergency"),
            Rm("consultation_room", 3, fill=True, zone="outpatients"),
            Rm("imaging_room", optional=True), Rm("cafe", area=30, optional=True),
            *_TOILETS,
        ),
        (Zone("emergency", "corridor", 14.0), Zone("outpatients", "waiting_area", 18.0), _TOILET_ZONE),
    ),
    upper=FloorTemplate(
        "corridor",
        (
            Rm("ward", 4, fill=True, zone="ward_wing"),
            Rm("nurse_station", zone="ward_wing"),
            Rm("treatment_room"), Rm("clean_utility", optional=True), Rm("dirty_utility"),
            Rm("staff_room", optional=True), *_TOILETS,
        ),
        (Zone("ward_wing", "ward_corridor", 20.0), _TOILET_ZONE),
        banks=True,
        racetrack=True,
    ),
    top=FloorTemplate(
        "corridor",
        (
            Rm("operating_theatre", 2), Rm("recovery_room"), Rm("sterile_store"),
            Rm("changing_room", 2), Rm("ward", 2, fill=True, zone="ward_wing"),
            Rm("nurse_station", zone="ward_wing"), Rm("laboratory", optional=True), *_TOILETS,
        ),
        (Zone("ward_wing", "ward_corridor", 16.0), _TOILET_ZONE),
        banks=True,
        racetrack=True,
    ),
    shapes=("rectangle", "l_shape", "t_shape", "u_shape", "courtyard"),
    stacks=("uniform", "podium", "setback"),
    stair_only_floors=1,
    reserve=(0.29, 0.4),
    description="lobby with reception and pharmacy, emergency and outpatients below; wards with a nurse station above",
)

SCHOOL = Typology(
    "school", "public", (1, 4), (350, 500),
    FloorTemplate(
        "entrance_hall",
        (
            Rm("head_office", zone="admin"), Rm("staff_office", zone="admin"),
            Rm("staff_room", zone="admin", optional=True), Rm("sick_room", zone="admin", optional=True),
            Rm("classroom", 2, fill=True, zone="classrooms"), Rm("canteen", optional=True),
            *_TOILETS,
        ),
        (Zone("admin", "reception", 12.0), Zone("classrooms", "corridor", 20.0), _TOILET_ZONE),
    ),
    upper=FloorTemplate(
        "corridor",
        (
            Rm("classroom", 3, fill=True, zone="classrooms"), Rm("science_lab", optional=True),
            Rm("computer_lab", optional=True), Rm("storage", optional=True), *_TOILETS,
        ),
        (Zone("classrooms", "corridor", 18.0), _TOILET_ZONE),
        banks=True,
    ),
    top=FloorTemplate(
        "corridor",
        (
            Rm("classroom", 2, fill=True, zone="classrooms"), Rm("art_room", optional=True),
            Rm("music_room", optional=True), Rm("library", area=60, optional=True), *_TOILETS,
        ),
        (Zone("classrooms", "corridor", 18.0), _TOILET_ZONE),
        banks=True,
    ),
    shapes=("rectangle", "l_shape", "u_shape", "t_shape", "courtyard"),
    stacks=("uniform",),
    stair_only_floors=1,
    reserve=(0.26, 0.38),
    description="entrance hall with the office; classrooms off corridors; toilets on every floor",
)

KINDERGARTEN = Typology(
    "kindergarten", "public", (1, 2), (200, 380),
    FloorTemplate(
        "play_hall",
        (
            Rm("group_room", 2, fill=True), Rm("sleep_room"), Rm("washroom"), Rm("cloakroom"),
            Rm("kitchen", area=14, zone="staff"), Rm("staff_office", optional=True, zone="staff"),
            Rm("sick_room", optional=True, zone="staff"), Rm("storage", optional=True, zone="staff"),
        ),
        # the kitchen and the staff's rooms a wing off a corridor of their own, as kindergartens
        # are planned (the children's rooms off the play hall, the service rooms apart): the
        # hall's first round cuts six regions instead of ten, and ten rooms round a 50 m² hall
        # had left it snaking 3 m wide between them (rooms below their width on the
        # kindergartens of the offline hundreds 10 / 5 -> 5 / 5)
        (Zone("staff", "corridor", 8.0),),
        adjacent=(("washroom", "sleep_room"),),
    ),
    upper=FloorTemplate(
        "play_hall",
        (Rm("group_room", 2, fill=True), Rm("sleep_room"), Rm("washroom"),
         Rm("staff_room", optional=True), Rm("storage", optional=True)),
    ),
    shapes=("rectangle", "l_shape", "u_shape"),
    stacks=("uniform", "setback"),
    stair_only_floors=1,
    reserve=(0.14, 0.2),
    description="a play hall hub with group rooms, sleep room and washroom; kitchen and staff rooms off a staff corridor",
)

SUPERMARKET = Typology(
    "supermarket", "public", (1, 2), (320, 500),
    # The ground floor: a corridor hub with the sales floor a room off it, at 200 m² (the floors
    # are 320-500 m²; a sales floor is most of a store). With the sales floor as the hub it took
    # what its rooms left, a ring of 1.5-3 m aisles round back-of-house rooms cut in the middle
    # of the floor, and no 6 m square held its 100 m² minimum. On the supermarkets of the
    # offline hundreds, rooms below their width or area 6 / 4 -> 0 / 0, 17 optional rooms fewer;
    # at the vocabulary's 250 m² also 0 / 0 but 38 rooms fewer; at 120-180 m² 4 to 8 bad rooms.
    FloorTemplate(
        "corridor",
        (
            Rm("sales_floor", area=200.0), Rm("entrance_vestibule"), Rm("checkout_area"),
            Rm("produce_section", optional=True), Rm("bakery", optional=True),
            Rm("cold_storage", zone="back_of_house"), Rm("freezer_room", zone="back_of_house"),
            Rm("warehouse", zone="back_of_house"),
            Rm("receiving_area", zone="back_of_house", optional=True),
            Rm("staff_room", zone="back_of_house", optional=True),
            Rm("toilet", 2, zone="back_of_house"),
        ),
        (Zone("back_of_house", "back_of_house", 10.0),),
        adjacent=(("checkout_area", "entrance_vestibule"), ("cold_storage", "freezer_room")),
    ),
    upper=FloorTemplate(
        "corridor",
        (Rm("warehouse"), Rm("management_office"), Rm("staff_room"), Rm("changing_room", 2),
         Rm("warehouse", 1, fill=True, area=40), Rm("storage", optional=True), *_TOILETS),
        (_TOILET_ZONE,),
    ),
    shapes=("rectangle", "l_shape"),
    stacks=("uniform", "setback"),
    stair_only_floors=1,
    reserve=(0.19, 0.26),
    description=(
        "a sales floor off a corridor with checkouts by the entrance, cold storage and stores behind"
    ),
)

LIBRARY = Typology(
    "library", "public", (1, 3), (220, 460),
    FloorTemplate(
        "lobby",
        (Rm("circulation_desk"), Rm("reading_room"), Rm("stacks", fill=True),
         Rm("children_library", optional=True), Rm("cafe", area=30, optional=True), *_TOILETS),
        (_TOILET_ZONE,),
    ),
    # Upper floors: a corridor hub with the reading hall, stacks and study rooms off it, as a
    # library's upper floors are planned. With the reading hall as the hub, the hub takes what
    # the rooms cut from it leave: halls 1.5 m wide snaking between study rooms and stacks, no
    # 5 m square in them (rooms below their width on the libraries of the offline hundreds
    # 4 / 3 -> 0 / 0, below area 0 / 0 -> 0 / 1, rooms 185 / 199 -> 185 / 203).
    upper=FloorTemplate(
        "corridor",
        (Rm("reading_hall"), Rm("stacks", fill=True), Rm("study_room", 3),
         Rm("computer_lab", area=40, optional=True), Rm("multimedia_room", optional=True), *_TOILETS),
        (_TOILET_ZONE,),
    ),
    top=FloorTemplate(
        "corridor",
        (Rm("reading_hall"), Rm("archive"), Rm("study_room", 2), Rm("office", 2), Rm("stacks", fill=True),
         *_TOILETS),
        (_TOILET_ZONE,),
    ),
    shapes=("rectangle", "l_shape", "u_shape", "courtyard"),
    stacks=("uniform", "setback"),
    stair_only_floors=1,
    reserve=(0.22, 0.32),
    description=(
        "lobby with the circulation desk; reading rooms, stacks and study rooms; upper floors a "
        "corridor with the reading hall off it"
    ),
)

RESTAURANT = Typology(
    "restaurant", "public", (1, 2), (200, 300),
    FloorTemplate(
        "dining_hall",
        (Rm("host_stand"), Rm("bar", optional=True), Rm("commercial_kitchen", zone="kitchen"),
         Rm("dry_store", zone="kitchen"), Rm("cold_storage", area=8, zone="kitchen"),
         Rm("dishwashing", zone="kitchen", optional=True), Rm("toilet", 2),
         Rm("private_dining_room", optional=True)),
        (Zone("kitchen", "back_of_house", 6.0),),
        adjacent=(("commercial_kitchen", "dining_hall"),),
    ),
    upper=FloorTemplate(
        "dining_hall",
        (Rm("private_dining_room", 2), Rm("bar", optional=True), Rm("toilet", 2),
         Rm("office", optional=True), Rm("staff_room", optional=True)),
    ),
    shapes=("rectangle", "l_shape"),
    stacks=("uniform",),
    stair_only_floors=2,
    reserve=(0.12, 0.16),
    description="a dining hall hub, the kitchen with its stores behind, toilets",
)

HOTEL = Typology(
    "hotel", "public", (3, 8), (300, 500),
    FloorTemplate(
        "lobby",
        (Rm("reception"), Rm("lounge"), Rm("restaurant", zone="dining"),
         Rm("commercial_kitchen", area=30, zone="dining"), Rm("luggage_room"),
         Rm("back_office"), Rm("conference_room", optional=True), *_TOILETS),
        (Zone("dining", "corridor", 8.0), _TOILET_ZONE),
    ),
    upper=FloorTemplate(
        "corridor",
        (Rm("guest_room", 4, fill=True), Rm("housekeeping"), Rm("linen_room", optional=True)),
        banks=True,
    ),
    top=FloorTemplate(
        "corridor",
        (Rm("suite", 2), Rm("guest_room", 2, fill=True), Rm("housekeeping"),
         Rm("spa", optional=True)),
        banks=True,
    ),
    shapes=("rectangle", "l_shape", "t_shape", "u_shape"),
    stacks=("uniform", "podium"),
    stair_only_floors=1,
    reserve=(0.26, 0.38),
    copies=True,
    description="lobby, reception, restaurant below; guest rooms off a corridor above",
)

SHOPPING_MALL = Typology(
    "shopping_mall", "public", (2, 4), (420, 500),
    FloorTemplate(
        "atrium",
        (Rm("anchor_store"), Rm("shop", 4, fill=True), Rm("cafe", optional=True),
         Rm("management_office", zone="service"), Rm("loading_dock", zone="service"),
         Rm("storage", zone="service", optional=True), *_TOILETS),
        (Zone("service", "corridor", 8.0), _TOILET_ZONE),
    ),
    upper=FloorTemplate(
        "concourse",
        (Rm("shop", 4, fill=True), Rm("food_court", optional=True), *_TOILETS),
        (_TOILET_ZONE,),
    ),
    top=FloorTemplate(
        "concourse",
        (Rm("cinema", optional=True), Rm("food_court"), Rm("shop", 2, fill=True), *_TOILETS),
        (_TOILET_ZONE,),
    ),
    shapes=("rectangle", "l_shape", "t_shape", "u_shape"),
    stacks=("uniform", "podium", "setback"),
    stair_only_floors=1,
    reserve=(0.32, 0.4),
    description="an atrium with shops, an anchor store and a food court",
)

#: Every building type the offline planner generates, by key (bay typologies included).
TYPOLOGIES: dict[str, Typology] = {
    t.key: t
    for t in (
        STUDIO, FAMILY_APARTMENT, TOWNHOUSE, VILLA, HOSPITAL, SCHOOL, KINDERGARTEN, SUPERMARKET,
        LIBRARY, RESTAURANT, HOTEL, SHOPPING_MALL,
    )
}
