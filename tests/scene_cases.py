"""Shared helpers for the scene tests: the golden building and rounding for comparisons."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from mansion.building import generate_building
from mansion.models.building import Building
from mansion.scene import build_scenes

GOLDEN = Path(__file__).parent / "golden" / "villa-3"


def golden_building() -> Building:
    """A small building with a stair core on two floors: the golden test pins its scenes."""
    return generate_building("a 2-storey villa", building_type="villa", floors=2, seed=3)


def rounded(value: Any, digits: int = 4) -> Any:
    """``value`` with every float rounded, so platform float noise does not fail a comparison."""
    if isinstance(value, float):
        return round(value, digits) + 0.0
    if isinstance(value, dict):
        return {k: rounded(v, digits) for k, v in value.items()}
    if isinstance(value, list):
        return [rounded(v, digits) for v in value]
    return value


def golden_payload() -> dict[str, Any]:
    """Every floor's house JSON and the manifest of the golden building, rounded."""
    scenes = build_scenes(golden_building())
    out: dict[str, Any] = {"manifest.json": json.loads(scenes.manifest.model_dump_json())}
    for floor, house in zip(scenes.manifest.floors, scenes.houses, strict=True):
        out[floor.house] = house.to_dict()
    return rounded(out)


def write_golden() -> None:
    GOLDEN.mkdir(parents=True, exist_ok=True)
    for name, data in golden_payload().items():
        (GOLDEN / name).write_text(json.dumps(data, indent=1, sort_keys=True) + "\n")


if __name__ == "__main__":
    write_golden()
