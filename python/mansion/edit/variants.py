"""Task variants: a building edited for a task, kept beside the base building, which is never
changed by editing.

``BUILDING_DIR/variants/<name>/`` holds ``variant.json`` (the task text, the spec, the patch: per
floor the objects added, moved, removed and changed, against the base files' SHA-256; and the log
of checks and edits), ``task.json`` (the task for ``mansion eval tasks``) and ``scenes/`` (the
variant's house JSONs and manifest: ``BuildingEnv(BUILDING_DIR, variant=NAME)`` loads them).

``apply`` writes a variant's edited house JSONs over the building's own (atomically, after
checking they are the base the patch was made against, and keeping the base bytes in
``variants/.applied/``); ``revert`` writes those bytes back, byte for byte.
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
from pathlib import Path
from typing import Any

from pydantic import BaseModel, ConfigDict, Field

from mansion._io import atomic_write_bytes, atomic_write_text
from mansion.exceptions import EditError, InvalidInputError
from mansion.scene.house import House, house_text
from mansion.sim.tasks import TaskSet, TaskSpec
from mansion.sim.world import building_root, find_manifest

__all__ = [
    "FloorPatch",
    "Variant",
    "apply_variant",
    "diff_house",
    "list_variants",
    "load_variant",
    "patch_house",
    "revert_variant",
    "save_variant",
    "variants_dir",
]

VARIANTS = "variants"
APPLIED = ".applied"
_NAME_OK = frozenset("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_.")


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid")


class Added(_Model):
    parent: str | None
    object: dict[str, Any] = Field(description="The object as in the house JSON, without its children.")


class Moved(_Model):
    id: str
    parent: str | None
    position: dict[str, float]
    rotation: dict[str, float]
    room: str | None = None


class Removed(_Model):
    id: str
    parent: str | None


class Changed(_Model):
    id: str
    set: dict[str, Any]


class FloorPatch(_Model):
    floor: int
    house: str = Field(description="The floor's house file.")
    base_sha256: str
    added: list[Added] = Field(default_factory=list)
    moved: list[Moved] = Field(default_factory=list)
    removed: list[Removed] = Field(default_factory=list)
    changed: list[Changed] = Field(default_factory=list)


class Variant(_Model):
    """``variant.json``."""

    schema_version: str = "1.0"
    name: str
    building: str
    text: str
    planner: str
    spec: dict[str, Any]
    patch: list[FloorPatch]
    log: list[dict[str, Any]]
    task: TaskSpec

    def summary(self) -> str:
        n = {k: sum(len(getattr(p, k)) for p in self.patch) for k in ("added", "moved", "removed", "changed")}
        return ", ".join(f"{v} {k}" for k, v in n.items() if v) or "no edits"


def _sha(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def variants_dir(building_dir: str | Path) -> Path:
    return building_root(find_manifest(building_dir)) / VARIANTS


def check_name(name: str) -> str:
    if not name or name.startswith(".") or not set(name) <= _NAME_OK:
        raise InvalidInputError(f"variant name {name!r}: use letters, digits, '-', '_' and '.', not starting with '.'")
    return name


# -- patches ----------------------------------------------------------------------------------
def _flatten(objects: list[dict[str, Any]], parent: str | None, out: dict[str, tuple[str | None, dict[str, Any]]]) -> None:
    for o in objects:
        out[o["id"]] = (parent, o)
        _flatten(o.get("children", []), o["id"], out)


_PLACE_KEYS = ("position", "rotation", "room")


def diff_house(base: dict[str, Any], edited: dict[str, Any], floor: int, house: str, base_sha: str) -> FloorPatch:
    """What turned the base house into the edited one, object by object (ids are unique in a house)."""
    a: dict[str, tuple[str | None, dict[str, Any]]] = {}
    b: dict[str, tuple[str | None, dict[str, Any]]] = {}
    _flatten(base.get("objects", []), None, a)
    _flatten(edited.get("objects", []), None, b)
    patch = FloorPatch(floor=floor, house=house, base_sha256=base_sha)
    for oid, (parent, o) in a.items():
        if oid not in b:
            patch.removed.append(Removed(id=oid, parent=parent))
    for oid, (parent, o) in b.items():  # preorder: parents before their children
        if oid not in a:
            patch.added.append(Added(parent=parent, object={k: v for k, v in o.items() if k != "children"}))
            continue
        old_parent, old = a[oid]
        if old_parent != parent or any(old.get(k) != o.get(k) for k in _PLACE_KEYS):
            patch.moved.append(Moved(id=oid, parent=parent, position=o["position"], rotation=o["rotation"], room=o.get("room")))
        skip = {"children", *_PLACE_KEYS}
        changed = {k: o.get(k) for k in (set(o) | set(old)) - skip if o.get(k) != old.get(k)}
        if changed:
            patch.changed.append(Changed(id=oid, set=dict(sorted(changed.items()))))
    return patch


def patch_house(base: dict[str, Any], patch: FloorPatch) -> dict[str, Any]:
    """The base house with the patch applied (a new dict)."""
    house = json.loads(json.dumps(base))
    index: dict[str, tuple[str | None, dict[str, Any]]] = {}

    def reindex() -> None:
        index.clear()
        _flatten(house.get("objects", []), None, index)

    def siblings(parent: str | None) -> list[dict[str, Any]]:
        if parent is None:
            return house.setdefault("objects", [])  # type: ignore[no-any-return]
        if parent not in index:
            raise EditError(f"patch of floor {patch.floor}: no object {parent!r} to put things on")
        return index[parent][1].setdefault("children", [])  # type: ignore[no-any-return]

    def take(oid: str) -> dict[str, Any] | None:
        if oid not in index:
            return None
        parent, obj = index[oid]
        sib = siblings(parent)
        sib[:] = [o for o in sib if o["id"] != oid]
        reindex()
        return obj

    reindex()
    for r in patch.removed:
        take(r.id)
    for m in patch.moved:
        obj = take(m.id)
        if obj is None:
            raise EditError(f"patch of floor {patch.floor}: no object {m.id!r} to move")
        obj.update(position=m.position, rotation=m.rotation)
        if m.room is not None:
            obj["room"] = m.room
        siblings(m.parent).append(obj)
        reindex()
    for a in patch.added:
        siblings(a.parent).append({**a.object, "children": []})
        reindex()
    for c in patch.changed:
        if c.id not in index:
            raise EditError(f"patch of floor {patch.floor}: no object {c.id!r} to change")
        obj = index[c.id][1]
        for k, v in c.set.items():
            if v is None:
                obj.pop(k, None)
            else:
                obj[k] = v
    return House.model_validate(house).to_dict()


def _house_bytes(house: dict[str, Any]) -> bytes:
    return house_text(house).encode("utf-8")


# -- saving and loading -----------------------------------------------------------------------
def save_variant(workspace: Any, name: str, *, text: str, planner: str, spec: dict[str, Any],
                 log: list[dict[str, Any]], task: TaskSpec, root: Path | None = None) -> Path:
    """Write the variant of the workspace's edits into ``root`` (the building's ``variants/``);
    returns its folder. The folder is written beside and then moved into place, so a variant is
    there whole or not at all."""
    check_name(name)
    ws = workspace
    root = root if root is not None else ws.root / VARIANTS
    patches: list[FloorPatch] = []
    files: dict[str, bytes] = {}
    for f in ws.building.manifest.floors:
        k = f.index
        base = ws.base_bytes(k)
        now = ws.house_bytes(k)
        house = Path(f.house).name
        if now != base:
            p = diff_house(json.loads(base), json.loads(now), k, house, _sha(base))
            if _house_bytes(patch_house(json.loads(base), p)) != now:
                raise EditError(f"floor {k}: the patch does not reproduce the edited house (a bug)")
            patches.append(p)
        files[house] = now
    variant = Variant(name=name, building=ws.building.manifest.id, text=text, planner=planner, spec=spec,
                      patch=patches, log=log, task=task)
    tmp = root / f".{name}.tmp"
    shutil.rmtree(tmp, ignore_errors=True)
    for house, data in files.items():
        atomic_write_bytes(tmp / "scenes" / house, data)
    manifest = ws.building.manifest.model_copy(deep=True)
    manifest.floors = [f.model_copy(update={"house": Path(f.house).name}) for f in manifest.floors]
    manifest.to_json(tmp / "scenes" / "manifest.json")
    TaskSet(building=variant.building, tasks=[task]).to_json(tmp / "task.json")
    atomic_write_text(tmp / "variant.json", variant.model_dump_json(indent=1) + "\n")
    final = root / name
    old = root / f".{name}.old"
    if final.exists():
        shutil.rmtree(old, ignore_errors=True)
        os.replace(final, old)
    os.replace(tmp, final)
    shutil.rmtree(old, ignore_errors=True)
    return final


def load_variant(building_dir: str | Path, name: str) -> Variant:
    from mansion.models._validation import load_written

    path = variants_dir(building_dir) / check_name(name) / "variant.json"
    if not path.is_file():
        known = ", ".join(v.name for v in list_variants(building_dir)) or "none"
        raise InvalidInputError(f"no variant {name!r} in {str(path.parent.parent)!r} (variants: {known})")
    return load_written(Variant, path, "variant")


def list_variants(building_dir: str | Path) -> list[Variant]:
    root = variants_dir(building_dir)
    if not root.is_dir():
        return []
    return [load_variant(building_dir, p.name) for p in sorted(root.iterdir())
            if p.is_dir() and not p.name.startswith(".") and (p / "variant.json").is_file()]


def applied(building_dir: str | Path) -> str | None:
    """The variant now applied to the building's own house JSONs, if any."""
    marker = variants_dir(building_dir) / APPLIED / "applied.json"
    if not marker.is_file():
        return None
    return str(json.loads(marker.read_text(encoding="utf-8"))["name"])


