"""The AI2-THOR procedural house format, schema "1.0.0", as pydantic models.

Field names and nesting mirror the simulator's own definitions (allenai/ai2thor,
``unity/Assets/Scripts/ProceduralData.cs``: ``ProceduralHouse``, ``RoomHierarchy``,
``PolygonWall``, ``Door``, ``Window``, ``HouseObject``, ``ProceduralParameters``,
``HouseMetadata``); Python attributes are snake_case and the JSON keys camelCase, exactly as the
loader reads them. Extra keys are kept (the loader ignores keys it does not know, and ProcTHOR and
Holodeck files carry some), so a house read and written again is unchanged.

What the format does not say and the simulator assumes (see docs/HOUSE_JSON.md): y is up, metres;
walls are one-sided (the visible face is on the right of p0→p1 seen from above); a hole's
``holePolygon`` is two points [min, max] in wall0's local frame (x along the wall from p0, y up);
one hole per wall.

Our own records ride in keys the loader ignores: ``rooms[i].metadata.core`` (a stair or elevator
core: kind, floors served, landing pose) and ``metadata.mansion`` (floor index, elevation, hub).
"""

from __future__ import annotations

import json
import os
import re
from pathlib import Path
from typing import Any, Literal

import pydantic_core
from pydantic import BaseModel, ConfigDict, Field, ValidationError
from pydantic.alias_generators import to_camel

from mansion._io import atomic_write_text
from mansion.exceptions import InvalidInputError
from mansion.models._validation import describe_validation_error

__all__ = [
    "HOUSE_SCHEMA",
    "AgentPose",
    "BoundingBox",
    "Ceiling",
    "Color",
    "CoreRecord",
    "Door",
    "FloorRecord",
    "Furnishing",
    "House",
    "HouseMetadata",
    "HouseObject",
    "Light",
    "MaterialProperties",
    "ProceduralParameters",
    "Roof",
    "Room",
    "RoomFurnishing",
    "RoomMetadata",
    "ShadowParameters",
    "Vec3",
    "Wall",
    "Window",
    "house_json_schema",
    "house_text",
]

#: The value of ``metadata.schema`` this module reads and writes.
HOUSE_SCHEMA = "1.0.0"


class _Thor(BaseModel):
    """camelCase JSON keys, snake_case attributes; unknown keys kept; no NaN or infinity."""

    model_config = ConfigDict(
        alias_generator=to_camel,
        populate_by_name=True,
        serialize_by_alias=True,
        extra="allow",
        allow_inf_nan=False,
    )


class Vec3(_Thor):
    x: float
    y: float
    z: float


class Color(_Thor):
    r: float = Field(ge=0.0, le=1.0)
    g: float = Field(ge=0.0, le=1.0)
    b: float = Field(ge=0.0, le=1.0)
    a: float = Field(default=1.0, ge=0.0, le=1.0)


class MaterialProperties(_Thor):
    """A material by name from the simulator's material database, optionally tinted.

    Schema 1.0.0 wants this object; the bare string of the 0.0.1 format breaks loading.
    """

    name: str | None = None
    color: Color | None = None
    shader: str | None = None
    unlit: bool | None = None
    tiling_divisor_x: float | None = None
    tiling_divisor_y: float | None = None
    metallic: float | None = None
    smoothness: float | None = None


class AgentPose(_Thor):
    """A pose for ``TeleportFull``: position (y = 0.95 puts the agent on the floor), yaw in
    ``rotation.y`` (degrees, 0 faces +z), camera horizon in degrees."""

    position: Vec3
    rotation: Vec3
    horizon: float = 30.0
    standing: bool | None = True


class CoreRecord(_Thor):
    """A stair or elevator core as the exporters and the cross-floor skills need it.

    AI2-THOR has no stair or elevator asset: the flights, the car and the slab openings are
    geometry the exporters build from this record.
    """

    id: str
    kind: Literal["stair", "elevator"]
    floors: list[int] = Field(min_length=1, description="Every floor the core serves.")
    box: tuple[float, float, float, float] = Field(description="x0, z0, x1, z1 in metres.")
    door: str | None = Field(default=None, description="Id of the core's door on this floor.")
    landing_room: str | None = Field(default=None, description="The room the door opens into.")
    landing: AgentPose | None = Field(
        default=None, description="Where an agent arriving on this floor stands, facing outward."
    )


class RoomMetadata(_Thor):
    core: CoreRecord | None = None
    role: str | None = Field(default=None, description="'hub' for the floor's circulation hub.")
    part_of: str | None = Field(
        default=None, description="The layout room this room is a part of (rooms with holes are "
        "cut into simple parts joined by empty walls)."
    )


