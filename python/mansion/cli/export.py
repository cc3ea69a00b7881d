"""``mansion export``: a generated building as one glTF or USD file, and a 3D picture of it."""

from __future__ import annotations

import time
from pathlib import Path
from typing import Annotated, Optional

import typer
from rich.console import Console
from rich.markup import escape

from mansion.cli.main import _fail
from mansion.exceptions import MansionError
from mansion.export.formats import FORMATS


def export(
    building: Annotated[Path, typer.Argument(help="A building folder written by `mansion generate` (with scenes/manifest.json), its manifest, one house JSON, or a MansionWorld folder (floor_1.json, ...).")],
    out: Annotated[Optional[Path], typer.Option("--out", "-o", help="The file to write (.glb for gltf; .usd, .usda or .usdc for usd), or the folder for mansionworld.")] = None,
    fmt: Annotated[str, typer.Option("--format", "-f", help=f"One of: {', '.join(sorted(FORMATS))}.")] = "gltf",
    preview: Annotated[Optional[Path], typer.Option("--preview", help="Also draw the building in 3D (exploded floors) to this PNG.")] = None,
) -> None:
    """Export a building (every floor stacked at its elevation, with stairs, elevators, doors,
    windows and furniture) for Blender (gltf) or Isaac Sim (usd), or into the MANSION authors'
    layout for their MansionGym (mansionworld: a folder of floor_1.json, floor_2.json, ...)."""
    from mansion.export import building_model, export_format

    if out is None and preview is None:
        raise _fail("give --out FILE (and --format), --preview PNG, or both")
    console = Console()
    start = time.perf_counter()
    try:
        writer = export_format(fmt, out) if out is not None else None
        written = []
        if writer is not None and writer.folder is not None and out is not None:
            written.append(writer.folder(building, out))
            if preview is None:
                floors = sum(1 for _ in out.glob("floor_*.json"))
                console.print(f"Exported {floors} floors in {time.perf_counter() - start:.2f} s.")
                console.print(f"Wrote {escape(str(out))}")
                return
        model = building_model(building)
        if writer is not None and writer.write is not None and out is not None:
            written.append(writer.write(model, out))
        if preview is not None:
            from mansion.export.preview import render_preview

            written.append(render_preview(model, preview))
    except ModuleNotFoundError as exc:
        raise _fail(f"mansion export needs the {exc.name!r} package: pip install 'mansion[export]'") from None
    except MansionError as exc:
        raise _fail(str(exc)) from None
    except OSError as exc:
        raise _fail(f"cannot write {str(out or preview)!r}: {exc.strerror or exc}") from None
    nodes = sum(1 for _ in model.root.walk())
    console.print(f"Exported {len(model.root.children)} floors ({nodes} nodes) in {time.perf_counter() - start:.2f} s.")
    for path in written:
        console.print(f"Wrote {escape(str(path))}")
