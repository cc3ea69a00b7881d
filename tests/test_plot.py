"""plot_layout on a hand-made layout (no solver needed)."""

from __future__ import annotations

from pathlib import Path

import pytest

from mansion import FloorLayout, InvalidInputError, plot_layout
from mansion.plot import room_label

from test_models import LAYOUT_JSON


def _layout_with_courtyard() -> FloorLayout:
    data = {**LAYOUT_JSON, "rooms": [dict(r) for r in LAYOUT_JSON["rooms"]]}
    office = data["rooms"][1]
    office["polygon"] = [[2.0, 0.0], [8.0, 0.0], [8.0, 6.0], [2.0, 6.0]]
    office["holes"] = [[[4.0, 2.0], [6.0, 2.0], [6.0, 4.0], [4.0, 4.0]]]
    office["area"] = 32.0
    return FloorLayout.model_validate(data)


@pytest.mark.parametrize("suffix", [".png", ".svg"])
def test_plot_writes_the_file_atomically(tmp_path: Path, suffix: str) -> None:
    path = plot_layout(_layout_with_courtyard(), tmp_path / f"plan{suffix}", title="test")
    data = path.read_bytes()
    if suffix == ".png":
        assert data.startswith(b"\x89PNG")
    else:
        text = data.decode("utf-8")
        assert "<svg" in text
        assert "office" in text and "32.0 m²" in text
    assert [p.name for p in tmp_path.iterdir()] == [f"plan{suffix}"]


def test_plot_rejects_unknown_formats(tmp_path: Path) -> None:
    with pytest.raises(InvalidInputError, match=r"\.png or \.svg"):
        plot_layout(_layout_with_courtyard(), tmp_path / "plan.jpg")
    assert list(tmp_path.iterdir()) == []


def test_room_label() -> None:
    layout = FloorLayout.model_validate(LAYOUT_JSON)
    assert room_label(layout.room("hall")) == "hall\nentrance_hall\n3.0 m²"
    assert room_label(layout.room("office")) == "office\n4.0 m²"
