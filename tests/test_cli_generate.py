"""``mansion generate`` end to end: files written, same seed same building, clear errors."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from mansion.cli import app
from mansion.models.building import Building

runner = CliRunner()


def test_generate_writes_building_floors_and_overview(tmp_path: Path) -> None:
    out = tmp_path / "out"
    args = ["generate", "a three-storey office with two elevators", "--seed", "3", "--out", str(out)]
    result = runner.invoke(app, args)
    assert result.exit_code == 0, result.output
    b = Building.load(out / "building.json")
    assert b.program.floor_count == 3
    assert sum(c.type == "elevator" for c in b.program.cores) == 2
    for k in range(3):
        assert (out / f"floor_{k}.png").read_bytes()[:4] == b"\x89PNG"
    assert (out / "overview.png").stat().st_size > 0
    assert not list(out.glob(".*.tmp"))  # atomic writes leave no temporary files

    again = tmp_path / "again"
    assert runner.invoke(app, [*args[:-1], str(again)]).exit_code == 0
    strip = lambda p: json.loads(Building.load(p).model_dump_json(exclude={"floors": {"__all__": {"layout": {"diagnostics"}}}}))  # noqa: E731
    assert strip(out / "building.json") == strip(again / "building.json")


def test_generate_options_and_footprint_file(tmp_path: Path) -> None:
    fp = tmp_path / "fp.json"
    fp.write_text(json.dumps({"polygon": [[0, 0], [20, 0], [20, 12], [0, 12]]}))
    result = runner.invoke(
        app, ["generate", "a school", "--floors", "2", "--footprint", str(fp), "--out", str(tmp_path / "o")]
    )
    assert result.exit_code == 0, result.output
    b = Building.load(tmp_path / "o" / "building.json")
    assert b.program.floor_count == 2
    assert all(f.footprint.polygon == [(0, 0), (20, 0), (20, 12), (0, 12)] for f in b.floors)


def test_generate_errors_are_one_line_exit_2(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("ANTHROPIC_API_KEY", raising=False)
    result = runner.invoke(app, ["generate", "an office", "--floors", "12", "--out", str(tmp_path)])
    assert result.exit_code == 2 and "1 to 10 floors" in result.output
    result = runner.invoke(app, ["generate", "an office", "--planner", "anthropic", "--out", str(tmp_path)])
    assert result.exit_code == 2 and "set ANTHROPIC_API_KEY" in result.output
    assert not (tmp_path / "building.json").exists()
