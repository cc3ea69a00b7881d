"""The building being edited: its static house JSONs (the source of truth, as in the paper) read
into the simulator's floor states, and how the tools name things in it.

Objects are found by id or by keyword (fuzzy over object types, with rapidfuzz), rooms by id or
room type. Object ids repeat across copied floors, so an id found on several floors needs the
floor. Nothing here writes files: :mod:`mansion.edit.variants` saves what the tools changed.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import numpy as np
from rapidfuzz import fuzz, process

from mansion.exceptions import UnknownObjectError
from mansion.scene.house import house_text
from mansion.sim.grid import CELL
from mansion.sim.planner import BuildingMap
from mansion.sim.world import Building, FloorState, ObjectInfo, building_root, find_manifest

__all__ = ["Workspace", "norm"]

#: A keyword matches an object type at this rapidfuzz partial-ratio score (0-100) or above.
KEYWORD_SCORE = 90.0


def norm(text: str) -> str:
    """Lower case, letters and digits only: "dining table", "DiningTable" and "dining_table" meet."""
    return re.sub(r"[^a-z0-9]", "", text.lower())


class Workspace:
    """A building whose floors the edit tools read and change in memory."""

    def __init__(self, building_dir: str | Path, cell: float = CELL):
        self.manifest_path = find_manifest(building_dir)
        self.root = building_root(self.manifest_path)
        self.building = Building(self.manifest_path)
        self.cell = cell
        self.states: dict[int, FloorState] = {}
        #: floors whose house the tools changed
        self.edited: set[int] = set()
        self._reach: dict[int, tuple[int, np.ndarray]] = {}

    # -- floors ---------------------------------------------------------------------------------
    @property
    def floors(self) -> list[int]:
        return self.building.floors

    def check_floor(self, floor: int) -> int:
        if floor not in self.building.floor_files:
            raise UnknownObjectError(f"the building has no floor {floor} (floors {self.floors[0]}–{self.floors[-1]})")
        return floor

    def floor(self, k: int) -> FloorState:
        self.check_floor(k)
        if k not in self.states:
            self.states[k] = self.building.floor_state(k, self.cell)
        return self.states[k]

    def base_bytes(self, k: int) -> bytes:
        """Floor k's house file as read (the base the variant is a patch of)."""
        self.building.house(k)
        return self.building.raw[k]

    def house_bytes(self, k: int) -> bytes:
        """Floor k's house as it is now, in the bytes ``House.to_json`` writes."""
        if k not in self.edited:
            return self.base_bytes(k)
        return house_text(self.building.house(k).to_dict()).encode("utf-8")

    def touch(self, k: int) -> None:
        self.edited.add(k)
        self._reach.pop(k, None)

    def bmap(self) -> BuildingMap:
        return BuildingMap(self.building, self.cell, {k: self.floor(k) for k in self.states})

    # -- rooms ----------------------------------------------------------------------------------
    def room(self, floor: int, name: str) -> str:
        """A room of the floor by id, else by room type ("lobby", "Lobby", "staff kitchen")."""
        st = self.floor(floor)
        if name in st.rooms:
            return name
        key = norm(name)
        for pick in (lambda r: norm(r.room_type) == key, lambda r: norm(r.id) == key,
                     lambda r: key in norm(r.room_type) or key in norm(r.id)):
            found = sorted(r.id for r in st.rooms.values() if r.id not in st.core_ids and pick(r))
            if found:
                return found[0]
        rooms = ", ".join(sorted(f"{r.id} ({r.room_type})" for r in st.rooms.values()))
        raise UnknownObjectError(f"no room {name!r} on floor {floor}; its rooms: {rooms}")

    # -- objects --------------------------------------------------------------------------------
    def find(self, object_id: str, floor: int | None = None) -> tuple[int, ObjectInfo]:
        """The object of that id (on ``floor``, else on the one floor that has it)."""
        floors = [self.check_floor(floor)] if floor is not None else self.floors
        hits = [(k, self.floor(k).objects[object_id]) for k in floors if object_id in self.floor(k).objects]
        if len(hits) == 1:
            return hits[0]
        if hits:
            raise UnknownObjectError(f"{object_id!r} is on floors {', '.join(str(k) for k, _ in hits)}: give the floor")
        where = f"floor {floor}" if floor is not None else "any floor"
        ids = [i for k in floors for i in self.floor(k).objects]
        near = [m[0] for m in process.extract(object_id, ids, scorer=fuzz.ratio, limit=3)]
        hint = f"; did you mean {', '.join(near)}?" if near else ""
        raise UnknownObjectError(f"no object {object_id!r} on {where}{hint}")

    def match(self, keyword: str | None, floor: int | None = None, room: str | None = None) -> list[tuple[int, ObjectInfo]]:
        """Objects whose id is ``keyword``, else whose type matches it (exact type first, then
        fuzzy), on ``floor`` (else every floor) and in ``room``; sorted by floor and id."""
        floors = [self.check_floor(floor)] if floor is not None else self.floors
        out: list[tuple[int, ObjectInfo]] = []
        rooms = {k: self.room(k, room) for k in floors} if room is not None else {}
        for k in floors:
            st = self.floor(k)
            items = [i for i in st.objects.values() if room is None or i.room == rooms[k]]
            if keyword:
                if keyword in st.objects:
                    items = [st.objects[keyword]] if room is None or st.objects[keyword].room == rooms[k] else []
                else:
                    key = norm(keyword)
                    exact = [i for i in items if norm(i.props.object_type) == key]
                    items = exact or [i for i in items if fuzz.partial_ratio(key, norm(i.props.object_type)) >= KEYWORD_SCORE
                                      or key in norm(i.id)]
            out += [(k, i) for i in items]
        return sorted(out, key=lambda p: (p[0], p[1].id))

    def of_type(self, floor: int, object_type: str) -> list[ObjectInfo]:
        """Objects of exactly this AI2-THOR type on the floor (case and spacing ignored)."""
        key = norm(object_type)
        return sorted((i for i in self.floor(floor).objects.values() if norm(i.props.object_type) == key),
                      key=lambda i: i.id)

    def new_id(self, receptacle_id: str, object_type: str) -> str:
        """``<receptacle>|<Type>|<k>``, the furnishing's naming, with the first k free on every
        floor (the tasks want ids unique in the building)."""
        taken = {i for k in self.floors for i in self.floor(k).objects}
        k = 0
        while f"{receptacle_id}|{object_type}|{k}" in taken:
            k += 1
        return f"{receptacle_id}|{object_type}|{k}"

    # -- reachability ---------------------------------------------------------------------------
    def reachable(self, floor: int, object_id: str) -> bool:
        """Whether an agent coming from the floor's spawn can get within interaction distance of
        the object (the simulator's grid and its GoToObject goal)."""
        st = self.floor(floor)
        cached = self._reach.get(floor)
        if cached is None or cached[0] != st.version:
            spawn = next(f.spawn for f in self.building.manifest.floors if f.index == floor)
            g = st.grid
            cell = g.snap(spawn.position.x, spawn.position.z, within=0.6)
            dist = g.distances(cell) if cell is not None else np.full(g.free.shape, -1)
            cached = (st.version, dist)
            self._reach[floor] = cached
        mask = BuildingMap.object_goal(object_id)(st)
        return bool((mask & (cached[1] >= 0)).any())

    def describe(self, floor: int, info: ObjectInfo) -> dict[str, Any]:
        """An object as the tools report it: where it is and what it affords."""
        p = info.props
        out: dict[str, Any] = {
            "id": info.id, "floor": floor, "room": info.room, "type": p.object_type,
            "asset_id": info.obj.asset_id, "receptacle": p.receptacle, "openable": p.openable,
            "pickupable": p.pickupable,
        }
        if p.openable:
            out["open"] = self.floor(floor).is_open(info.id)
        if info.parent is not None:
            out["parent"] = info.parent
        out["size"] = [round(p.width, 3), round(p.height, 3), round(p.depth, 3)]
        return out
