"""The `mansion` command line, run in-process with typer's CliRunner."""

from __future__ import annotations

import json
from pathlib import Path

from typer.testing import CliRunner

from mansion import FloorLayout
from mansion.cli import app
from mansion.examples import example_apartment

runner = CliRunner()


def test_solve_example_apartment(tmp_path: Path) -> None:
    out = tmp_path / "out"
    result = runner.invoke(app, ["solve", "--example", "apartment", "--out", str(out)])
    assert result.exit_code == 0, result.output
    assert (out / "layout.png").read_bytes().startswith(b"\x89PNG")
    layout = FloorLayout.load(out / "layout.json")
    graph, _ = example_apartment()
    room_ids = {room.id for room in layout.rooms}
    assert {node.id for node in graph.nodes} <= room_ids
    assert "living" in result.output and "Solved in" in result.output


def _write_inputs(tmp_path: Path, graph: object) -> tuple[Path, Path]:
    _, footprint = example_apartment()
    graph_path = tmp_path / "graph.json"
    footprint_path = tmp_path / "footprint.json"
    graph_path.write_text(graph if isinstance(graph, str) else json.dumps(graph))
    footprint_path.write_text(footprint.model_dump_json())
    return graph_path, footprint_path


def _solve_files(tmp_path: Path, graph: object) -> tuple[int, str]:
    graph_path, footprint_path = _write_inputs(tmp_path, graph)
    result = runner.invoke(
        app,
        ["solve", "--graph", str(graph_path), "--footprint", str(footprint_path), "--out", str(tmp_path / "out")],
    )
    return result.exit_code, result.output


def test_bad_graph_file_exits_2_with_a_message(tmp_path: Path) -> None:
    graph, _ = example_apartment()
    data = json.loads(graph.model_dump_json())
    data["edges"].append({"source": "living", "target": "wine_cellar"})
    code, output = _solve_files(tmp_path, data)
    assert code == 2
    assert "error" in output and "wine_cellar" in output
    assert "Traceback" not in output
    assert not (tmp_path / "out").exists()


def test_graph_file_that_is_not_json_exits_2(tmp_path: Path) -> None:
    code, output = _solve_files(tmp_path, "{nodes: [")
    assert code == 2
    assert "not valid JSON" in output


def test_missing_inputs_exit_2(tmp_path: Path) -> None:
    result = runner.invoke(app, ["solve", "--out", str(tmp_path)])
    assert result.exit_code == 2
    assert "--example" in result.output
    result = runner.invoke(app, ["solve", "--graph", str(tmp_path / "nope.json"), "--footprint", str(tmp_path / "nope2.json"), "--out", str(tmp_path)])
    assert result.exit_code == 2
    assert "nope.json" in result.output


def test_version() -> None:
    result = runner.invoke(app, ["version"])
    assert result.exit_code == 0
    assert result.output.startswith("mansion ")
