"""``mansion dataset``: the mix draw, determinism across worker counts and engines, resume after a
crash, failures recorded without stopping the others, the Ray engine, the command end to end."""

from __future__ import annotations

import dataclasses

import json
import os
from collections import Counter
from pathlib import Path
from typing import Any

import pytest
from typer.testing import CliRunner

from mansion.cli import app
from mansion.dataset import (
    CATEGORIES,
    DatasetSettings,
    building_spec,
    dataset_specs,
    make_dataset,
    parse_floors,
    parse_mix,
)
from mansion.building.generate import RELAYOUTS
from mansion.exceptions import InvalidInputError
from mansion.models.building import Building
from mansion.planning.description import parse_description

runner = CliRunner()

#: Small, quick buildings: two floors of at most 300 m², no validation (it does not change bytes).
#: Seed 25 starts with an office, a villa and a restaurant, which all generate.
SMALL = DatasetSettings.parse(floors="2-2", seed=25, max_floor_area=300, validate=False)
N = 3


def _files(root: Path) -> dict[str, bytes]:
    """Every file of every finished building but its record (which has the timings)."""
    return {
        str(p.relative_to(root)): p.read_bytes()
        for p in sorted((root / "buildings").rglob("*"))
        if p.is_file() and p.name != "record.json"
    }


def _without_seconds(path: Path) -> list[dict]:
    lines = [json.loads(line) for line in path.read_text().splitlines()]
    for line in lines:
        line.pop("seconds", None)
    return lines