class Ceiling(_Thor):
    id: str
    polygon: list[Vec3]
    material: MaterialProperties | None = None


class Room(_Thor):
    """``RoomHierarchy``: a floor polygon at y = 0 with its material."""

    id: str = Field(min_length=1)
    room_type: str
    floor_material: MaterialProperties
    floor_polygon: list[Vec3] = Field(min_length=3)
    ceilings: list[Ceiling] = Field(default_factory=list)
    layer: str | None = None
    children: list[Any] | None = None
    metadata: RoomMetadata | None = None


class Wall(_Thor):
    """``PolygonWall``: one side of a wall. The loader takes the two lowest points of
    ``polygon`` as p0→p1 and shows the face on the right of that direction seen from above."""

    id: str = Field(min_length=1)
    room_id: str
    polygon: list[Vec3] = Field(min_length=3)
    material: MaterialProperties | None = None
    empty: bool = False
    thickness: float | None = None
    layer: str | None = None

    def segment(self) -> tuple[tuple[float, float], tuple[float, float]]:
        """The wall's foot p0 → p1 on the floor plane (x, z), read as the loader reads it: the
        two lowest points of ``polygon``, in their order."""
        pts = sorted(self.polygon, key=lambda p: p.y)
        return (pts[0].x, pts[0].z), (pts[1].x, pts[1].z)


class _Hole(_Thor):
    """What doors and windows share (``WallRectangularHole``)."""

    id: str = Field(min_length=1)
    asset_id: str
    room0: str
    room1: str
    wall0: str
    wall1: str
    hole_polygon: list[Vec3] = Field(
        min_length=2, max_length=2, description="[min, max] corners in wall0's local frame."
    )
    asset_position: Vec3 = Field(description="The hole's centre in wall0's local frame.")
    openable: bool = False
    openness: float = Field(default=0.0, ge=0.0, le=1.0)
    type: str | None = None
    material: MaterialProperties | None = None
    scale: Vec3 | None = None
    color: Color | None = None


class Door(_Hole):
    swing_room: str | None = Field(
        default=None,
        description="Ours: the room the leaf swings into (the furniture keeps the square of the "
        "door's width free there, an apron on the other side).",
    )


class Window(_Hole):
    pass


class BoundingBox(_Thor):
    min: Vec3
    max: Vec3


class HouseObject(_Thor):
    """A placed asset; ``position`` is the centre of its world bounding box."""

    id: str = Field(min_length=1)
    asset_id: str
    position: Vec3
    rotation: Vec3 = Field(default_factory=lambda: Vec3(x=0.0, y=0.0, z=0.0))
    kinematic: bool = True
    children: list[HouseObject] = Field(default_factory=list)
    room: str | None = None
    tucked_under: str | None = Field(
        default=None,
        description="Ours: the table or desk this chair or stool is pushed under (they may overlap).",
    )
    bounding_box: BoundingBox | None = None
    layer: str | None = None
    openness: float | None = None
    is_on: bool | None = None
    is_dirty: bool | None = None
    material: MaterialProperties | None = None


class ShadowParameters(_Thor):
    type: str = "Soft"
    strength: float = 1.0
    normal_bias: float = 0.0
    bias: float = 0.05
    near_plane: float = 0.2
    resolution: str = "FromQualitySettings"


class Light(_Thor):
    id: str = Field(min_length=1)
    type: Literal["point", "directional", "spot"]
    position: Vec3
    rotation: Vec3 | None = None
    intensity: float = Field(ge=0.0)
    indirect_multiplier: float | None = None
    range: float | None = None
    rgb: Color
    shadow: ShadowParameters | None = None
    room_id: str | None = None
    layer: str | None = None
    culling_mask_off: list[str] | None = None


class ProceduralParameters(_Thor):
    floor_collider_thickness: float = 1.0
    receptacle_height: float = 0.7
    skybox_id: str
    lights: list[Light] = Field(default_factory=list)
    ceiling_material: MaterialProperties
    ceiling_color: Color | None = None
    reflections: list[Any] = Field(default_factory=list)


class Roof(_Thor):
    material: MaterialProperties | None = None
    asset_id: str | None = None


class RoomFurnishing(_Thor):
    """How one room was furnished: ``furnished`` (objects placed), ``empty`` (the engine placed
    nothing of its plan), ``skipped`` (a core or circulation, left clear on purpose) or
    ``failed`` (the engine could not furnish it, e.g. its entrances do not reach each other;
    the room keeps no objects)."""

    status: Literal["furnished", "empty", "skipped", "failed"]
    reason: str | None = None
    objects: int = Field(default=0, ge=0)
    small_objects: int = Field(default=0, ge=0)
    dropped: int = Field(default=0, ge=0, description="Plan copies the engine could not place.")


