"""A dataset folder on disk, and the files derived from its buildings.

::

    DIR/dataset.json            the settings (a rerun must match them; only --n may change)
    DIR/buildings/<id>/         one finished building: building.json, scenes/, record.json
    DIR/failures/<id>.json      one failed building: seed, type, the exception
    DIR/index.jsonl             one line per finished building (from the record.json files)
    DIR/failures.jsonl          one line per failed building (from failures/)
    DIR/summary.json            counts and totals over the index
    DIR/statistics.png          the paper's figure (mansion.dataset.statistics)

The index, failures and summary are never appended to: they are rebuilt from the building
folders, so they always agree with what is on disk, however the last run ended. Everything but
the ``seconds`` fields is the same for the same command.
"""

from __future__ import annotations

import json
import os
import shutil
from collections import Counter
from pathlib import Path
from typing import Any

from mansion._io import atomic_write_text
from mansion.exceptions import InvalidInputError

__all__ = [
    "INDEX_FIELDS",
    "clean_stale",
    "failure_path",
    "finished_ids",
    "load_records",
    "RECORD",
    "rebuild",
    "summarise",
    "write_json",
]

#: The fields of each index line (the rest of a record stays in its folder's record.json).
INDEX_FIELDS = (
    "id", "seed", "category", "type", "floors", "rooms", "objects", "area", "floor_area", "seconds",
)


#: The record file in every finished building's folder.
RECORD = "record.json"


def write_json(path: str | os.PathLike[str], data: Any) -> Path:
    return atomic_write_text(path, json.dumps(data, indent=1, sort_keys=True) + "\n")


def failure_path(root: str | os.PathLike[str], building_id: str) -> Path:
    return Path(root) / "failures" / f"{building_id}.json"


def finished_ids(root: str | os.PathLike[str]) -> set[str]:
    """Ids of the finished buildings: their folder exists (it is only ever renamed into place
    complete)."""
    folder = Path(root) / "buildings"
    if not folder.is_dir():
        return set()
    return {p.name for p in folder.iterdir() if p.is_dir() and not p.name.startswith(".")}


def clean_stale(root: str | os.PathLike[str]) -> int:
    """Delete the half-built ``.tmp-`` folders a crashed or interrupted run left; returns how
    many. Only call it when no job of this dataset is running."""
    folder = Path(root) / "buildings"
    stale = sorted(folder.glob(".tmp-*")) if folder.is_dir() else []
    for p in stale:
        shutil.rmtree(p, ignore_errors=True)
    return len(stale)


def _read(path: Path) -> dict[str, Any]:
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise InvalidInputError(f"cannot read {str(path)!r}: {exc}") from exc
    if not isinstance(data, dict):
        raise InvalidInputError(f"{str(path)!r} is not a JSON object")
    return data


def load_records(root: str | os.PathLike[str], ids: set[str] | None = None) -> list[dict[str, Any]]:
    """The record of every finished building (only ``ids`` when given), in index order."""
    base = Path(root) / "buildings"
    chosen = sorted(finished_ids(root) if ids is None else finished_ids(root) & ids)
    return [_read(base / i / RECORD) for i in chosen]


def _failures(root: Path, ids: set[str]) -> list[dict[str, Any]]:
    folder = root / "failures"
    if not folder.is_dir():
        return []
    done = finished_ids(root)
    return [_read(p) for p in sorted(folder.glob("*.json")) if p.stem in ids and p.stem not in done]


def summarise(records: list[dict[str, Any]], failures: int, settings: dict[str, Any]) -> dict[str, Any]:
    """Counts and totals of a dataset's index (``seconds`` is the only timing in it)."""

    def count(key: str) -> dict[str, int]:
        return {str(k): v for k, v in sorted(Counter(r[key] for r in records).items())}

    functions: Counter[str] = Counter()
    for r in records:
        functions.update(r.get("functions", {}))
    return {
        "settings": settings,
        "buildings": len(records),
        "failures": failures,
        "categories": count("category"),
        "types": count("type"),
        "floors": count("floors"),
        "total_floors": sum(r["floors"] for r in records),
        "rooms": sum(r["rooms"] for r in records),
        "objects": sum(r["objects"] for r in records),
        "area": round(sum(r["area"] for r in records), 2),
        "functions": {k: round(v, 2) for k, v in sorted(functions.items())},
        "seconds": round(sum(r["seconds"] for r in records), 3),
    }


def rebuild(root: str | os.PathLike[str], ids: list[str], settings: dict[str, Any]) -> dict[str, Any]:
    """Rewrite ``index.jsonl``, ``failures.jsonl`` and ``summary.json`` from the folders of the
    buildings ``ids`` (the dataset's first n); returns the summary."""
    base = Path(root)
    wanted = set(ids)
    records = load_records(base, wanted)
    failures = _failures(base, wanted)
    lines = [json.dumps({k: r[k] for k in INDEX_FIELDS}, sort_keys=False) for r in records]
    atomic_write_text(base / "index.jsonl", "".join(line + "\n" for line in lines))
    atomic_write_text(
        base / "failures.jsonl", "".join(json.dumps(f, sort_keys=True) + "\n" for f in failures)
    )
    summary = summarise(records, len(failures), settings)
    write_json(base / "summary.json", summary)
    return summary
