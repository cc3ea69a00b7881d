"""Colours for AI2-THOR material names, and the fixed looks of what the houses do not colour.

The material database lists names only ("WoodFloorsCrossRED", "DrywallEggshell"); the textures
live in the simulator. A name reads as words (the same reading the scene stage uses to pick
materials), and the words give a colour: the surface kind a base (wood, brick, marble, ...), colour
words a hue, "dark"/"light" a shade. A house's own tint (``material.color``) wins.
"""

from __future__ import annotations

import hashlib
from functools import cache

import numpy as np

from mansion.export.model import Look
from mansion.scene.house import MaterialProperties
from mansion.scene.materials import _words as material_words

__all__ = ["CAR", "DOOR", "GLASS", "STEP", "WINDOW_FRAME", "material_look", "object_look"]

_KINDS: dict[str, tuple[float, float, float]] = {
    "wood": (0.66, 0.48, 0.30), "planks": (0.66, 0.48, 0.30), "brick": (0.65, 0.32, 0.25),
    "bricks": (0.65, 0.32, 0.25), "marble": (0.90, 0.89, 0.86), "granite": (0.52, 0.51, 0.50),
    "concrete": (0.63, 0.63, 0.61), "carpet": (0.52, 0.47, 0.42), "tiles": (0.86, 0.86, 0.84),
    "ceramic": (0.88, 0.88, 0.86), "drywall": (0.90, 0.89, 0.86), "plaster": (0.90, 0.88, 0.84),
    "stone": (0.70, 0.68, 0.64), "metal": (0.70, 0.71, 0.73),
}
_HUES: dict[str, tuple[float, float, float]] = {
    "white": (0.94, 0.94, 0.92), "pure": (0.96, 0.96, 0.96), "eggshell": (0.94, 0.91, 0.83),
    "cream": (0.94, 0.90, 0.80), "creame": (0.94, 0.90, 0.80), "ivory": (0.95, 0.93, 0.85),
    "beige": (0.85, 0.78, 0.65), "sand": (0.85, 0.78, 0.62), "tan": (0.80, 0.68, 0.52),
    "grey": (0.58, 0.58, 0.58), "gray": (0.58, 0.58, 0.58), "black": (0.15, 0.15, 0.15),
    "red": (0.70, 0.25, 0.20), "orange": (0.86, 0.52, 0.22), "yellow": (0.90, 0.82, 0.36),
    "green": (0.42, 0.60, 0.38), "blue": (0.36, 0.50, 0.76), "turquoise": (0.30, 0.70, 0.70),
    "pink": (0.90, 0.66, 0.70), "rose": (0.88, 0.62, 0.66), "brown": (0.46, 0.31, 0.20),
    "purple": (0.55, 0.40, 0.65),
}
_DEFAULT = (0.86, 0.85, 0.82)

DOOR = Look("door", (0.55, 0.38, 0.22, 1.0))
WINDOW_FRAME = Look("window_frame", (0.92, 0.92, 0.92, 1.0))
GLASS = Look("glass", (0.65, 0.82, 0.92, 0.35))
STEP = Look("stair_concrete", (0.70, 0.70, 0.68, 1.0))
CAR = Look("elevator_car", (0.72, 0.74, 0.77, 1.0))


@cache
def _name_colour(name: str) -> tuple[float, float, float]:
    words = material_words(name)
    kinds = [c for w, c in _KINDS.items() if w in words]
    hues = [c for w, c in _HUES.items() if w in words]
    base = np.array(kinds[0] if kinds else _DEFAULT)
    # A colour word sets the hue; the surface kind keeps a third of its own (oak stays woody).
    if hues:
        base = 0.35 * base + 0.65 * np.mean(hues, axis=0)
    if "dark" in words:
        base = 0.55 * base
    if "light" in words or "pale" in words:
        base = base + 0.4 * (1.0 - base)
    r, g, b = (round(float(min(1.0, c)), 4) for c in base)
    return r, g, b


def material_look(material: MaterialProperties | None, fallback: str) -> Look:
    """The look of a house material: its tint when it has one, else its name's colour."""
    if material is None or (material.name is None and material.color is None):
        return Look(fallback, (*_name_colour(fallback), 1.0))
    name = material.name or fallback
    if material.color is not None:
        c = material.color
        return Look(f"{name}_{c.r:.3f}_{c.g:.3f}_{c.b:.3f}", (c.r, c.g, c.b, c.a))
    return Look(name, (*_name_colour(name), 1.0))


@cache
def object_look(object_type: str) -> Look:
    """A furniture colour per object type, stable across runs: mid tones, so objects stand out
    against pale floors and walls."""
    h = hashlib.blake2b(object_type.encode(), digest_size=3).digest()
    rgb = tuple(round(0.30 + 0.45 * b / 255, 4) for b in h)
    return Look(f"object_{object_type}", (*rgb, 1.0))  # type: ignore[arg-type]