class Furnishing(_Thor):
    """Our record of the floor's object placement."""

    planner: str = "offline"
    agent_radius: float = Field(gt=0.0)
    rooms: dict[str, RoomFurnishing] = Field(default_factory=dict)

    @property
    def failed(self) -> list[str]:
        return sorted(r for r, f in self.rooms.items() if f.status == "failed")


class FloorRecord(_Thor):
    """Our record of which floor of which building this house is."""

    building: str
    floor: int = Field(ge=0)
    floor_count: int = Field(ge=1)
    elevation: float = Field(description="Height of this floor's slab above the ground floor, m.")
    ceiling_height: float = Field(gt=0.0)
    hub: str = Field(description="Id of the floor's circulation hub (the agent's start room).")
    copy_of: int | None = None
    furnishing: Furnishing | None = None


class HouseMetadata(_Thor):
    schema_version: str = Field(default=HOUSE_SCHEMA, alias="schema")
    agent_poses: dict[str, AgentPose] = Field(default_factory=dict)
    mansion: FloorRecord | None = None


class House(_Thor):
    """``ProceduralHouse``: one floor of a building, loadable with ``controller.reset(scene=house)``.

    ``id`` is optional, as for the loader (it names the root object ``Floor`` without one)."""

    id: str | None = None
    procedural_parameters: ProceduralParameters
    rooms: list[Room] = Field(default_factory=list)
    walls: list[Wall] = Field(default_factory=list)
    doors: list[Door] = Field(default_factory=list)
    windows: list[Window] = Field(default_factory=list)
    objects: list[HouseObject] = Field(default_factory=list)
    roof: Roof | None = None
    metadata: HouseMetadata

    def to_dict(self) -> dict[str, Any]:
        """The JSON object the simulator reads (unset optional fields left out)."""
        return self.model_dump(mode="json", exclude_none=True)

    def to_json(self, path: str | os.PathLike[str], *, indent: int | None = 1) -> Path:
        """Write the house, atomically. Returns the path."""
        return atomic_write_text(path, house_text(self.to_dict(), indent=indent))

    @classmethod
    def parse(cls, data: Any, *, source: str = "house") -> House:
        """Validate a dict as a house; problems are one :class:`InvalidInputError`."""
        try:
            return cls.model_validate(data)
        except ValidationError as exc:
            raise InvalidInputError(f"{source}: {describe_validation_error(exc)}") from exc

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> House:
        p = Path(path)
        try:
            data = json.loads(p.read_text(encoding="utf-8"))
        except (OSError, ValueError) as exc:
            raise InvalidInputError(f"cannot read house JSON {str(p)!r}: {exc}") from exc
        return cls.parse(data, source=str(p))


def house_json_schema() -> dict[str, Any]:
    """The JSON Schema of the house format as these models read it."""
    schema = House.model_json_schema(by_alias=True, mode="validation")
    schema["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    schema["title"] = f"AI2-THOR procedural house (schema {HOUSE_SCHEMA}), as written by mansion"
    return schema


def house_text(data: dict[str, Any], *, indent: int | None = 1) -> str:
    """A house JSON object as every house file mansion writes holds it (:meth:`House.to_json`):
    edits, variants and exports compare files byte for byte, so they all write through this.

    Encoded by pydantic's serializer, not :func:`json.dumps`, whose indented output takes the
    pure-Python path (a seven-storey building's floors: 29 against 227 ms). The text is the same
    as ``json.dumps(data, indent=indent)`` (non-ASCII characters escaped likewise) except that
    numbers between 1e-7 and 1e-4 are written in full (``0.00001``, not ``1e-05``): the same
    values."""
    if indent is None:  # json.dumps's C encoder, with its ", " and ": " separators
        return json.dumps(data) + "\n"
    text = pydantic_core.to_json(data, indent=indent).decode("utf-8")
    if _NON_ASCII.search(text):
        text = _NON_ASCII.sub(_escape, text)
    return text + "\n"


_NON_ASCII = re.compile(r"[^\x00-\x7f]")


def _escape(match: re.Match[str]) -> str:
    """A character outside ASCII as json.dumps escapes it (two UTF-16 halves beyond U+FFFF);
    outside strings a JSON text holds none."""
    code = ord(match.group())
    if code > 0xFFFF:
        code -= 0x10000
        return f"\\u{0xD800 + (code >> 10):04x}\\u{0xDC00 + (code & 0x3FF):04x}"
    return f"\\u{code:04x}"