def apply_variant(building_dir: str | Path, name: str) -> list[Path]:
    """Write the variant's edited house JSONs over the building's (atomically, one file each);
    returns the files written. The base bytes are kept for :func:`revert_variant`."""
    v = load_variant(building_dir, name)
    now = applied(building_dir)
    if now is not None:
        raise EditError(f"variant {now!r} is applied to the building: revert it first")
    scenes = find_manifest(building_dir).parent
    keep = variants_dir(building_dir) / APPLIED
    written = []
    plans = []
    for p in v.patch:
        target = scenes / p.house
        base = target.read_bytes()
        if _sha(base) != p.base_sha256:
            raise EditError(f"{target} is not the house variant {name!r} was made from (it changed since)")
        plans.append((p, target, base, _house_bytes(patch_house(json.loads(base), p))))
    for p, target, base, _ in plans:
        atomic_write_bytes(keep / "base" / p.house, base)
    atomic_write_text(keep / "applied.json", json.dumps({"name": name, "files": [p.house for p in v.patch]}) + "\n")
    for _, target, _, data in plans:
        written.append(atomic_write_bytes(target, data))
    return written


def revert_variant(building_dir: str | Path) -> tuple[str, list[Path]]:
    """Restore the building's house JSONs a variant's ``apply`` replaced, byte for byte."""
    name = applied(building_dir)
    if name is None:
        raise EditError("no variant is applied to the building")
    keep = variants_dir(building_dir) / APPLIED
    scenes = find_manifest(building_dir).parent
    files = json.loads((keep / "applied.json").read_text(encoding="utf-8"))["files"]
    written = [atomic_write_bytes(scenes / f, (keep / "base" / f).read_bytes()) for f in files]
    shutil.rmtree(keep)
    return name, written
