"""Top-down pictures of house JSONs: rooms, walls, doors, windows, objects and agent poses.

Drawn from the JSON itself (not from the layout), so the picture shows what the simulator will
load: a wall drawn is a wall written, a gap is an empty wall, a door sits where its hole is.
"""

from __future__ import annotations

import hashlib
import math
import os
from pathlib import Path

from mansion.exceptions import InvalidInputError
from mansion.plot import save_figure
from mansion.scene.databases import asset_ids
from mansion.scene.house import AgentPose, House
from mansion.scene.manifest import BuildingManifest

__all__ = ["render_folder", "render_house"]

_CORE_COLOURS = {"stair": "#b8b8c8", "elevator": "#a8b8c8"}


def _colour(room_type: str) -> tuple[float, float, float]:
    # A pale colour per room type, stable across runs and floors.
    h = hashlib.blake2b(room_type.encode(), digest_size=3).digest()
    return tuple(0.72 + 0.25 * b / 255 for b in h)  # type: ignore[return-value]


def _segment(house: House) -> dict[str, tuple[tuple[float, float], tuple[float, float]]]:
    out = {}
    for w in house.walls:
        pts = sorted(w.polygon, key=lambda p: p.y)
        out[w.id] = ((pts[0].x, pts[0].z), (pts[1].x, pts[1].z))
    return out


def _arrow(ax: object, pose: AgentPose, colour: str, label: str, size: float) -> None:
    yaw = math.radians(pose.rotation.y)
    x, z = pose.position.x, pose.position.z
    ax.add_patch(  # type: ignore[attr-defined]
        __import__("matplotlib.patches", fromlist=["Circle"]).Circle(
            (x, z), 0.25, color=colour, zorder=6
        )
    )
    ax.annotate(  # type: ignore[attr-defined]
        "", xy=(x + math.sin(yaw) * 0.8, z + math.cos(yaw) * 0.8), xytext=(x, z),
        arrowprops={"arrowstyle": "-|>", "color": colour, "lw": 1.5}, zorder=7,
    )
    if label:
        ax.text(x, z - 0.45, label, fontsize=size, ha="center", va="top", color=colour, zorder=7)  # type: ignore[attr-defined]


