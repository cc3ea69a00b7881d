"""The paper's eight scene-editing tools, on the static house JSONs and AI2-THOR's asset database.

``CheckPath``, ``SearchAssets``, ``ListObjects``, ``CheckSurface``, ``SearchContents``,
``PlaceInContainer``, ``RemoveObject``, ``PlaceOnSurface``: methods of :class:`SceneTools` (the
offline controller calls them) and, through :data:`TOOL_SPECS` and :meth:`SceneTools.run`, tools
Claude calls by name with JSON arguments. Every answer is a JSON-able dict; a call that cannot be
done raises a typed error of :mod:`mansion.exceptions` naming the object, receptacle or floor (an
unknown id: :class:`UnknownObjectError`; a full top or inside: :class:`SurfaceFullError`; a
closed container: :class:`ContainerClosedError`; a receptacle that cannot take the object:
:class:`IncompatibleReceptacleError`), and changes nothing.

Placement is geometric (:mod:`mansion.edit.surfaces`): a free spot on the receptacle's top or on
the floor of its inside box, clear of what lies there, ``y`` from the surface. What a receptacle
may take follows AI2-THOR's receptacle database (``receptacles.json``: the small object types
its scenes put on each receptacle type) where it lists the type; a surface is used with
``PlaceOnSurface`` and a container (an openable receptacle) with ``PlaceInContainer``, as the
simulator's ``Put`` does. A receptacle the agent cannot reach from the floor's spawn is refused:
provisioning it would not make any task executable.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass
from typing import Any, Literal

import numpy as np

from mansion.edit.asset_search import Embedder, search_assets
from mansion.edit.surfaces import area_free, contents, fit, on_top
from mansion.edit.workspace import Workspace
from mansion.exceptions import (
    ContainerClosedError,
    EditError,
    IncompatibleReceptacleError,
    InvalidInputError,
    MansionError,
    SurfaceFullError,
    UnknownObjectError,
)
from mansion.placement.assets import database
from mansion.scene.databases import asset_ids
from mansion.scene.house import HouseObject
from mansion.sim.planner import BuildingMap
from mansion.sim.world import ObjectInfo, props

__all__ = ["TOOL_NAMES", "TOOL_SPECS", "Edit", "SceneTools"]

#: Most objects one answer lists (the rest are counted), to keep a model's context small.
LIST_LIMIT = 60


@dataclass(frozen=True)
class Edit:
    """One change to a floor's house JSON."""

    op: Literal["add", "move", "remove", "open"]
    floor: int
    object_id: str
    asset_id: str
    receptacle: str | None
    text: str

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)


def _xyz(obj: HouseObject) -> list[float]:
    return [round(obj.position.x, 3), round(obj.position.y, 3), round(obj.position.z, 3)]


