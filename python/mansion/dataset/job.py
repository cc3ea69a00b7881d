"""One building of a dataset: the job every engine runs, a function of the building's spec alone.

The job generates the building (plans), its AI2-THOR scenes (furnished), validates them as the
simulator's loader would, optionally draws its plans (:mod:`mansion.dataset.pictures`), and moves the finished folder into
``DIR/buildings/<id>/`` with one ``os.rename``: it is built in ``DIR/buildings/.tmp-<id>-<pid>/``
first, so a building folder either is complete or does not exist (a crash leaves only a ``.tmp-``
folder, which the next run deletes). On a cluster ``DIR`` must be a path every worker sees.

The result record goes into the folder as ``record.json`` and back to the caller; the index of the
dataset is derived from these files (:mod:`mansion.dataset.store`). Timings and the worker's peak
memory are in the record only, never in ``building.json`` or the scenes, which are the same bytes
for the same spec on any machine. A failure (any exception) is recorded in
``DIR/failures/<id>.json`` and returned, never raised, so one building cannot stop the others.
"""

from __future__ import annotations

import os
import resource
import shutil
import sys
import time
import traceback
from collections import Counter
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

from mansion._collector import collector_paused
from mansion.building.generate import RELAYOUTS
from mansion.dataset.mix import BuildingSpec
from mansion.dataset.pictures import draw_plans
from mansion.dataset.store import RECORD, failure_path, write_json
from mansion.exceptions import InvalidBuildingError
from mansion.planning.vocabulary import room_kind

__all__ = ["JobSettings", "record_failure", "run_job", "warm_up"]

#: The stages a record's ``timings`` names, in the order they run.
STAGES = ("planning", "solving", "checks", "scenes", "writing", "validation", "pictures")


@dataclass(frozen=True)
class JobSettings:
    """The dataset-wide options of every job."""

    max_floor_area: float = 500.0
    pictures: bool = False
    validate: bool = True
    relayouts: int = RELAYOUTS


def warm_up() -> None:
    """Import what a job uses, so a worker's first building is not charged for the imports."""
    import mansion.building  # noqa: F401
    import mansion.scene  # noqa: F401
    import mansion.scene.validate  # noqa: F401


def _peak_memory_mb() -> float:
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    # kilobytes on Linux, bytes on macOS
    return round(peak / (1024 * 1024 if sys.platform == "darwin" else 1024), 1)


class _Clock:
    """Seconds per stage; ``lap(name)`` charges the time since the last lap to ``name``: wall
    clock in ``timings``, this process's CPU time in ``cpu`` (which other work on a busy
    machine does not inflate, and which leaves out waiting on the disk)."""

    def __init__(self) -> None:
        self.start = self.last = time.perf_counter()
        self.cpu_start = self.cpu_last = time.process_time()
        self.timings: dict[str, float] = {}
        self.cpu: dict[str, float] = {}

    def lap(self, name: str) -> None:
        now, cpu = time.perf_counter(), time.process_time()
        self.timings[name] = round(self.timings.get(name, 0.0) + now - self.last, 4)
        self.cpu[name] = round(self.cpu.get(name, 0.0) + cpu - self.cpu_last, 4)
        self.last, self.cpu_last = now, cpu

    def total(self) -> float:
        return round(time.perf_counter() - self.start, 3)

    def cpu_total(self) -> float:
        return round(time.process_time() - self.cpu_start, 3)


def _functions(building: Any) -> dict[str, float]:
    """Room area (m²) by function (the vocabulary's role; cores and unknown types by their own
    name), over every floor: the dataset's functional composition."""
    area: Counter[str] = Counter()
    cores = {c.id for c in building.program.cores}
    for floor in building.floors:
        for room in floor.layout.rooms:
            role = "core" if room.id in cores else room_kind(room.room_type).role
            area[role] += room.area
    return {k: round(v, 2) for k, v in sorted(area.items())}


def _describe(spec: BuildingSpec, building: Any, objects: int, warnings: int) -> dict[str, Any]:
    floor_areas = [sum(r.area for r in f.layout.rooms) for f in building.floors]
    return {
        "id": spec.id,
        "index": spec.index,
        "seed": spec.seed,
        "category": spec.category,
        "type": building.program.building_type,
        "description": spec.description,
        "floors": building.program.floor_count,
        "rooms": sum(len(f.layout.rooms) for f in building.floors),
        "objects": objects,
        "area": round(sum(floor_areas), 2),
        "floor_area": round(max(floor_areas), 2),
        "relaxed_floors": sum(1 for f in building.floors if f.relaxations),
        "warnings": warnings,
        "functions": _functions(building),
    }


