"""A 3D picture of the building on the CPU: an axonometric view of its floors pulled apart
(exploded), walls cut away at sill height so the rooms, furniture and stairs show, like the
paper's teaser. A small z-buffer rasteriser over the model's triangles in numpy, saved with Pillow: no
display, no GPU, no OpenGL.
"""

from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw, ImageFont

from mansion._io import atomic_write_bytes
from mansion.export.model import BuildingModel, Node

__all__ = ["render_preview"]

#: Walls, doors, windows and the elevator car are cut at this height above their floor.
CUT = 1.2
_CUT_KINDS = {"wall", "door", "window", "elevator_car"}
_SKIP = {"roof", "glass"}
_BACKGROUND = (255, 255, 255)


def _camera(azimuth: float, elevation: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """right, up and view direction (into the picture) of a camera looking down from the
    (azimuth, elevation) direction, degrees."""
    a, e = math.radians(azimuth), math.radians(elevation)
    eye = np.array([math.cos(e) * math.sin(a), math.sin(e), math.cos(e) * math.cos(a)])
    forward = -eye
    right = np.cross(forward, [0.0, 1.0, 0.0])
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    return right, up, forward


def _layers(model: BuildingModel, gap: float) -> list[tuple[int, str, np.ndarray, tuple[float, float, float]]]:
    """(floor order, layer, triangles (m × 3 × 3, world), colour) of every visible mesh; each
    floor raised by ``gap`` per floor below it."""
    out = []
    for order, floor in enumerate(model.root.children):
        lift = np.array([0.0, floor.offset[1] + order * gap, 0.0])

        def visit(node: Node, origin: np.ndarray, order: int = order) -> None:
            here = origin + np.asarray(node.offset)
            if node.kind in _SKIP:
                return
            if node.mesh is not None and len(node.mesh[1]) and node.look is not None:
                v = node.mesh[0] + here
                if node.kind in _CUT_KINDS:
                    v = v.copy()
                    v[:, 1] = np.minimum(v[:, 1], lift[1] + CUT)
                layer = "slab" if node.kind == "room" else "body"
                out.append((order, layer, v[node.mesh[1]], node.look.rgba[:3]))
            for child in node.children:
                visit(child, here)

        for child in floor.children:
            visit(child, lift)
    return out


def _raster(tri: np.ndarray, colour: np.ndarray, zbuf: np.ndarray, cbuf: np.ndarray) -> None:
    """Fill one screen triangle (x, y in pixels, depth) where it is nearer than the z-buffer."""
    (x0, y0, d0), (x1, y1, d1), (x2, y2, d2) = tri
    area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
    if abs(area) < 1e-9:
        return
    h, w = zbuf.shape
    c0, c1 = max(int(min(x0, x1, x2)), 0), min(int(max(x0, x1, x2)) + 1, w)
    r0, r1 = max(int(min(y0, y1, y2)), 0), min(int(max(y0, y1, y2)) + 1, h)
    if c0 >= c1 or r0 >= r1:
        return
    px = np.arange(c0, c1) + 0.5
    py = (np.arange(r0, r1) + 0.5)[:, None]
    w0 = ((x1 - px) * (y2 - py) - (x2 - px) * (y1 - py)) / area
    w1 = ((x2 - px) * (y0 - py) - (x0 - px) * (y2 - py)) / area
    w2 = 1.0 - w0 - w1
    depth = w0 * d0 + w1 * d1 + w2 * d2
    sub = zbuf[r0:r1, c0:c1]
    hit = (w0 >= -1e-6) & (w1 >= -1e-6) & (w2 >= -1e-6) & (depth < sub)
    sub[hit] = depth[hit]
    cbuf[r0:r1, c0:c1][hit] = colour


def render_preview(
    model: BuildingModel, path: str | os.PathLike[str], *, size: int = 1600,
    azimuth: float = 215.0, elevation: float = 32.0, exploded: float | None = None,
    title: str | None = None,
) -> Path:
    """Draw ``model`` to a PNG at ``path`` (``size`` pixels on its longer side): floors stacked
    bottom to top, ``exploded`` metres apart (default: 0.9 × the ground floor's height, half
    that above four floors), seen from ``azimuth``/``elevation``."""
    floors = model.root.children
    heights = [float(n.info.get("height", 3.0)) for n in floors]
    gap = (0.9 if len(floors) <= 4 else 0.5) * (heights[0] if heights else 3.0) if exploded is None else exploded
    right, up, forward = _camera(azimuth, elevation)
    light = -np.array([0.4, -1.0, 0.25]) / np.linalg.norm([0.4, -1.0, 0.25])
    layers = _layers(model, gap)
    if not layers:
        raise ValueError("the building has no geometry to draw")

    allv = np.concatenate([t.reshape(-1, 3) for _, _, t, _ in layers])
    sx, sy = allv @ right, -(allv @ up)
    margin, head = 0.04, 70
    span_x, span_y = max(sx.max() - sx.min(), 1e-6), max(sy.max() - sy.min(), 1e-6)
    pad = 2 * margin * size
    scale = min((size - pad) / span_x, (size - pad - head) / span_y)
    width = int(span_x * scale + pad)
    height = int(span_y * scale + pad) + head
    ss = 2  # supersampling, for smooth edges
    ox = margin * size - sx.min() * scale
    oy = margin * size + head - sy.min() * scale

    zbuf = np.full((height * ss, width * ss), np.inf, np.float32)
    cbuf = np.empty((height * ss, width * ss, 3), np.uint8)
    cbuf[:] = _BACKGROUND
    for _order, _layer, tris, rgb in layers:
        normals = np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0])
        norm = np.linalg.norm(normals, axis=1)
        keep = (norm > 1e-12) & ((normals @ forward) < 0)  # facing the camera
        if not keep.any():
            continue
        tris, normals = tris[keep], normals[keep] / norm[keep, None]
        shade = 0.55 + 0.45 * np.clip(normals @ light, 0.0, 1.0)
        screen = np.stack([((tris @ right) * scale + ox) * ss, (-(tris @ up) * scale + oy) * ss, tris @ forward], axis=-1)
        colours = np.clip(np.asarray(rgb) * 255 * shade[:, None], 0, 255).astype(np.uint8)
        for tri, colour in zip(screen, colours, strict=True):
            _raster(tri, colour, zbuf, cbuf)

    img = Image.fromarray(cbuf)
    img = img.resize((width, height), Image.Resampling.LANCZOS)
    draw = ImageDraw.Draw(img)
    font = ImageFont.load_default(size=22)
    label = title or str(model.root.info.get("description") or model.root.name)
    draw.text((margin * size, 18), f"{label}: {len(floors)} floors", fill=(30, 30, 30), font=font)
    from io import BytesIO

    buf = BytesIO()
    # Flat-shaded faces need few colours: a 256-colour palette keeps the file a third the size.
    img.quantize(colors=256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE).save(buf, format="PNG", optimize=True)
    return atomic_write_bytes(path, buf.getvalue())