class SceneTools:
    """The eight tools over one :class:`Workspace`; ``edits`` lists what they changed, in order."""

    def __init__(self, workspace: Workspace, embedder: Embedder | None = None):
        self.ws = workspace
        #: SearchAssets ranks by meaning with this embedding model when given (off by default)
        self.embedder = embedder
        self.edits: list[Edit] = []

    # -- CheckPath ------------------------------------------------------------------------------
    def check_path(self, start_floor: int, start_room: str, end_floor: int, end_room: str) -> dict[str, Any]:
        """Whether an agent can walk from the start room to the end room, across floors through
        the cores (the simulator's grids and planner)."""
        ws = self.ws
        a, b = ws.room(start_floor, start_room), ws.room(end_floor, end_room)
        st = ws.floor(start_floor)
        g = st.grid
        k = g.room_ids.index(a)
        free = g.free & (g.label == k)
        out: dict[str, Any] = {"start": {"floor": start_floor, "room": a}, "end": {"floor": end_floor, "room": b}}
        if not free.any():
            return {**out, "ok": False, "reason": f"room {a} on floor {start_floor} has no cell an agent fits in"}
        px, pz = g.centres()
        lx, lz = st.landmarks[a]
        d = (px - lx) ** 2 + (pz - lz) ** 2
        r, c = np.unravel_index(int(np.argmin(np.where(free, d, np.inf))), d.shape)
        cell = (int(r), int(c))
        route = ws.bmap().route(start_floor, cell, end_floor, BuildingMap.room_goal(b))
        if route is None:
            where = "on the floor" if start_floor == end_floor else "through any core"
            return {**out, "ok": False, "reason": f"no walkable way from {a} (floor {start_floor}) to {b} (floor {end_floor}) {where}"}
        cores = [act[1] for act in route.actions if act[0] == "GoToRoom"]
        rides = [" ".join(str(x) for x in act) for act in route.actions if act[0] != "GoToRoom"]
        return {**out, "ok": True, "metres": round(route.metres, 1), "cores": cores, "rides": rides}

    # -- SearchAssets ---------------------------------------------------------------------------
    def search_assets(self, query: str, top_k: int = 5, properties: list[str] | None = None) -> dict[str, Any]:
        return {"assets": search_assets(query, top_k, properties, embedder=self.embedder)}

    # -- ListObjects ----------------------------------------------------------------------------
    def list_objects(self, room: str | None = None, keyword_or_id: str | None = None,
                     floor: int | None = None) -> dict[str, Any]:
        """Objects (of ``room``, matching ``keyword_or_id``) with what they afford."""
        if room is not None and floor is None:
            floors = [k for k in self.ws.floors if _has_room(self.ws, k, room)]
            if not floors:
                raise UnknownObjectError(f"no room {room!r} on any floor")
            found = [p for k in floors for p in self.ws.match(keyword_or_id, k, room)]
        else:
            found = self.ws.match(keyword_or_id, floor, room)
        items = [self.ws.describe(k, i) for k, i in found]
        out: dict[str, Any] = {"count": len(items), "objects": items[:LIST_LIMIT]}
        if len(items) > LIST_LIMIT:
            out["more"] = f"{len(items) - LIST_LIMIT} more: narrow by room or keyword"
        return out

    # -- CheckSurface / SearchContents ----------------------------------------------------------
    def _receptacles(self, keyword_or_id: str, floor: int | None) -> list[tuple[int, ObjectInfo]]:
        found = [(k, i) for k, i in self.ws.match(keyword_or_id, floor) if i.props.receptacle]
        if not found:
            if self.ws.match(keyword_or_id, floor):
                raise IncompatibleReceptacleError(f"{keyword_or_id!r} matches no receptacle (nothing can be put on or in it)")
            where = f" on floor {floor}" if floor is not None else ""
            raise UnknownObjectError(f"no receptacle {keyword_or_id!r}{where}")
        return found[:LIST_LIMIT]

    def check_surface(self, keyword_or_id: str, floor: int | None = None) -> dict[str, Any]:
        """What lies on top of each matching receptacle (by the boxes' heights)."""
        out = []
        for k, rec in self._receptacles(keyword_or_id, floor):
            items = on_top(rec, list(self.ws.floor(k).objects.values()))
            out.append({**self.ws.describe(k, rec),
                        "top_y": round(rec.obj.position.y + rec.props.height / 2, 3),
                        "free_area_m2": round(area_free(rec, items), 3),
                        "on_top": [self.ws.describe(k, i) for i in items]})
        return {"receptacles": out}

    def search_contents(self, keyword_or_id: str, floor: int | None = None) -> dict[str, Any]:
        """What lies inside each matching receptacle (below its top), and whether it is open."""
        out = []
        for k, rec in self._receptacles(keyword_or_id, floor):
            items = contents(rec, list(self.ws.floor(k).objects.values()))
            out.append({**self.ws.describe(k, rec), "inside": [self.ws.describe(k, i) for i in items]})
        return {"receptacles": out}

    # -- RemoveObject ---------------------------------------------------------------------------
    def remove_object(self, object_id: str | None = None, receptacle_id: str | None = None,
                      floor: int | None = None) -> dict[str, Any]:
        """Remove one object (with what lies on or in it), or everything on and in a receptacle."""
        if (object_id is None) == (receptacle_id is None):
            raise InvalidInputError("RemoveObject takes object_id or receptacle_id, one of the two")
        if object_id is not None:
            k, info = self.ws.find(object_id, floor)
            victims = [info]
        else:
            k, rec = self.ws.find(receptacle_id or "", floor)
            if not rec.props.receptacle:
                raise IncompatibleReceptacleError(f"{rec.id} ({rec.props.object_type}) is not a receptacle")
            victims = [self.ws.floor(k).objects[c.id] for c in rec.obj.children]
            if not victims:
                return {"removed": [], "floor": k, "note": f"nothing lies on or in {rec.id}"}
        st = self.ws.floor(k)
        removed = []
        for v in victims:
            st.detach(v.id)
            removed.append(v.id)
            self._record("remove", k, v.obj, v.parent, f"removed {v.id} ({v.props.object_type}) from {v.parent or v.room}")
        self.ws.touch(k)
        return {"removed": removed, "floor": k}

    # -- PlaceOnSurface / PlaceInContainer ------------------------------------------------------
    def place_on_surface(self, asset_id: str, receptacle_id: str, floor: int | None = None) -> dict[str, Any]:
        """Put a new object of ``asset_id`` (or move the object of that id) on the receptacle."""
        return self._place(asset_id, receptacle_id, floor, inside=False, open_it=False)

    def place_in_container(self, asset_id: str, container_id: str, floor: int | None = None,
                           open: bool = False) -> dict[str, Any]:  # noqa: A002 - the tool's argument name
        """Put a new object of ``asset_id`` (or move the object of that id) into the container;
        a closed one is refused unless ``open`` (then its door is opened in the scene)."""
        return self._place(asset_id, container_id, floor, inside=True, open_it=open)

    def _item(self, asset_or_object: str) -> tuple[str, Any, tuple[int, ObjectInfo] | None]:
        if asset_or_object in asset_ids():
            return asset_or_object, props(asset_or_object), None
        try:
            k, info = self.ws.find(asset_or_object)
        except UnknownObjectError:
            raise UnknownObjectError(f"{asset_or_object!r} is neither an AI2-THOR asset id nor an object of the "
                                     "building (SearchAssets finds asset ids)") from None
        if info.obj.children:
            raise IncompatibleReceptacleError(f"{info.id} holds other objects; it cannot be moved onto another")
        return info.obj.asset_id, info.props, (k, info)

    def _place(self, asset_or_object: str, receptacle_id: str, floor: int | None, *, inside: bool,
               open_it: bool) -> dict[str, Any]:
        ws = self.ws
        k, rec = ws.find(receptacle_id, floor)
        st = ws.floor(k)
        rp = rec.props
        asset_id, item, moving = self._item(asset_or_object)
        what = f"{asset_or_object} ({item.object_type})"
        if not rp.receptacle:
            raise IncompatibleReceptacleError(f"{rec.id} ({rp.object_type}) is not a receptacle")
        if inside and not rp.openable:
            raise IncompatibleReceptacleError(f"{rec.id} ({rp.object_type}) is a surface, not a container: use PlaceOnSurface")
        if not inside and rp.openable:
            raise IncompatibleReceptacleError(f"{rec.id} ({rp.object_type}) is a container: use PlaceInContainer")
        if not item.pickupable:
            raise IncompatibleReceptacleError(f"{what} cannot be picked up: only small objects go on or in receptacles")
        allowed = database().receptacles.get(rp.object_type)
        if allowed is not None and item.object_type not in allowed:
            raise IncompatibleReceptacleError(
                f"{rec.id} ({rp.object_type}) cannot take {what}: AI2-THOR's receptacle database puts only "
                f"{', '.join(sorted(allowed))} {'in' if inside else 'on'} a {rp.object_type}")
        if inside and not st.is_open(rec.id) and not open_it:
            raise ContainerClosedError(f"{rec.id} ({rp.object_type}) is closed: call PlaceInContainer with open=true "
                                       "to open it first")
        if not ws.reachable(k, rec.id):
            raise EditError(f"{rec.id} on floor {k} cannot be reached from the floor's spawn: "
                            "an object there would be of no use to the agent")
        others = [o for o in st.objects.values() if moving is None or o.id != moving[1].id]
        taken = contents(rec, others) if inside else on_top(rec, others)
        slot = fit(rec, item, taken, inside)
        if slot is None:
            size = f"{item.width:.2f} × {item.depth:.2f} m"
            holds = ", ".join(o.id for o in taken) or "nothing"
            raise SurfaceFullError(f"no free spot {'in' if inside else 'on'} {rec.id} ({rp.object_type}, "
                                   f"{rp.width:.2f} × {rp.depth:.2f} m) for {what}, {size}; it holds {holds}")
        record = st.house.metadata.mansion
        if record is not None and slot.y + item.height / 2 > record.ceiling_height:
            raise IncompatibleReceptacleError(f"{what} on {rec.id} would reach above the ceiling")
        opened = inside and not st.is_open(rec.id)
        if opened:
            self.open_container(rec.id, k)
        if moving is not None:
            src, info = moving
            obj = ws.floor(src).detach(info.id)
            ws.touch(src)
            op: Literal["add", "move"] = "move"
        else:
            obj = HouseObject.model_validate({
                "id": ws.new_id(rec.id, item.object_type), "assetId": asset_id,
                "position": {"x": 0.0, "y": 0.0, "z": 0.0}, "rotation": {"x": 0.0, "y": 0.0, "z": 0.0},
                "kinematic": False,
            })
            op = "add"
        obj.position.x, obj.position.y, obj.position.z = slot.x, slot.y, slot.z
        obj.rotation.x, obj.rotation.y, obj.rotation.z = 0.0, slot.yaw + 0.0, 0.0  # + 0.0: no "-0.0" in the JSON
        obj.room = rec.room
        obj.layer = rec.obj.layer
        st.attach(obj, rec.id)
        ws.touch(k)
        word = "in" if inside else "on"
        verb = "moved" if op == "move" else "added"
        self._record(op, k, obj, rec.id, f"{verb} {obj.id} ({asset_id}) {word} {rec.id} on floor {k} at "
                     f"({slot.x:.2f}, {slot.y:.2f}, {slot.z:.2f})")
        return {"placed": obj.id, "asset_id": asset_id, "type": item.object_type, "floor": k, "receptacle": rec.id,
                "room": rec.room, "position": _xyz(obj), "opened": opened}

    def open_container(self, container_id: str, floor: int | None = None) -> dict[str, Any]:
        """Open a closed container in the scene (an object the task needs lies shut in it)."""
        k, rec = self.ws.find(container_id, floor)
        if not rec.props.openable:
            raise IncompatibleReceptacleError(f"{rec.id} ({rec.props.object_type}) does not open")
        if not self.ws.floor(k).is_open(rec.id):
            rec.obj.openness = 1.0
            self.ws.touch(k)
            self._record("open", k, rec.obj, rec.parent, f"opened {rec.id} ({rec.props.object_type})")
        return {"open": rec.id, "floor": k}

    def _record(self, op: Any, floor: int, obj: HouseObject, receptacle: str | None, text: str) -> None:
        self.edits.append(Edit(op, floor, obj.id, obj.asset_id, receptacle, text))

    # -- dispatch for the model -----------------------------------------------------------------
    def run(self, name: str, args: dict[str, Any]) -> tuple[bool, dict[str, Any]]:
        """Call tool ``name`` with JSON ``args``: (True, answer), or (False, {"error": why})."""
        method = _METHODS.get(name)
        if method is None:
            return False, {"error": f"no tool {name!r}; tools: {', '.join(TOOL_NAMES)}"}
        try:
            return True, getattr(self, method)(**args)
        except TypeError as exc:
            return False, {"error": f"{name}: bad arguments {sorted(args)} ({exc})"}
        except MansionError as exc:
            return False, {"error": f"{type(exc).__name__}: {exc}"}


