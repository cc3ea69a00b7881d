"""A dataset building's picture: every floor's plan side by side, drawn with Pillow.

``mansion generate`` draws with matplotlib (labels fitted to each room, hatched cores), which
takes longer than generating the building: 5–40 s for a ten-storey office on this machine against
its 4 s of generation. A dataset wants a picture to browse, not a drawing to read, so this one
fills each room with its colour, outlines it and names only the floors; it takes milliseconds.
"""

from __future__ import annotations

import io
import math
import os
from pathlib import Path
from typing import Any

from mansion._io import atomic_write_bytes

__all__ = ["draw_plans"]

#: matplotlib's tab20, so rooms look as in ``mansion generate``'s pictures.
_TAB20 = (
    (31, 119, 180), (174, 199, 232), (255, 127, 14), (255, 187, 120), (44, 160, 44),
    (152, 223, 138), (214, 39, 40), (255, 152, 150), (148, 103, 189), (197, 176, 213),
    (140, 86, 75), (196, 156, 148), (227, 119, 194), (247, 182, 210), (127, 127, 127),
    (199, 199, 199), (188, 189, 34), (219, 219, 141), (23, 190, 207), (158, 218, 229),
)
_CORE = (209, 209, 209)


def draw_plans(building: Any, path: str | os.PathLike[str], *, pixels_per_metre: float = 8.0) -> Path:
    """Every floor of ``building`` (ground first, up to three a row, one scale) to a PNG."""
    from PIL import Image, ImageDraw

    xs = [x for f in building.floors for r in f.layout.rooms for x, _ in r.polygon]
    ys = [y for f in building.floors for r in f.layout.rooms for _, y in r.polygon]
    x0, y0 = min(xs), min(ys)
    margin, caption = 10, 14
    pw = math.ceil((max(xs) - x0) * pixels_per_metre) + 2 * margin
    ph = math.ceil((max(ys) - y0) * pixels_per_metre) + 2 * margin + caption
    n = len(building.floors)
    cols = min(n, 3 if n > 4 else n)
    rows = math.ceil(n / cols)
    image = Image.new("RGB", (pw * cols, ph * rows), "white")
    draw = ImageDraw.Draw(image)
    for k, floor in enumerate(building.floors):
        ox, oy = (k % cols) * pw + margin, (k // cols) * ph + margin + caption

        def px(p: tuple[float, float], ox: int = ox, oy: int = oy) -> tuple[float, float]:
            # y up in the plan, down in the image
            return ox + (p[0] - x0) * pixels_per_metre, oy + (max(ys) - p[1]) * pixels_per_metre

        colour = 0
        for room in floor.layout.rooms:
            fill = _CORE if room.is_core else _TAB20[colour % len(_TAB20)]
            colour += 0 if room.is_core else 1
            draw.polygon([px(p) for p in room.polygon], fill=fill, outline=(0, 0, 0), width=1)
            for hole in room.holes:
                draw.polygon([px(p) for p in hole], fill="white", outline=(0, 0, 0), width=1)
        copy = f" = floor {floor.copy_of}" if floor.copy_of is not None else ""
        draw.text((ox, oy - caption), f"floor {floor.index}{copy}", fill=(0, 0, 0))
    buf = io.BytesIO()
    image.save(buf, format="PNG", optimize=False)
    return atomic_write_bytes(path, buf.getvalue())
