"""Bay typologies: residential and office towers whose floors share one structural grid.

Every floor is a corridor hub with the same row of structural bays, each bay one zone off the
corridor (an apartment, an office wing, the toilet core). Bays keep their ids and areas from floor
to floor and only their use changes (the ground floor's first apartment bay becomes the residents'
amenity rooms, the top office bay the executive suite), which is what lets the walls of one floor's
first cut round carry the floor above as load-bearing walls.
"""

from __future__ import annotations

from dataclasses import dataclass

from mansion.planning.typologies import FloorTemplate, Rm, Typology

__all__ = ["BAY_TYPOLOGIES", "BayPlan", "BayProgram"]


@dataclass(frozen=True)
class BayProgram:
    """One use of a bay: its sub-hub room type and rooms (areas are scaled to the bay)."""

    name: str
    hub: str
    rooms: tuple[Rm, ...]
    min_area: float = 0.0


@dataclass(frozen=True)
class BayPlan:
    bay_area: tuple[float, float]
    floor_hub: dict[str, str]  # floor role -> hub room type
    #: Uses of the first bays by floor role (ground: lobby amenities, top: executive suite).
    leading: dict[str, tuple[BayProgram, ...]]
    #: Uses for the other bays; the largest whose ``min_area`` the bay meets is eligible, the seed
    #: picks among eligible ones.
    default: tuple[BayProgram, ...]
    #: A bay of its own on every floor, last in the row (toilets), with this area.
    services: BayProgram | None = None
    services_area: float = 0.0


_ONE_BED = BayProgram(
    "one_bedroom_unit", "unit_living",
    (Rm("kitchen", area=8), Rm("bedroom", area=12), Rm("bathroom", area=5)),
)
_TWO_BED = BayProgram(
    "two_bedroom_unit", "unit_living",
    (Rm("kitchen", area=9), Rm("master_bedroom", area=14), Rm("bedroom", area=11),
     Rm("bathroom", area=6)),
    min_area=62,
)
_THREE_BED = BayProgram(
    "three_bedroom_unit", "unit_living",
    (Rm("kitchen", area=10), Rm("master_bedroom", area=15), Rm("bedroom", area=11),
     Rm("children_room", area=10), Rm("bathroom", area=6), Rm("wc", area=3)),
    min_area=85,
)
_AMENITY = BayProgram(
    "residents_amenities", "foyer",
    (Rm("mail_room"), Rm("bike_storage"), Rm("refuse_room"), Rm("storage")),
)

APARTMENT_BLOCK = Typology(
    "apartment_block", "residential", (3, 8), (280, 480),
    FloorTemplate("corridor", ()),
    shapes=("rectangle", "l_shape", "u_shape", "t_shape"),
    stacks=("uniform",),
    stair_only_floors=3,
    reserve=(0.12, 0.18),
    load_bearing=True,
    description="a corridor with apartments on every floor; residents' amenities by the entrance",
)
APARTMENT_BAYS = BayPlan(
    bay_area=(55.0, 95.0),
    floor_hub={"ground": "entrance_hall", "upper": "corridor", "top": "corridor"},
    leading={"ground": (_AMENITY,)},
    default=(_ONE_BED, _TWO_BED, _THREE_BED),
)

_OFFICE_WING = BayProgram(
    "office_wing", "open_office",
    (Rm("private_office"), Rm("private_office"), Rm("meeting_room"), Rm("phone_booth"),
     Rm("print_room", area=5)),
)
_CELLULAR_WING = BayProgram(
    "cellular_offices", "corridor",
    (Rm("office", area=14), Rm("office", area=14), Rm("office", area=14), Rm("meeting_room"),
     Rm("storage", area=4)),
    min_area=70,
)
_RECEPTION = BayProgram(
    "reception_suite", "reception",
    (Rm("meeting_room"), Rm("meeting_room", area=12), Rm("storage", area=4)),
)
_CAFE = BayProgram("staff_cafe", "cafe", (Rm("pantry"), Rm("storage", area=5)))
_EXECUTIVE = BayProgram(
    "executive_suite", "corridor",
    (Rm("board_room"), Rm("private_office", area=16), Rm("private_office", area=16), Rm("pantry", area=8)),
)
_SERVICES = BayProgram(
    "toilet_core", "toilet_lobby",
    (Rm("toilet", area=8), Rm("toilet", area=8), Rm("accessible_toilet", area=5)),
)

OFFICE = Typology(
    "office", "work", (2, 8), (320, 500),
    FloorTemplate("corridor", ()),
    shapes=("rectangle", "l_shape", "u_shape", "t_shape", "courtyard"),
    stacks=("uniform",),
    stair_only_floors=2,
    reserve=(0.14, 0.22),
    load_bearing=True,
    description="a corridor with office wings and a toilet core on every floor; reception below",
)
OFFICE_BAYS = BayPlan(
    bay_area=(70.0, 110.0),
    floor_hub={"ground": "lobby", "upper": "corridor", "top": "corridor"},
    leading={"ground": (_RECEPTION, _CAFE), "top": (_EXECUTIVE,)},
    default=(_OFFICE_WING, _CELLULAR_WING),
    services=_SERVICES,
    services_area=26.0,
)

#: Bay typologies by key, with their bay plans.
BAY_TYPOLOGIES: dict[str, tuple[Typology, BayPlan]] = {
    "apartment_block": (APARTMENT_BLOCK, APARTMENT_BAYS),
    "office": (OFFICE, OFFICE_BAYS),
}
