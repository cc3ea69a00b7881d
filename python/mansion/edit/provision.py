"""The offline controller: the paper's check-and-provision workflow, run deterministically from a
structured task (:class:`~mansion.edit.spec.EditSpec`).

The task is decomposed into preconditions, in order: the start room exists and the agent fits in
it; each object to fetch lies where the task says (found there, else provisioned: an asset of
its type from the asset database placed on or in a receptacle of the named type on that floor);
the destination receptacle exists, is reachable and has room for every fetched object (else the
clutter on it is cleared, largest first); and a walkable route joins the start, each object and
the destination across floors through the cores. Each precondition is checked with the tools and
logged with every check and edit; the first that cannot be met stops the run, naming it and why.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, field
from typing import Any, Literal

from mansion.edit.spec import EditSpec, Fetch
from mansion.edit.surfaces import contents, on_top
from mansion.edit.tools import SceneTools
from mansion.edit.workspace import norm
from mansion.exceptions import EditError, IncompatibleReceptacleError, SurfaceFullError
from mansion.scene.house import HouseObject
from mansion.sim.tasks import Destination, Start, TargetObject
from mansion.sim.world import ObjectInfo

__all__ = ["EditLog", "LogLine", "PreconditionFailed", "Provisioned", "provision"]

#: Assets of a type tried, smallest first, before a receptacle counts as full for it.
ASSET_TRIES = 3


@dataclass(frozen=True)
class LogLine:
    kind: Literal["precondition", "check", "edit", "result"]
    text: str
    ok: bool | None = None

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)


@dataclass
class EditLog:
    lines: list[LogLine] = field(default_factory=list)

    def precondition(self, text: str) -> None:
        self.lines.append(LogLine("precondition", text))

    def check(self, text: str, ok: bool) -> None:
        self.lines.append(LogLine("check", text, ok))

    def edit(self, text: str) -> None:
        self.lines.append(LogLine("edit", text, True))

    def result(self, text: str, ok: bool) -> None:
        self.lines.append(LogLine("result", text, ok))


class PreconditionFailed(EditError):
    """A precondition of the task cannot be met; ``precondition`` names it."""

    def __init__(self, precondition: str, reason: str):
        super().__init__(f"precondition not met: {precondition}: {reason}")
        self.precondition = precondition
        self.reason = reason


@dataclass
class Provisioned:
    """What the task uses, once every precondition holds."""

    start: Start
    targets: list[TargetObject]
    destination: Destination


class _Run:
    def __init__(self, tools: SceneTools, spec: EditSpec, log: EditLog):
        self.tools, self.ws, self.spec, self.log = tools, tools.ws, spec, log
        self.claimed: set[tuple[int, str]] = set()
        self.done_edits = 0

    def flush_edits(self) -> None:
        for e in self.tools.edits[self.done_edits:]:
            self.log.edit(e.text)
        self.done_edits = len(self.tools.edits)

    def _begin(self, what: str, floor: int) -> str:
        """Log the precondition; a floor the building lacks fails it at once."""
        self.log.precondition(what)
        try:
            self.ws.check_floor(floor)
        except EditError as exc:
            raise PreconditionFailed(what, str(exc)) from None
        return what

    # -- start ----------------------------------------------------------------------------------
    def start(self) -> Start:
        s = self.spec.start
        what = f"the agent starts in {s.room} on floor {s.floor}"
        self.log.precondition(what)
        try:
            room = self.ws.room(s.floor, s.room)
        except EditError as exc:
            self.log.check(str(exc), False)
            raise PreconditionFailed(what, str(exc)) from None
        here = self.tools.check_path(s.floor, room, s.floor, room)
        self.log.check(f"CheckPath({room} → {room}): {'the agent fits there' if here['ok'] else here['reason']}", here["ok"])
        if not here["ok"]:
            raise PreconditionFailed(what, here["reason"])
        return Start(floor=s.floor, room=room)

    # -- objects to fetch -----------------------------------------------------------------------
    def fetch(self, f: Fetch) -> TargetObject:
        what = self._begin(f"{_a(f.object_type)} {f.where()} on floor {f.floor}", f.floor)
        f = f.model_copy(update={"object_type": _object_type(f.object_type, what)})
        kind = f.on or f.in_
        if kind is not None:
            recs = self.ws.of_type(f.floor, kind)
            self.log.check(f"ListObjects(floor={f.floor}, {kind}): {', '.join(r.id for r in recs) or 'none'}", bool(recs))
            if not recs:
                types = sorted({i.props.object_type for i in self.ws.floor(f.floor).objects.values()
                                if i.props.receptacle and i.parent is None})
                raise PreconditionFailed(what, f"floor {f.floor} has no {kind} (its furniture that holds things: "
                                         f"{', '.join(types)})")
        else:
            recs = []
        found = self._find(f, recs)
        if found is None:
            found = self._provision(f, what, recs)
        else:
            shut = self.ws.floor(f.floor).inside(found)
            if shut is not None:
                self.tools.open_container(shut, f.floor)
                self.flush_edits()
        self.claimed.add((f.floor, found.id))
        return self._target(f.floor, found)

    def _find(self, f: Fetch, recs: list[ObjectInfo]) -> ObjectInfo | None:
        st = self.ws.floor(f.floor)
        everything = list(st.objects.values())
        want = norm(f.object_type)

        def usable(o: ObjectInfo) -> bool:
            return (norm(o.props.object_type) == want and o.props.pickupable and not o.obj.children
                    and (f.floor, o.id) not in self.claimed)

        if not recs:
            hits = sorted((o for o in everything if usable(o) and o.parent is not None
                           and self.ws.reachable(f.floor, o.parent)), key=lambda o: o.id)
            self.log.check(f"ListObjects(floor={f.floor}, {f.object_type}): {', '.join(o.id for o in hits) or 'none'}", bool(hits))
            return hits[0] if hits else None
        for rec in recs:
            items = contents(rec, everything) if f.in_ else on_top(rec, everything)
            tool = "SearchContents" if f.in_ else "CheckSurface"
            hit = next((o for o in items if usable(o)), None)
            listed = ", ".join(o.props.object_type for o in items) or "nothing"
            self.log.check(f"{tool}({rec.id}): {listed}" + (f" — {hit.id} is there" if hit else f" — no {f.object_type}"),
                           hit is not None)
            if hit is not None and self.ws.reachable(f.floor, rec.id):
                return hit
        return None

    def _provision(self, f: Fetch, what: str, recs: list[ObjectInfo]) -> ObjectInfo:
        found = self.tools.search_assets(f.object_type, top_k=50, properties=["Pickupable"])["assets"]
        assets = [a for a in found if norm(a["object_type"]) == norm(f.object_type)]
        self.log.check(f"SearchAssets({f.object_type!r}, Pickupable): "
                       f"{', '.join(a['asset_id'] for a in assets[:5]) or 'none of that type'}", bool(assets))
        if not assets:
            raise PreconditionFailed(what, f"AI2-THOR's asset database has no pickupable {f.object_type}")
        # the smallest assets first: the likeliest to fit between what is there
        assets.sort(key=lambda a: (a["size"][0] * a["size"][2], a["asset_id"]))
        if not recs:
            recs = self._any_receptacles(f)
        why: list[str] = []
        for rec in recs:
            if not self.ws.reachable(f.floor, rec.id):
                why.append(f"{rec.id} cannot be reached")
                self.log.check(f"{rec.id} reachable from the spawn of floor {f.floor}: no", False)
                continue
            for a in assets[:ASSET_TRIES]:
                try:
                    if rec.props.openable:
                        placed = self.tools.place_in_container(a["asset_id"], rec.id, f.floor, open=True)
                    else:
                        placed = self.tools.place_on_surface(a["asset_id"], rec.id, f.floor)
                except SurfaceFullError as exc:
                    why.append(str(exc))
                    continue
                except IncompatibleReceptacleError as exc:
                    self.log.check(str(exc), False)
                    why.append(str(exc))
                    break
                self.flush_edits()
                return self.ws.floor(f.floor).objects[placed["placed"]]
            self.log.check(f"room for a {f.object_type} {'in' if rec.props.openable else 'on'} {rec.id}: no", False)
        raise PreconditionFailed(what, "; ".join(why) or f"no receptacle on floor {f.floor} can take a {f.object_type}")

    def _any_receptacles(self, f: Fetch) -> list[ObjectInfo]:
        """Receptacles of the floor AI2-THOR's database lets take the type, those its scenes put
        the type on most often first (a tomato goes to the fridge before the sink)."""
        from mansion.placement.assets import database

        rec_db = database().receptacles
        st = self.ws.floor(f.floor)
        out = [i for i in st.objects.values() if i.parent is None and i.props.receptacle
               and f.object_type in rec_db.get(i.props.object_type, {})]
        return sorted(out, key=lambda i: (-rec_db[i.props.object_type][f.object_type], i.id))

    def _target(self, floor: int, o: ObjectInfo) -> TargetObject:
        st = self.ws.floor(floor)
        parent = st.objects[o.parent] if o.parent else None
        room = o.room or ""
        return TargetObject(object_id=o.id, object_type=o.props.object_type, floor=floor, room=room,
                            room_type=st.rooms[room].room_type if room in st.rooms else "",
                            receptacle=o.parent, receptacle_type=parent.props.object_type if parent else None)

    # -- destination ----------------------------------------------------------------------------
    def deliver(self, start: Start, targets: list[TargetObject]) -> Destination:
        d = self.spec.deliver
        kinds = ", ".join(t.object_type for t in targets)
        what = self._begin(f"{_a(d.on)} on floor {d.floor} with room for {kinds}", d.floor)
        recs = [r for r in self.ws.of_type(d.floor, d.on) if r.parent is None]
        # the one in the start room first (the sofa of "the lobby's sofa"), then by id
        recs.sort(key=lambda r: (not (d.floor == start.floor and r.room == start.room), r.id))
        self.log.check(f"ListObjects(floor={d.floor}, {d.on}): {', '.join(r.id for r in recs) or 'none'}", bool(recs))
        if not recs:
            raise PreconditionFailed(what, f"floor {d.floor} has no {d.on}")
        if recs[0].props.openable or not recs[0].props.receptacle:
            raise PreconditionFailed(what, f"a {d.on} is {'a container' if recs[0].props.receptacle else 'no receptacle'}: "
                                     "the task puts its objects on a surface")
        items = [self.ws.floor(t.floor).objects[t.object_id] for t in targets]
        reachable = [r for r in recs if self.ws.reachable(d.floor, r.id)]
        for r in recs:
            if r not in reachable:
                self.log.check(f"{r.id} reachable from the spawn of floor {d.floor}: no", False)
        for r in reachable:
            ok = _takes_all(r, items)
            self.log.check(f"room on {r.id} for {kinds}: {'yes' if ok else 'no'}", ok)
            if ok:
                return self._destination(d.floor, r)
        if not reachable:
            raise PreconditionFailed(what, f"no {d.on} on floor {d.floor} can be reached")
        # make room on the first: clear what lies on it, largest first, until everything fits
        rec = reachable[0]
        clutter = sorted(on_top(rec, list(self.ws.floor(d.floor).objects.values())),
                         key=lambda o: (-o.props.width * o.props.depth, o.id))
        for o in clutter:
            self.tools.remove_object(object_id=o.id, floor=d.floor)
            self.flush_edits()
            rec = self.ws.floor(d.floor).objects[rec.id]
            if _takes_all(rec, items):
                self.log.check(f"room on {rec.id} for {kinds}: yes", True)
                return self._destination(d.floor, rec)
        raise PreconditionFailed(what, f"{kinds} do not fit on {rec.id} even cleared")

    def _destination(self, floor: int, r: ObjectInfo) -> Destination:
        st = self.ws.floor(floor)
        room = r.room or ""
        return Destination(floor=floor, room=room, room_type=st.rooms[room].room_type if room in st.rooms else "",
                           receptacle=r.id, receptacle_type=r.props.object_type)

    # -- routes ---------------------------------------------------------------------------------
    def routes(self, start: Start, targets: list[TargetObject], dest: Destination) -> None:
        what = "a walkable route from the start to each object and on to the destination"
        self.log.precondition(what)
        legs = []
        for t in targets:
            legs += [(start.floor, start.room or "", t.floor, t.room), (t.floor, t.room, dest.floor, dest.room)]
        for a in dict.fromkeys(legs):
            r = self.tools.check_path(*a)
            via = f" via {', '.join(r['cores'])}" if r.get("cores") else ""
            text = (f"CheckPath({a[1]} floor {a[0]} → {a[3]} floor {a[2]}): "
                    + (f"{r['metres']} m{via}" if r["ok"] else r["reason"]))
            self.log.check(text, r["ok"])
            if not r["ok"]:
                raise PreconditionFailed(what, r["reason"])


def _object_type(name: str, what: str) -> str:
    """AI2-THOR's spelling of an object type ("apple", "wine bottle" → Apple, WineBottle)."""
    from rapidfuzz import process

    from mansion.placement.assets import database

    types = {norm(t): t for t in database().types}
    if norm(name) in types:
        return types[norm(name)]
    near = [m[0] for m in process.extract(name, sorted(types.values()), limit=3)]
    raise PreconditionFailed(what, f"AI2-THOR has no object type {name!r} (nearest: {', '.join(near)})")


