"""Shared helpers for the scene tests: the golden building and rounding for comparisons."""

from __future__ import annotations

import json
import math
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


def box_house(
    rooms: dict[str, tuple[float, float, float, float]],
    doors: list[tuple[str, str, float]],
    spawn: tuple[float, float],
    objects: list[dict[str, Any]] | None = None,
    *,
    furnished: bool = True,
) -> dict[str, Any]:
    """A small valid house JSON by hand: axis-aligned box rooms (x0, z0, x1, z1), a door of the
    given width in the middle of the wall two rooms share, the spawn, and ``objects``. With
    ``furnished`` the house records mansion's furnishing (its furniture promises the agent's
    room). For the navigability tests: cases the layouts we generate may never produce."""
    from mansion.scene.databases import hole_asset_position

    height = 2.7

    def pt(x: float, z: float, y: float = 0.0) -> dict[str, float]:
        return {"x": x, "y": y, "z": z}

    def edges(r: str) -> list[tuple[tuple[float, float], tuple[float, float]]]:
        x0, z0, x1, z1 = rooms[r]
        # clockwise in (x, z): the room lies on the right of each wall
        ring = [(x0, z0), (x0, z1), (x1, z1), (x1, z0)]
        return list(zip(ring, ring[1:] + ring[:1]))

    cuts = sorted({v for b in rooms.values() for v in b})
    walls: list[dict[str, Any]] = []
    pieces: dict[tuple[Any, ...], str] = {}
    for r in rooms:
        for (ax, az), (bx, bz) in edges(r):
            horizontal = az == bz
            lo, hi = sorted((ax, bx) if horizontal else (az, bz))
            stops = [lo, *[c for c in cuts if lo < c < hi], hi]
            if (ax, az) > (bx, bz):
                stops = stops[::-1]
            for s, t in zip(stops, stops[1:]):
                p0 = (s, az) if horizontal else (ax, s)
                p1 = (t, az) if horizontal else (ax, t)
                wid = f"wall|{r}|{len(walls)}"
                walls.append({"id": wid, "roomId": r, "material": {"name": "PureWhite"},
                              "polygon": [pt(*p0), pt(*p1), pt(*p1, height), pt(*p0, height)]})
                pieces[(r, p0, p1)] = wid
    twin_of: dict[str, str] = {}
    for (r, p0, p1), wid in list(pieces.items()):
        other = next((w for (q, a, b), w in pieces.items() if q != r and a == p1 and b == p0), None)
        if other is None:
            ext = f"wall|exterior|{wid}"
            walls.append({"id": ext, "roomId": r, "material": {"name": "PureWhite"},
                          "polygon": [pt(*p1), pt(*p0), pt(*p0, height), pt(*p1, height)]})
            other = ext
        twin_of[wid] = other
    out_doors = []
    for k, (a, b, width) in enumerate(doors):
        wid, (p0, p1) = next((w, (pa, pb)) for (r, pa, pb), w in pieces.items()
                             if r == a and twin_of[w] in {x for (q, _, _), x in pieces.items() if q == b})
        n = math.dist(p0, p1)
        lo, hi = (n - width) / 2, (n + width) / 2
        x, y = hole_asset_position("Doorway_1", (lo, 0.0)) or ((lo + hi) / 2, 1.0)
        out_doors.append({
            "id": f"door|{k}", "assetId": "Doorway_1", "room0": a, "room1": b, "wall0": wid,
            "wall1": twin_of[wid], "holePolygon": [{"x": lo, "y": 0.0, "z": 0.0}, {"x": hi, "y": 2.1, "z": 0.0}],
            "assetPosition": {"x": x, "y": y, "z": 0.0}, "openable": True, "openness": 1.0,
        })
    metadata: dict[str, Any] = {
        "schema": "1.0.0",
        "agentPoses": {"default": {"position": pt(spawn[0], spawn[1], 0.95),
                                   "rotation": pt(0.0, 0.0), "horizon": 30.0, "standing": True}},
    }
    if furnished:
        metadata["mansion"] = {
            "building": "box", "floor": 0, "floorCount": 1, "elevation": 0.0,
            "ceilingHeight": height, "hub": next(iter(rooms)),
            "furnishing": {"planner": "offline", "agentRadius": 0.25, "rooms": {}},
        }
    return {
        "proceduralParameters": {"skyboxId": "SkyMountain", "ceilingMaterial": {"name": "PureWhite"},
                                 "lights": []},
        "rooms": [{"id": r, "roomType": "Bedroom", "floorMaterial": {"name": "PureWhite"},
                   "floorPolygon": [pt(*p) for p, _ in edges(r)]} for r in rooms],
        "walls": walls, "doors": out_doors, "windows": [], "objects": objects or [],
        "metadata": metadata,
    }
