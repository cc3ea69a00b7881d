"""Top-down pictures for agents and for people, drawn with Pillow (no plotting library).

``FloorPainter`` draws a floor once (rooms, walls, doors open or shut, objects, core landings) and
then crops the agent's surroundings from it for every observation, so an observation costs a crop,
a resize and an arrow. ``draw_episode`` draws an agent's walk across the floors it visited, one
panel per floor, side by side.
"""

from __future__ import annotations

import hashlib
import math
from pathlib import Path
from typing import Any

import numpy as np
from PIL import Image, ImageDraw, ImageFont

from mansion._io import atomic_write_bytes
from mansion.sim.world import HELD_KEY, FloorState

__all__ = ["FloorPainter", "draw_episode"]

#: Pixels per metre of the floor picture the observations are cropped from.
PX = 24
#: The agent's surroundings shown in an observation (m across).
VIEW = 8.0
_WALL = (30, 30, 30)
_OUTSIDE = (250, 250, 250)


def _room_colour(room_type: str) -> tuple[int, int, int]:
    h = hashlib.blake2b(room_type.encode(), digest_size=3).digest()
    return tuple(int(184 + 64 * b / 255) for b in h)  # type: ignore[return-value]


class FloorPainter:
    def __init__(self, state: FloorState, px: int = PX, margin: float = VIEW / 2):
        self.version = state.version
        self.state_id = id(state)
        self.px = px
        xs = [p.x for r in state.house.rooms for p in r.floor_polygon]
        zs = [p.z for r in state.house.rooms for p in r.floor_polygon]
        self.x0, self.z0 = min(xs) - margin, min(zs) - margin
        self.w = int(math.ceil((max(xs) + margin - self.x0) * px))
        self.h = int(math.ceil((max(zs) + margin - self.z0) * px))
        img = Image.new("RGB", (self.w, self.h), _OUTSIDE)
        d = ImageDraw.Draw(img)
        for r in state.house.rooms:
            core = r.metadata.core if r.metadata else None
            fill = (170, 178, 196) if core else _room_colour(r.room_type)
            d.polygon([self.to_px(p.x, p.z) for p in r.floor_polygon], fill=fill)
        for info in state.objects.values():
            if info.parent is not None or (info.obj.model_extra or {}).get(HELD_KEY):
                continue
            d.polygon(self._box(info.centre, info.props.width, info.props.depth, info.obj.rotation.y),
                      fill=(150, 110, 80), outline=(90, 60, 40))
        for info in state.objects.values():
            if info.parent is not None and state.inside(info) is None:
                x, y = self.to_px(*info.centre)
                d.ellipse((x - 2, y - 2, x + 2, y + 2), fill=(240, 200, 40))
        for w in state.house.walls:
            if not w.empty:
                a, b = w.segment()
                d.line([self.to_px(*a), self.to_px(*b)], fill=_WALL, width=max(2, px // 10))
        walls = {w.id: w for w in state.house.walls}
        for door in state.house.doors:
            wall = walls.get(door.wall0)
            if wall is None:
                continue
            (ax, az), (bx, bz) = wall.segment()
            n = math.dist((ax, az), (bx, bz)) or 1.0
            lo, hi = door.hole_polygon[0].x, door.hole_polygon[1].x
            a = (ax + (bx - ax) * lo / n, az + (bz - az) * lo / n)
            b = (ax + (bx - ax) * hi / n, az + (bz - az) * hi / n)
            shut = door.openable and door.openness <= 0.0
            d.line([self.to_px(*a), self.to_px(*b)], fill=(200, 40, 40) if shut else (245, 160, 60),
                   width=max(3, px // 6))
        self.image = np.asarray(img)

    def stale(self, state: FloorState) -> bool:
        return state.version != self.version or id(state) != self.state_id

    def to_px(self, x: float, z: float) -> tuple[float, float]:
        # north (+z) up
        return ((x - self.x0) * self.px, (self.h - 1) - (z - self.z0) * self.px)

    def _box(self, c: tuple[float, float], w: float, dep: float, yaw: float) -> list[tuple[float, float]]:
        t = math.radians(yaw)
        ux, uz = math.cos(t), -math.sin(t)
        vx, vz = math.sin(t), math.cos(t)
        pts = []
        for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            pts.append(self.to_px(c[0] + su * w / 2 * ux + sv * dep / 2 * vx,
                                  c[1] + su * w / 2 * uz + sv * dep / 2 * vz))
        return pts

    def view(self, x: float, z: float, yaw: float, size: int, held: bool = False, span: float = VIEW) -> np.ndarray:
        """The ``span`` × ``span`` metres around (x, z), ``size`` px square, with the agent."""
        cx, cy = self.to_px(x, z)
        half = span / 2 * self.px
        left, top = int(round(cx - half)), int(round(cy - half))
        side = int(round(2 * half))
        crop = np.full((side, side, 3), _OUTSIDE, dtype=np.uint8)
        sx0, sy0 = max(left, 0), max(top, 0)
        sx1, sy1 = min(left + side, self.w), min(top + side, self.h)
        if sx1 > sx0 and sy1 > sy0:
            crop[sy0 - top:sy1 - top, sx0 - left:sx1 - left] = self.image[sy0:sy1, sx0:sx1]
        img = Image.fromarray(crop).resize((size, size), Image.Resampling.NEAREST)
        d = ImageDraw.Draw(img)
        s = size / side
        ax, ay = (cx - left) * s, (cy - top) * s
        r = 0.25 * self.px * s
        d.ellipse((ax - r, ay - r, ax + r, ay + r), fill=(40, 110, 220) if not held else (40, 170, 90))
        t = math.radians(yaw)
        d.line([(ax, ay), (ax + math.sin(t) * 2.5 * r, ay - math.cos(t) * 2.5 * r)], fill=(20, 20, 120), width=max(2, size // 96))
        return np.asarray(img)


def _wrap(text: str, font: Any, width: float) -> list[str]:
    lines, line = [], ""
    for word in text.split():
        trial = f"{line} {word}".strip()
        if line and font.getlength(trial) > width:
            lines.append(line)
            line = word
        else:
            line = trial
    return lines + ([line] if line else [])


def draw_episode(states: dict[int, FloorState], trace: list[tuple[int, list[tuple[float, float]]]],
                 out: str | Path, title: str = "", marks: dict[int, list[tuple[float, float, str]]] | None = None,
                 px: int = 16) -> Path:
    """One panel per floor the agent visited (in building order), its walk drawn on each, the
    start green and the end red; ``marks``: labelled points per floor (the target, the goal)."""
    floors = sorted({f for f, _ in trace})
    panels = []
    font = ImageFont.load_default(size=max(12, px))
    for f in floors:
        painter = FloorPainter(states[f], px=px, margin=1.0)
        img = Image.fromarray(painter.image.copy())
        d = ImageDraw.Draw(img)
        for k, (floor, pts) in enumerate(trace):
            if floor != f or not pts:
                continue
            pix = [painter.to_px(*p) for p in pts]
            if len(pix) >= 2:
                d.line(pix, fill=(30, 90, 220), width=max(3, px // 4), joint="curve")
            for p, colour in ((pix[0], (40, 170, 60)), (pix[-1], (210, 40, 40))):
                d.ellipse((p[0] - px / 3, p[1] - px / 3, p[0] + px / 3, p[1] + px / 3), fill=colour)
        for x, z, label in (marks or {}).get(f, []):
            p = painter.to_px(x, z)
            d.rectangle((p[0] - px / 3, p[1] - px / 3, p[0] + px / 3, p[1] + px / 3), outline=(120, 0, 160), width=3)
            d.text((p[0] + px / 2, p[1] - px / 2), label, fill=(120, 0, 160), font=font)
        band = Image.new("RGB", (img.width, max(14, px) + 8), (255, 255, 255))
        ImageDraw.Draw(band).text((4, 2), f"floor {f}", fill=(0, 0, 0), font=font)
        panel = Image.new("RGB", (img.width, img.height + band.height), (255, 255, 255))
        panel.paste(band, (0, 0))
        panel.paste(img, (0, band.height))
        panels.append(panel)
    gap = 12
    w = sum(panel.width for panel in panels) + gap * (len(panels) - 1)
    lines = _wrap(title, font, w - 12) if title else []
    line_h = max(14, px) + 6
    head = line_h * len(lines) + (6 if lines else 0)
    h = max(panel.height for panel in panels) + head
    sheet = Image.new("RGB", (w, h), (255, 255, 255))
    x = 0
    for panel in panels:
        sheet.paste(panel, (x, head))
        x += panel.width + gap
    d = ImageDraw.Draw(sheet)
    for k, line in enumerate(lines):
        d.text((6, 4 + k * line_h), line, fill=(0, 0, 0), font=font)
    import io

    buf = io.BytesIO()
    sheet.save(buf, format="PNG", optimize=True)
    return atomic_write_bytes(out, buf.getvalue())