def _a(word: str) -> str:
    return f"{'an' if word[:1].lower() in 'aeiou' else 'a'} {word}"


def _takes_all(rec: ObjectInfo, items: list[ObjectInfo]) -> bool:
    """Whether the simulator's ``Put`` finds a spot on ``rec`` for every item, one after the
    other (its own free-spot search, on a copy of the receptacle)."""
    from mansion.sim.env import _free_spot

    copy = ObjectInfo(rec.obj.model_copy(deep=True), rec.parent, rec.room, rec.props)
    for it in items:
        spot = _free_spot(copy, it, False)
        if spot is None:
            return False
        copy.obj.children.append(HouseObject.model_validate({
            "id": f"{it.id}|probe", "assetId": it.obj.asset_id, "position": {"x": spot[0], "y": spot[1], "z": spot[2]},
            "rotation": {"x": 0.0, "y": rec.obj.rotation.y, "z": 0.0}}))
    return True


def provision(tools: SceneTools, spec: EditSpec, log: EditLog) -> Provisioned:
    """Check every precondition of ``spec`` on the tools' workspace, provisioning what is
    missing; raises :class:`PreconditionFailed` at the first that cannot be met."""
    run = _Run(tools, spec, log)
    run.done_edits = len(tools.edits)  # a controller before this one logged its own edits
    start = run.start()
    targets = [run.fetch(f) for f in spec.fetch]
    dest = run.deliver(start, targets)
    run.routes(start, targets, dest)
    return Provisioned(start, targets, dest)