def _has_room(ws: Workspace, floor: int, room: str) -> bool:
    try:
        ws.room(floor, room)
    except UnknownObjectError:
        return False
    return True


_METHODS = {
    "CheckPath": "check_path", "SearchAssets": "search_assets", "ListObjects": "list_objects",
    "CheckSurface": "check_surface", "SearchContents": "search_contents",
    "PlaceInContainer": "place_in_container", "RemoveObject": "remove_object",
    "PlaceOnSurface": "place_on_surface",
}
TOOL_NAMES = tuple(_METHODS)

_FLOOR = {"type": "integer", "description": "Floor index (0 = ground floor). Needed when an id is on several floors."}
_ID = {"type": "string", "description": "An object id, or a keyword matched against object types (e.g. 'Fridge', 'table')."}

#: The tools as the Messages API's ``tools`` parameter (name, description, JSON Schema input).
TOOL_SPECS: list[dict[str, Any]] = [
    {"name": "CheckPath", "description": "Whether an agent can walk from a room to another, across floors through the stair and elevator cores. Returns the walking length and the cores taken.",
     "input_schema": {"type": "object", "properties": {
         "start_floor": {"type": "integer"}, "start_room": {"type": "string", "description": "Room id or room type."},
         "end_floor": {"type": "integer"}, "end_room": {"type": "string"}},
         "required": ["start_floor", "start_room", "end_floor", "end_room"]}},
    {"name": "SearchAssets", "description": "Fuzzy search of AI2-THOR's asset database by words; filter by properties such as Pickupable, Receptacle, Openable.",
     "input_schema": {"type": "object", "properties": {
         "query": {"type": "string"}, "top_k": {"type": "integer", "default": 5},
         "properties": {"type": "array", "items": {"type": "string"}}}, "required": ["query"]}},
    {"name": "ListObjects", "description": "Objects of the building (optionally of one room, matching a keyword or id) with their floor, room, type and whether they are a Receptacle, Openable, Pickupable.",
     "input_schema": {"type": "object", "properties": {
         "room": {"type": "string"}, "keyword_or_id": {"type": "string"}, "floor": _FLOOR}}},
    {"name": "CheckSurface", "description": "What lies on top of a receptacle (by bounding-box heights) and its free area.",
     "input_schema": {"type": "object", "properties": {"keyword_or_id": _ID, "floor": _FLOOR}, "required": ["keyword_or_id"]}},
    {"name": "SearchContents", "description": "What lies inside a receptacle (a fridge, a shelf) and whether it is open.",
     "input_schema": {"type": "object", "properties": {"keyword_or_id": _ID, "floor": _FLOOR}, "required": ["keyword_or_id"]}},
    {"name": "PlaceInContainer", "description": "Put a new object of an asset id (or move an existing object by its id) inside a container such as a Fridge. A closed container is refused unless open is true.",
     "input_schema": {"type": "object", "properties": {
         "asset_id": {"type": "string"}, "container_id": {"type": "string"}, "floor": _FLOOR,
         "open": {"type": "boolean", "default": False, "description": "Open a closed container first."}},
         "required": ["asset_id", "container_id"]}},
    {"name": "RemoveObject", "description": "Remove an object (object_id), or everything on and in a receptacle (receptacle_id).",
     "input_schema": {"type": "object", "properties": {
         "object_id": {"type": "string"}, "receptacle_id": {"type": "string"}, "floor": _FLOOR}}},
    {"name": "PlaceOnSurface", "description": "Put a new object of an asset id (or move an existing object by its id) on top of a receptacle such as a DiningTable, clear of what lies there.",
     "input_schema": {"type": "object", "properties": {
         "asset_id": {"type": "string"}, "receptacle_id": {"type": "string"}, "floor": _FLOOR},
         "required": ["asset_id", "receptacle_id"]}},
]