@pytest.fixture(scope="module")
def two_workers(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("two") / "ds"
    make_dataset(out, N, SMALL, workers=2)
    return out


def test_mix_follows_the_shares_on_every_prefix_and_descriptions_say_type_and_floors() -> None:
    settings = DatasetSettings.parse()
    specs = dataset_specs(settings, 1000)
    for n in (100, 1000):
        share = Counter(s.category for s in specs[:n])
        for name, want in settings.mix.items():
            assert abs(share[name] - want * n) <= 2, (n, share)
    assert {s.seed for s in specs} == set(range(1000))
    assert {s.floors for s in specs} == set(range(2, 11))
    for s in specs:
        assert s.building_type in CATEGORIES[s.category]
        request = parse_description(s.description)
        assert (request.building_type, request.floors) == (s.building_type, s.floors), s
    # building i does not depend on the dataset's size
    assert building_spec(0, 637, settings.mix, (2, 10)) == specs[637]
    assert dataset_specs(settings, 10) == specs[:10]


@pytest.mark.parametrize(
    "text", ["residential=0.5,garage=0.5", "office", "office=-1", "office=x", "office=0", "office=1,office=2"]
)
def test_bad_mix_is_a_clear_error(text: str) -> None:
    with pytest.raises(InvalidInputError, match="mix"):
        parse_mix(text)


@pytest.mark.parametrize("text", ["0-3", "3-2", "2-11", "two"])
def test_bad_floor_range_is_a_clear_error(text: str) -> None:
    with pytest.raises(InvalidInputError, match="floors"):
        parse_floors(text)


def test_same_bytes_whatever_the_worker_count(two_workers: Path, tmp_path: Path) -> None:
    one = tmp_path / "one"
    make_dataset(one, N, SMALL, workers=1)
    files = _files(two_workers)
    assert any(k.endswith("building.json") for k in files)
    assert any(k.endswith("manifest.json") for k in files)
    assert _files(one) == files
    assert (one / "statistics.png").read_bytes() == (two_workers / "statistics.png").read_bytes()
    for name in ("index.jsonl", "failures.jsonl"):
        assert _without_seconds(one / name) == _without_seconds(two_workers / name)
    summaries = [json.loads((d / "summary.json").read_text()) for d in (one, two_workers)]
    for s in summaries:
        s.pop("seconds")
    assert summaries[0] == summaries[1]
    assert (summaries[0]["buildings"], summaries[0]["failures"]) == (N, 0)
    assert set(summaries[0]["categories"]) == {"residential", "office", "public"}
    index = [json.loads(line) for line in (one / "index.jsonl").read_text().splitlines()]
    for line in index:
        b = Building.load(one / "buildings" / line["id"] / "building.json")
        assert b.program.floor_count == line["floors"] == 2
        assert max(sum(r.area for r in f.layout.rooms) for f in b.floors) <= 300 + 1e-6
        assert "timings" not in (one / "buildings" / line["id"] / "building.json").read_text()


def test_resume_cleans_a_half_built_building_and_regenerates_nothing(tmp_path: Path) -> None:
    out = tmp_path / "ds"
    make_dataset(out, 2, SMALL, workers=1)
    finished = sorted((out / "buildings").iterdir())
    stamps = {p: (p / "building.json").stat().st_mtime_ns for p in finished}
    # a crash in the middle of building 00002: its half-built folder is all that is left of it
    half = out / "buildings" / ".tmp-00002-4242"
    (half / "scenes").mkdir(parents=True)
    (half / "building.json").write_text('{"desc')
    (out / "index.jsonl").unlink()
    ran: list[str] = []
    make_dataset(out, N, SMALL, workers=1, on_result=lambda r: ran.append(r["id"]))
    assert ran == ["00002"]
    assert not half.exists()
    assert {p: (p / "building.json").stat().st_mtime_ns for p in finished} == stamps
    assert len((out / "index.jsonl").read_text().splitlines()) == N
    assert (out / "failures.jsonl").read_text() == ""
    # nothing left to do: a rerun finishes at once with nothing regenerated
    again: list[str] = []
    starts: list[tuple[int, int]] = []
    make_dataset(
        out, N, SMALL, workers=1, on_result=lambda r: again.append(r["id"]),
        on_start=lambda total, done: starts.append((total, done)),
    )
    assert again == []
    assert starts == [(N, N)]


def test_a_failing_building_is_recorded_and_the_others_finish(two_workers: Path, tmp_path: Path) -> None:
    out = tmp_path / "ds"
    make_dataset(out, 1, SMALL, workers=1)
    # a file where building 00001's folder must go: its final rename fails
    (out / "buildings" / "00001").write_text("in the way")
    summary = make_dataset(out, N, SMALL, workers=2)
    failures = [json.loads(line) for line in (out / "failures.jsonl").read_text().splitlines()]
    ours = [f for f in failures if f["id"] == "00001"]
    assert len(ours) == 1
    assert ours[0]["seed"] == SMALL.seed + 1 and ours[0]["type"] == dataset_specs(SMALL, N)[1].building_type
    assert ours[0]["error"] in ("NotADirectoryError", "FileExistsError", "OSError")
    expected = json.loads((two_workers / "summary.json").read_text())
    assert summary["failures"] == expected["failures"] + 1
    assert summary["buildings"] == expected["buildings"] - 1
    # the others are the same buildings as in a run without the failure
    theirs = _files(two_workers)
    ours_files = {k: v for k, v in _files(out).items() if k != "buildings/00001"}
    assert ours_files == {k: v for k, v in theirs.items() if not k.startswith("buildings/00001/")}
    # the obstacle gone, a rerun makes the building and forgets the failure
    (out / "buildings" / "00001").unlink()
    again = make_dataset(out, N, SMALL, workers=1)
    assert again["failures"] == expected["failures"]
    assert _files(out) == theirs


def test_settings_of_a_dataset_cannot_change_on_resume(two_workers: Path) -> None:
    other = DatasetSettings.parse(floors="2-2", seed=26, max_floor_area=300, validate=False)
    with pytest.raises(InvalidInputError, match="seed"):
        make_dataset(two_workers, N, other)
    # relayouts decide the buildings too: a dataset made with them (the default) does not
    # resume without them
    bare = dataclasses.replace(SMALL, relayouts=0)
    with pytest.raises(InvalidInputError, match="relayouts"):
        make_dataset(two_workers, N, bare)


def test_relayouts_reach_every_building_and_are_recorded_unless_none() -> None:
    # a dataset made without relayouts, as before the option, writes no key for them, so it
    # resumes as it was with --relayouts 0
    assert "relayouts" not in dataclasses.replace(SMALL, relayouts=0).to_dict()
    assert SMALL.to_dict()["relayouts"] == RELAYOUTS == 1
    relaid = dataclasses.replace(SMALL, relayouts=2)
    assert relaid.to_dict()["relayouts"] == 2 and relaid.job().relayouts == 2
    with pytest.raises(InvalidInputError, match="relayouts"):
        DatasetSettings.parse(relayouts=6)


@pytest.mark.slow  # about 40 s on the shared machine: Ray starts in 10-15 s
def test_ray_engine_gives_the_same_dataset(two_workers: Path, tmp_path: Path) -> None:
    pytest.importorskip("ray")
    out = tmp_path / "ray"
    make_dataset(out, N, SMALL, workers=2, engine="ray")
    assert _files(out) == _files(two_workers)
    assert _without_seconds(out / "index.jsonl") == _without_seconds(two_workers / "index.jsonl")


def test_cli_dataset_end_to_end(tmp_path: Path) -> None:
    out = tmp_path / "ds"
    args = [
        "dataset", "--n", "1", "--floors", "2-2", "--max-floor-area", "300", "--seed", "25",
        "--out", str(out), "--workers", "1", "--pictures", "--mix", "residential=1",
    ]
    result = runner.invoke(app, args)
    assert result.exit_code in (0, 1), result.output
    summary = json.loads((out / "summary.json").read_text())
    assert summary["buildings"] + summary["failures"] == 1
    assert result.exit_code == (1 if summary["failures"] else 0)
    assert set(summary["categories"]) <= {"residential"}
    assert (out / "statistics.png").read_bytes()[:4] == b"\x89PNG"
    for line in (out / "index.jsonl").read_text().splitlines():
        folder = out / "buildings" / json.loads(line)["id"]
        assert (folder / "overview.png").read_bytes()[:4] == b"\x89PNG"
        assert (folder / "scenes" / "manifest.json").is_file()
        record = json.loads((folder / "record.json").read_text())
        assert {"planning", "solving", "scenes", "writing", "validation", "pictures"} <= set(record["timings"])
        assert record["peak_memory_mb"] > 0
    # rerun: nothing to do
    again = runner.invoke(app, args)
    assert "1 of 1 buildings already finished" in again.output or summary["failures"]
    # bad input: clear errors, exit 2
    bad = runner.invoke(app, ["dataset", "--out", str(tmp_path / "x"), "--mix", "garage=1"])
    assert bad.exit_code == 2 and "unknown mix category" in bad.output
    other = runner.invoke(app, [
        "dataset", "--n", "1", "--floors", "2-2", "--max-floor-area", "300", "--seed", "26",
        "--out", str(out), "--pictures", "--mix", "residential=1",
    ])
    assert other.exit_code == 2 and "other settings" in other.output


def test_a_non_dataset_folder_is_refused(tmp_path: Path) -> None:
    (tmp_path / "notes.txt").write_text("mine")
    with pytest.raises(InvalidInputError, match="not empty"):
        make_dataset(tmp_path, 1, SMALL)
    assert sorted(os.listdir(tmp_path)) == [".lock", "notes.txt"]


def test_a_worker_killed_mid_building_fails_only_its_buildings(two_workers: Path, tmp_path: Path) -> None:
    import multiprocessing
    import signal
    import threading
    import time

    out = tmp_path / "ds"
    killed: list[int] = []

    def kill_a_worker() -> None:
        # as the OOM killer would: SIGKILL a worker once it is building something
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline and not killed:
            folder = out / "buildings"
            if folder.is_dir() and any(p.name.startswith(".tmp-") for p in folder.iterdir()):
                workers = multiprocessing.active_children()
                if workers:
                    os.kill(workers[0].pid, signal.SIGKILL)
                    killed.append(workers[0].pid)
            time.sleep(0.05)

    killer = threading.Thread(target=kill_a_worker)
    killer.start()
    summary = make_dataset(out, N, SMALL, workers=2)
    killer.join()
    assert killed
    failures = [json.loads(line) for line in (out / "failures.jsonl").read_text().splitlines()]
    assert 1 <= len(failures) <= 2  # the buildings in flight when the pool broke
    assert all("the worker died" in f["message"] for f in failures)
    assert summary["buildings"] + summary["failures"] == N
    # the rest went on in a new pool; a rerun makes the lost ones, the same as ever
    again = make_dataset(out, N, SMALL, workers=2)
    assert again["failures"] == 0
    assert _files(out) == _files(two_workers)


def test_a_job_pauses_the_cyclic_collector_and_restores_it(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The collector is off while a building is made (also when it fails) and back as it was."""
    import gc

    from mansion.dataset import job

    seen: list[bool] = []

    def build(*args: Any) -> dict[str, Any]:
        seen.append(gc.isenabled())
        raise RuntimeError("no building")

    monkeypatch.setattr(job, "_build", build)
    spec = dataset_specs(DatasetSettings(), 1)[0]
    (tmp_path / "failures").mkdir()
    for before in (True, False):
        (gc.enable if before else gc.disable)()
        try:
            record = job.run_job(spec, job.JobSettings(), tmp_path)
            assert record["failed"] and record["error"] == "RuntimeError"
            assert gc.isenabled() is before
        finally:
            gc.enable()
    assert seen == [False, False]
