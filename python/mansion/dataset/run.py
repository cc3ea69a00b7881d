"""``make_dataset``: a dataset of n buildings in a folder, resumable, on either engine.

A rerun of the same command skips the finished buildings (their folders exist), deletes the
half-built ones a crash or Ctrl-C left, retries the failed ones and rebuilds the index, failures,
summary and picture from what is on disk. The settings are kept in ``DIR/dataset.json``; a rerun
with other settings is refused (only ``n`` may change: a larger n extends the dataset with the
same first buildings).
"""

from __future__ import annotations

import contextlib
import fcntl
import json
import os
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from mansion.dataset.engines import ENGINES
from mansion.dataset.job import JobSettings
from mansion.building.generate import RELAYOUTS
from mansion.dataset.mix import BuildingSpec, building_spec, parse_floors, parse_mix
from mansion.dataset.statistics import plot_statistics
from mansion.dataset.store import clean_stale, finished_ids, load_records, rebuild, write_json
from mansion.exceptions import InvalidInputError
from mansion.planning.program import DEFAULT_MAX_FLOOR_AREA

__all__ = ["DatasetSettings", "dataset_specs", "make_dataset"]

#: The paper's MansionWorld mix.
DEFAULT_MIX = "residential=0.5,office=0.3,public=0.2"


@dataclass(frozen=True)
class DatasetSettings:
    """Everything that decides a dataset's buildings, but their number."""

    mix: dict[str, float] = field(default_factory=lambda: parse_mix(DEFAULT_MIX))
    floors: tuple[int, int] = (2, 10)
    max_floor_area: float = DEFAULT_MAX_FLOOR_AREA
    seed: int = 0
    pictures: bool = False
    validate: bool = True
    #: :func:`mansion.generate_building`'s ``relayouts`` for every building.
    relayouts: int = RELAYOUTS

    @classmethod
    def parse(
        cls, *, mix: str = DEFAULT_MIX, floors: str = "2-10",
        max_floor_area: float = DEFAULT_MAX_FLOOR_AREA, seed: int = 0, pictures: bool = False,
        validate: bool = True, relayouts: int = RELAYOUTS,
    ) -> DatasetSettings:
        if not 20 <= max_floor_area <= DEFAULT_MAX_FLOOR_AREA * 4:
            raise InvalidInputError(f"max floor area must be within 20-2000 m², got {max_floor_area:g}")
        if seed < 0:
            raise InvalidInputError(f"seed must be >= 0, got {seed}")
        from mansion.building.generate import check_relayouts

        check_relayouts(relayouts)
        return cls(
            parse_mix(mix), parse_floors(floors), float(max_floor_area), seed, pictures, validate, relayouts,
        )

    def to_dict(self) -> dict[str, Any]:
        out = {
            "mix": {k: round(v, 6) for k, v in self.mix.items()}, "floors": list(self.floors),
            "max_floor_area": self.max_floor_area, "seed": self.seed, "pictures": self.pictures,
            "validate": self.validate,
        }
        # written only when asked for, so datasets made before the option resume as they were
        if self.relayouts:
            out["relayouts"] = self.relayouts
        return out

    def job(self) -> JobSettings:
        return JobSettings(self.max_floor_area, self.pictures, self.validate, self.relayouts)


def dataset_specs(settings: DatasetSettings, n: int) -> list[BuildingSpec]:
    """The first ``n`` buildings of the dataset ``settings`` decides."""
    return [building_spec(settings.seed, i, settings.mix, settings.floors) for i in range(n)]


def _open(root: Path, settings: DatasetSettings, n: int) -> None:
    path = root / "dataset.json"
    wanted = settings.to_dict()
    if path.is_file():
        try:
            kept = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError) as exc:
            raise InvalidInputError(f"cannot read {str(path)!r}: {exc}") from exc
        old = {k: v for k, v in kept.items() if k != "n"}
        if old != wanted:
            diff = ", ".join(
                f"{k}: {old.get(k)!r} there, {wanted.get(k)!r} now"
                for k in sorted(set(wanted) | set(old)) if old.get(k) != wanted.get(k)
            )
            raise InvalidInputError(
                f"{str(root)!r} holds a dataset made with other settings ({diff}); "
                "rerun with the same settings or choose another --out"
            )
    elif any(p.name != ".lock" for p in root.iterdir()):
        raise InvalidInputError(f"{str(root)!r} is not empty and holds no dataset.json; choose another --out")
    write_json(path, {**wanted, "n": n})


@contextlib.contextmanager
def _lock(root: Path) -> Iterator[None]:
    """One run per dataset folder: a second would delete the first's half-built buildings."""
    root.mkdir(parents=True, exist_ok=True)
    with open(root / ".lock", "w") as handle:
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            raise InvalidInputError(f"another run is writing the dataset in {str(root)!r}") from None
        yield


def make_dataset(
    out: str | os.PathLike[str],
    n: int,
    settings: DatasetSettings,
    *,
    workers: int = 1,
    engine: str = "local",
    address: str | None = None,
    on_start: Callable[[int, int], None] | None = None,
    on_result: Callable[[dict[str, Any]], None] | None = None,
) -> dict[str, Any]:
    """Generate the dataset's first ``n`` buildings into ``out``; returns the summary.

    ``on_start(total, already_done)`` is called once the finished buildings are counted, and
    ``on_result(record)`` after every job (a failed one has ``"failed": True``). The index,
    failures, summary and picture are written even when the run is interrupted.
    """
    if isinstance(n, bool) or not isinstance(n, int) or n < 1:
        raise InvalidInputError(f"n must be a whole number >= 1, got {n!r}")
    if engine not in ENGINES:
        raise InvalidInputError(f"unknown engine {engine!r}; choose from {', '.join(ENGINES)}")
    root = Path(out)
    with _lock(root):
        return _make(root, n, settings, workers, engine, address, on_start, on_result)


def _make(
    root: Path, n: int, settings: DatasetSettings, workers: int, engine: str, address: str | None,
    on_start: Callable[[int, int], None] | None, on_result: Callable[[dict[str, Any]], None] | None,
) -> dict[str, Any]:
    _open(root, settings, n)
    clean_stale(root)
    specs = dataset_specs(settings, n)
    done = finished_ids(root)
    todo = [s for s in specs if s.id not in done]
    if on_start:
        on_start(n, n - len(todo))
    try:
        if todo:
            for record in ENGINES[engine](todo, settings.job(), root, workers=workers, address=address):
                if on_result:
                    on_result(record)
    finally:
        ids = [s.id for s in specs]
        summary = rebuild(root, ids, settings.to_dict())
        plot_statistics(
            load_records(root, set(ids)), root / "statistics.png", max_floor_area=settings.max_floor_area
        )
    return summary
