"""Agent poses: the spawn on a free cell of the hub, and each core's landing facing outward.

AI2-THOR puts an agent on the floor when its position has y = 0.95 (ProcTHOR's convention);
yaw is ``rotation.y`` in degrees, 0 facing +z, 90 facing +x.
"""

from __future__ import annotations

import math

import numpy as np
from shapely.geometry import Point, Polygon

from mansion.models.layout import FloorLayout
from mansion.scene.house import AgentPose, Vec3

__all__ = ["AGENT_Y", "AGENT_MODES", "hub_spawn", "landing_pose", "pose", "yaw_of"]

AGENT_Y = 0.95
#: The agent modes a house's ``metadata.agentPoses`` has a pose for; ``reset`` picks by mode.
AGENT_MODES = ("default", "arm", "locobot", "stretch")
#: Clearance an agent needs around its centre (m): AI2-THOR agents are about 0.25 m in radius.
CLEARANCE = 0.3


def yaw_of(dx: float, dz: float) -> float:
    """Yaw in degrees (0 faces +z, 90 faces +x) of the direction (dx, dz), in [0, 360)."""
    return round(math.degrees(math.atan2(dx, dz)) % 360.0, 6) % 360.0


def pose(x: float, z: float, yaw: float) -> AgentPose:
    return AgentPose(
        position=Vec3(x=x, y=AGENT_Y, z=z), rotation=Vec3(x=0.0, y=yaw, z=0.0), horizon=30.0,
        standing=True,
    )


def _within(xs: np.ndarray, ys: np.ndarray, d: tuple[float, float], r: float) -> np.ndarray:
    """Which points lie nearer than ``r`` to ``d``, exactly as ``math.dist(p, d) < r`` says:
    numpy decides the points clearly either side, math.dist the few within rounding of ``r``."""
    d2 = (xs - d[0]) ** 2 + (ys - d[1]) ** 2
    near = d2 < (r - 1e-9) ** 2
    for i in np.flatnonzero(~near & (d2 <= (r + 1e-9) ** 2)):
        near[i] = math.dist((xs[i], ys[i]), d) < r
    return near


def hub_spawn(layout: FloorLayout, hub: str, avoid: list[tuple[float, float]]) -> AgentPose:
    """The hub cell farthest from the hub's walls (ties: nearest the hub's centroid), away from
    door swings (``avoid``: door centres), facing the longest free run along an axis."""
    grid = layout.grid
    k = grid.ids.index(hub)
    mask = grid.array() == k
    # Chebyshev depth of each hub cell inside the hub: repeated 8-neighbour erosion.
    depth = np.zeros(mask.shape, dtype=np.int32)
    cur = mask.copy()
    level = 0
    while cur.any():
        level += 1
        depth[cur] = level
        padded = np.pad(cur, 1, constant_values=False)
        nxt = cur.copy()
        for dr in (-1, 0, 1):
            for dc in (-1, 0, 1):
                nxt &= padded[1 + dr : 1 + dr + cur.shape[0], 1 + dc : 1 + dc + cur.shape[1]]
        cur = nxt
    s, (ox, oy) = grid.cell_size, grid.origin
    cx, cy = layout.room(hub).centroid
    rows, cols = np.nonzero(mask)
    xs, ys = ox + (cols + 0.5) * s, oy + (rows + 0.5) * s
    free = np.ones(len(rows), dtype=bool)
    for d in avoid:
        free &= ~_within(xs, ys, d, 1.2)
    best: tuple[float, float, int, int] | None = None
    if free.any():
        # the deepest free cells, then math.dist's own distances break the tie
        deep = depth[rows, cols]
        top = deep[free].max()
        best = max(
            (float(top), -math.dist((xs[i], ys[i]), (cx, cy)), int(rows[i]), int(cols[i]))
            for i in np.flatnonzero(free & (deep == top))
        )
    if best is None:  # a hub that is all door swing: take its deepest cell anyway
        r, c = np.unravel_index(int(np.argmax(depth)), depth.shape)
    else:
        r, c = best[2], best[3]
    runs = []
    for dr, dc, yaw in ((1, 0, 0.0), (0, 1, 90.0), (-1, 0, 180.0), (0, -1, 270.0)):
        n, rr, cc = 0, r + dr, c + dc
        while 0 <= rr < mask.shape[0] and 0 <= cc < mask.shape[1] and mask[rr, cc]:
            n, rr, cc = n + 1, rr + dr, cc + dc
        runs.append((n, -yaw))
    yaw = -max(runs)[1]
    return pose(ox + (c + 0.5) * s, oy + (r + 0.5) * s, yaw)


def landing_pose(
    room: Polygon, door_centre: tuple[float, float], outward: tuple[float, float],
    steps: tuple[float, ...] = (0.75, 1.0, 0.6, 1.25, 0.5),
) -> AgentPose:
    """Where an agent coming through a door stands: in ``room``, a step beyond the door (the
    first of ``steps`` that has room), facing away from it (``outward``: into the room)."""
    inner = room.buffer(-CLEARANCE)
    for step in steps:
        x, y = door_centre[0] + outward[0] * step, door_centre[1] + outward[1] * step
        if inner.contains(Point(x, y)):
            break
    else:
        # No room for a full step straight out (a narrow strip beyond the door): the nearest
        # point of the room with clearance, or of the room itself.
        from shapely.ops import nearest_points

        target = inner if not inner.is_empty else room.buffer(-0.05)
        q = nearest_points(target, Point(door_centre))[0]
        x, y = q.x, q.y
    return pose(x, y, yaw_of(outward[0], outward[1]))
