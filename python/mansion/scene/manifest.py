"""The building manifest: how the per-floor house JSONs stack into one building.

AI2-THOR has no levels, so each floor is its own house; the manifest gives every floor its
height, elevation and house file, and every vertical core its box, the floors it serves and, per
floor, the landing pose (in the room outside the core's door, facing outward) the cross-floor
skills put an agent at.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Literal

from pydantic import BaseModel, ConfigDict, Field

from mansion._io import atomic_write_text
from mansion.models._validation import load_written
from mansion.scene.house import AgentPose

__all__ = ["MANIFEST_SCHEMA_VERSION", "BuildingManifest", "CoreLanding", "ManifestCore", "ManifestFloor"]

MANIFEST_SCHEMA_VERSION = "1.0"


class ManifestFloor(BaseModel):
    model_config = ConfigDict(allow_inf_nan=False)

    index: int = Field(ge=0)
    house: str = Field(description="The floor's house JSON, relative to the manifest.")
    elevation: float = Field(description="Height of the floor's slab above the ground floor, m.")
    height: float = Field(gt=0.0, description="Floor-to-floor height, m.")
    ceiling_height: float = Field(gt=0.0)
    hub: str
    spawn: AgentPose
    copy_of: int | None = None
    entrance: str | None = Field(
        default=None, description="The ground floor's front door (id of its door to the outside)."
    )


class CoreLanding(BaseModel):
    floor: int = Field(ge=0)
    room: str = Field(description="The room the core's door opens into.")
    door: str | None = Field(description="The core's door on this floor (None: an opening).")
    pose: AgentPose = Field(description="Just outside the door, facing away from the core.")
    core_room: str | None = Field(
        default=None,
        # left out when None, so mansion's own manifests keep their bytes
        exclude_if=lambda v: v is None,
        description="The core's own room on this floor when its id is not the core's (a "
        "MansionWorld building names it per floor: F2_stair); None: the room is the core's id.",
    )


class ManifestCore(BaseModel):
    model_config = ConfigDict(allow_inf_nan=False)

    id: str
    kind: Literal["stair", "elevator"]
    x: tuple[float, float] = Field(description="x0, x1 of the core's box (scene x), m.")
    z: tuple[float, float] = Field(description="z0, z1 of the core's box (scene z = plan y), m.")
    floors: list[int] = Field(min_length=1)
    landings: list[CoreLanding]

    def room_on(self, floor: int) -> str:
        """The id of the core's room on ``floor`` (its own id unless the landing names another)."""
        landing = next((l for l in self.landings if l.floor == floor), None)
        return landing.core_room if landing is not None and landing.core_room else self.id


class BuildingManifest(BaseModel):
    """``manifest.json`` beside the floors' house JSONs."""

    schema_version: str = MANIFEST_SCHEMA_VERSION
    id: str
    description: str
    building_type: str
    seed: int
    floors: list[ManifestFloor]
    cores: list[ManifestCore] = Field(default_factory=list)

    def to_json(self, path: str | os.PathLike[str]) -> Path:
        return atomic_write_text(path, self.model_dump_json(indent=2) + "\n")

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> BuildingManifest:
        return load_written(cls, path, "manifest")