def render_house(house: House, path: str | os.PathLike[str], *, title: str | None = None) -> Path:
    """Draw one house top-down to ``path`` (PNG or SVG)."""
    from matplotlib.figure import Figure
    from matplotlib.patches import Polygon as Patch
    from matplotlib.patches import Rectangle
    from matplotlib.transforms import Affine2D

    xs = [p.x for r in house.rooms for p in r.floor_polygon] or [0.0, 1.0]
    zs = [p.z for r in house.rooms for p in r.floor_polygon] or [0.0, 1.0]
    width, depth = max(xs) - min(xs), max(zs) - min(zs)
    scale = 9.0 / max(width, depth, 1.0)
    fig = Figure(figsize=(max(3.0, width * scale) + 0.4, max(3.0, depth * scale) + 0.8))
    ax = fig.add_subplot(1, 1, 1)
    ax.set_aspect("equal")
    ax.set_axis_off()
    font = max(4.0, min(8.0, 60.0 / max(width, depth, 1.0)))

    for room in house.rooms:
        pts = [(p.x, p.z) for p in room.floor_polygon]
        core = room.metadata.core if room.metadata else None
        face = _CORE_COLOURS[core.kind] if core else _colour(room.room_type)
        ax.add_patch(Patch(pts, closed=True, facecolor=face, edgecolor="none", zorder=1,
                           hatch="//" if core else None))
        if not (room.metadata and room.metadata.part_of and not room.id.endswith("|1")):
            from shapely.geometry import Polygon

            c = Polygon(pts).representative_point()
            label = room.metadata.part_of if room.metadata and room.metadata.part_of else room.id
            ax.text(c.x, c.y, label, fontsize=font, ha="center", va="center", zorder=5)

    segs = _segment(house)
    for wall in house.walls:
        (x0, z0), (x1, z1) = segs[wall.id]
        if wall.empty:
            ax.plot([x0, x1], [z0, z1], color="#999999", lw=0.6, ls=(0, (2, 2)), zorder=2)
        else:
            ax.plot([x0, x1], [z0, z1], color="#222222", lw=2.0, solid_capstyle="butt", zorder=3)

    for items, colour, lw in ((house.doors, "#e08020", 3.5), (house.windows, "#3090e0", 3.0)):
        for hole in items:
            if hole.wall0 not in segs:
                continue
            (x0, z0), (x1, z1) = segs[hole.wall0]
            n = math.hypot(x1 - x0, z1 - z0) or 1.0
            dx, dz = (x1 - x0) / n, (z1 - z0) / n
            lo, hi = hole.hole_polygon[0].x, hole.hole_polygon[1].x
            a, b = (x0 + dx * lo, z0 + dz * lo), (x0 + dx * hi, z0 + dz * hi)
            ax.plot([a[0], b[0]], [a[1], b[1]], color="white", lw=lw + 1.0, solid_capstyle="butt", zorder=4)
            ax.plot([a[0], b[0]], [a[1], b[1]], color=colour, lw=lw * 0.6, solid_capstyle="butt", zorder=4)

    db = asset_ids()

    def objects(items: list) -> None:  # type: ignore[type-arg]
        for obj in items:
            bb = db.get(obj.asset_id, {}).get("boundingBox", {"x": 0.3, "z": 0.3})
            w, d = bb["x"], bb["z"]
            rect = Rectangle((obj.position.x - w / 2, obj.position.z - d / 2), w, d,
                             facecolor="#806040", edgecolor="black", lw=0.4, alpha=0.8, zorder=5)
            # Yaw turns +z toward +x: clockwise when drawn with z up.
            rect.set_transform(Affine2D().rotate_deg_around(obj.position.x, obj.position.z, -obj.rotation.y) + ax.transData)
            ax.add_patch(rect)
            objects(obj.children)

    objects(house.objects)

    for room in house.rooms:
        core = room.metadata.core if room.metadata else None
        if core is not None and core.landing is not None:
            _arrow(ax, core.landing, "#208040", "", font)
    spawn = house.metadata.agent_poses.get("default")
    if spawn is not None:
        _arrow(ax, spawn, "#d02020", "spawn", font)

    ax.set_xlim(min(xs) - 0.5, max(xs) + 0.5)
    ax.set_ylim(min(zs) - 0.5, max(zs) + 0.5)
    ax.set_title(title or house.id or "", fontsize=10)
    fig.tight_layout()
    return save_figure(fig, path)


def render_folder(folder: str | os.PathLike[str]) -> list[Path]:
    """Draw every floor of a building folder (its ``manifest.json``, or ``scenes/manifest.json``
    below it) to ``floor_<k>.png`` beside the floor's JSON; without a manifest, every house JSON
    in the folder."""
    root = Path(folder)
    for manifest_path in (root / "manifest.json", root / "scenes" / "manifest.json"):
        if manifest_path.is_file():
            manifest = BuildingManifest.load(manifest_path)
            out = []
            for floor in manifest.floors:
                file = manifest_path.parent / floor.house
                house = House.load(file)
                title = f"{manifest.building_type.replace('_', ' ')}: floor {floor.index} ({house.id})"
                out.append(render_house(house, file.with_suffix(".png"), title=title))
            return out
    files = sorted(p for p in root.glob("*.json") if p.name != "building.json")
    houses = []
    for file in files:
        try:
            houses.append((file, House.load(file)))
        except InvalidInputError:
            continue
    if not houses:
        raise InvalidInputError(f"{str(root)!r} holds no manifest.json and no house JSON")
    return [render_house(h, f.with_suffix(".png")) for f, h in houses]
