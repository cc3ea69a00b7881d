"""Synthetic plans in the T2D file format, made by the tests themselves (the real data set stays
outside the project): a rectangular or L-shaped apartment cut into rooms by guillotine splits."""

from __future__ import annotations

import json
import random
from pathlib import Path
from typing import Any

import numpy as np

CLASSES = [
    "outside", "living_room", "master_room", "kitchen", "bathroom", "dining_room",
    "common_room", "balcony", "entrance", "storage",
]
_OTHER_TYPES = ["master_room", "kitchen", "bathroom", "common_room", "balcony", "common_room"]


def _split(rng: random.Random, box: tuple[int, int, int, int], n: int) -> list[tuple[int, int, int, int]]:
    """Guillotine-split a (r0, c0, r1, c1) box (half-open) into n boxes at least 4 cells a side."""
    boxes = [box]
    while len(boxes) < n:
        boxes.sort(key=lambda b: (b[2] - b[0]) * (b[3] - b[1]))
        r0, c0, r1, c1 = boxes.pop()
        if r1 - r0 >= c1 - c0 and r1 - r0 >= 8:
            cut = rng.randint(r0 + 4, r1 - 4)
            boxes += [(r0, c0, cut, c1), (cut, c0, r1, c1)]
        elif c1 - c0 >= 8:
            cut = rng.randint(c0 + 4, c1 - 4)
            boxes += [(r0, c0, r1, cut), (r0, cut, r1, c1)]
        else:
            boxes.append((r0, c0, r1, c1))
            break
    return boxes


def make_plan(seed: int) -> dict[str, Any]:
    """One plan: label64 (row 0 = top), rooms with pixel centroids and areas, adjacency."""
    rng = random.Random(seed)
    h, w = rng.randint(24, 34), rng.randint(26, 36)
    r0, c0 = rng.randint(6, 60 - h), rng.randint(6, 60 - w)
    rooms_map = np.full((64, 64), -1, dtype=np.int32)
    boxes = _split(rng, (r0, c0, r0 + h, c0 + w), rng.randint(4, 6))
    if seed % 2:  # an L: drop a corner box from the outline when there is one to spare
        boxes.sort(key=lambda b: (b[0], b[1]))
        boxes = boxes[1:] if len(boxes) > 4 else boxes
    # the largest box is the living room (every T2D plan has exactly one)
    boxes.sort(key=lambda b: -(b[2] - b[0]) * (b[3] - b[1]))
    types = ["living_room"] + [_OTHER_TYPES[i % len(_OTHER_TYPES)] for i in range(len(boxes) - 1)]
    for k, (a, b, c, d) in enumerate(boxes):
        rooms_map[a:c, b:d] = k
    label64 = np.zeros((64, 64), dtype=np.int32)
    rooms = []
    for k, t in enumerate(types):
        a, b, c, d = boxes[k]
        rows, cols = np.nonzero(rooms_map == k)
        label64[rows, cols] = CLASSES.index(t)
        rooms.append(
            {
                "id": k,
                "type": t,
                # pixel geometry of the 256 image: cell (r, c) is pixels [4c, 4c+4) × [4r, 4r+4)
                "area_px": int(16 * rows.size),
                "centroid": [float(4 * (cols.mean() + 0.5)), float(4 * (rows.mean() + 0.5))],
                "bbox": [int(4 * cols.min()), int(4 * rows.min()), int(4 * cols.max() + 4), int(4 * rows.max() + 4)],
                # the room's box as a pixel outline (x right, y down)
                "polygon": [[4 * b, 4 * a], [4 * d, 4 * a], [4 * d, 4 * c], [4 * b, 4 * c]],
            }
        )
    adjacency = set()
    for arr in (rooms_map, rooms_map.T):
        a, b = arr[:-1], arr[1:]
        m = (a >= 0) & (b >= 0) & (a != b)
        for x, y in zip(a[m], b[m]):
            adjacency.add((int(min(x, y)), int(max(x, y))))
    return {
        "source": f"synthetic-{seed}",
        "canvas": [256, 256],
        "footprint": [],
        "rooms": rooms,
        "adjacency": sorted(adjacency),
        "front_door": None,
        "classes": CLASSES,
        "label64": label64.tolist(),
    }


def write_plans(folder: Path, seeds: range) -> Path:
    plans = folder / "plans"
    plans.mkdir(parents=True, exist_ok=True)
    for s in seeds:
        (plans / f"{s}.json").write_text(json.dumps(make_plan(s)))
    return folder
