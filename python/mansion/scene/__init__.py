"""The scene stage: simulator-ready AI2-THOR houses (one per floor) and the building manifest,
their validation and their pictures."""

from mansion.scene.house import HOUSE_SCHEMA, House, house_json_schema
from mansion.scene.instantiate import BuildingScenes, build_scenes, ceiling_height, floor_house
from mansion.scene.manifest import BuildingManifest
from mansion.scene.validate import Problem, validate_building, validate_house, validate_path
from mansion.scene.write import write_scenes

__all__ = [
    "HOUSE_SCHEMA",
    "BuildingManifest",
    "BuildingScenes",
    "House",
    "Problem",
    "build_scenes",
    "ceiling_height",
    "floor_house",
    "house_json_schema",
    "validate_building",
    "validate_house",
    "validate_path",
    "write_scenes",
]