def _solver_seconds(building: Any) -> float:
    """The solver's own wall-clock time over the floors it solved (copies take none); kept in
    memory only by the models, so it goes to the record."""
    return round(sum(f.layout.diagnostics.seconds for f in building.floors if f.copy_of is None), 4)


def _build(spec: BuildingSpec, settings: JobSettings, stage: Path, clock: _Clock) -> dict[str, Any]:
    from mansion.building import generate_building
    from mansion.scene import build_scenes, validate_building
    from mansion.scene.write import save_scenes
    from mansion.scene.validate import errors

    solving = False

    def progress(message: str, done: int, total: int) -> None:
        # generate_building reports floor 0 once the program is planned and "checks" once
        # every floor is solved: the laps of the paper's planning and solving steps
        nonlocal solving
        if not solving:
            clock.lap("planning")
            solving = True
        if message == "checks":
            clock.lap("solving")

    building = generate_building(
        spec.description, floors=spec.floors, building_type=spec.building_type, seed=spec.seed,
        max_floor_area=settings.max_floor_area, relayouts=settings.relayouts, progress=progress,
    )
    clock.lap("checks")
    scenes = build_scenes(building, objects=True)
    clock.lap("scenes")
    solver_seconds = _solver_seconds(building)
    building.to_json(stage / "building.json")  # no timings: the models never write them
    manifest = save_scenes(scenes, stage / "scenes")
    clock.lap("writing")
    warnings = 0
    if settings.validate:
        problems = validate_building(manifest, written=scenes.houses)
        bad = errors(problems)
        if bad:
            shown = "; ".join(str(p) for p in bad[:3])
            raise InvalidBuildingError(f"{len(bad)} validation error(s): {shown}")
        warnings = len(problems)
        clock.lap("validation")
    if settings.pictures:
        draw_plans(building, stage / "overview.png")
        clock.lap("pictures")
    objects = sum(len(h.objects) + sum(len(o.children) for o in h.objects) for h in scenes.houses)
    clock.timings["solver"] = solver_seconds  # inside "solving": the Rust solver's own time
    return _describe(spec, building, objects, warnings)


def run_job(spec: BuildingSpec, settings: JobSettings, out: str | os.PathLike[str]) -> dict[str, Any]:
    """Generate building ``spec`` into ``out/buildings/<id>/``; returns its record (with
    ``"failed": True``, the exception and traceback when it failed; then it is also written to
    ``out/failures/<id>.json``). Never raises for a failure of the building itself."""
    root = Path(out)
    final = root / "buildings" / spec.id
    stage = root / "buildings" / f".tmp-{spec.id}-{os.getpid()}"
    clock = _Clock()
    try:
        shutil.rmtree(stage, ignore_errors=True)
        (stage / "scenes").mkdir(parents=True)
        with collector_paused():
            record = _build(spec, settings, stage, clock)
        record["seconds"] = clock.total()
        record["timings"] = clock.timings
        record["cpu_seconds"] = clock.cpu_total()
        record["cpu_timings"] = clock.cpu
        record["peak_memory_mb"] = _peak_memory_mb()
        write_json(stage / RECORD, record)
        failure_path(root, spec.id).unlink(missing_ok=True)
        os.rename(stage, final)  # the one step that makes the building exist
        return record
    except Exception as exc:
        shutil.rmtree(stage, ignore_errors=True)
        return record_failure(root, spec, exc, traceback.format_exc(limit=8), clock.total())


def record_failure(
    root: Path, spec: BuildingSpec, exc: BaseException, trace: str = "", seconds: float = 0.0,
    message: str | None = None,
) -> dict[str, Any]:
    """Write ``root/failures/<id>.json`` for building ``spec`` (its seed, type and the
    exception) and return it."""
    failure = {
        **{k: v for k, v in asdict(spec).items() if k != "building_type"},
        "type": spec.building_type, "failed": True, "error": type(exc).__name__,
        "message": str(exc) if message is None else message, "traceback": trace,
        "seconds": seconds,
    }
    write_json(failure_path(root, spec.id), failure)
    return failure
