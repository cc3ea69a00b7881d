"""The exported building as a tree of named nodes holding meshes, shared by every writer.

One node per floor (translated to its elevation), per room and per element (wall, door, window,
object, stair flight, elevator car), so a user can hide a floor or a room in Blender or Isaac Sim.
Coordinates are metres, y up, in the frame of the parent node (a floor's children are in its
house JSON's frame, which starts at the floor's slab).
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import Literal

import numpy as np

from mansion.export.meshes import Mesh

__all__ = ["BuildingModel", "Look", "Node", "Physics"]

#: How a simulator should treat a node's mesh: a static collider (walls, slabs, stairs, fixed
#: furniture), a rigid body (objects the agent can move), or nothing (glass, door leaves).
Physics = Literal["collider", "rigid", "none"]


@dataclass(frozen=True)
class Look:
    """A flat material: a name (from the material database when the house names one) and an RGBA
    colour in 0-1."""

    name: str
    rgba: tuple[float, float, float, float]


@dataclass
class Node:
    name: str
    kind: str
    #: Translation of this node in its parent's frame.
    offset: tuple[float, float, float] = (0.0, 0.0, 0.0)
    mesh: Mesh | None = None
    look: Look | None = None
    physics: Physics = "none"
    #: The ids this node stands for (house JSON id, asset id, ...), written as glTF extras and
    #: USD custom data.
    info: dict[str, str | float | int] = field(default_factory=dict)
    children: list[Node] = field(default_factory=list)

    def add(self, child: Node) -> Node:
        self.children.append(child)
        return child

    def walk(self, origin: np.ndarray | None = None) -> Iterator[tuple[Node, np.ndarray]]:
        """Every node below and including this one, with its world translation."""
        here = (np.zeros(3) if origin is None else origin) + np.asarray(self.offset)
        yield self, here
        for child in self.children:
            yield from child.walk(here)


@dataclass
class BuildingModel:
    """The root node (the building) and what the writers and tests want to know about it."""

    root: Node
    #: (x0, z0, x1, z1) of the footprint: every floor's rooms.
    footprint: tuple[float, float, float, float]
    #: The top of the roof above the ground floor's slab.
    height: float
    #: The ground floor slab's thickness (the model reaches this far below y = 0).
    base: float
