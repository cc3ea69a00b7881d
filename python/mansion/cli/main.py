"""``mansion solve`` and ``mansion version``."""

from __future__ import annotations

import time
from enum import Enum
from pathlib import Path
from typing import Annotated, Optional

import typer
from rich.console import Console
from rich.markup import escape
from rich.table import Table

from mansion.exceptions import MansionError

app = typer.Typer(
    name="mansion",
    help="Lay out building floors from a room graph and a footprint (MANSION).",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
)


class Example(str, Enum):
    apartment = "apartment"
    office = "office"


def _fail(message: str) -> typer.Exit:
    # Rich markup would eat bracketed text such as coordinates "[1.0, 2.0]"; escape it.
    Console(stderr=True).print(f"[bold red]error:[/bold red] [red]{escape(message)}[/red]", soft_wrap=True)
    return typer.Exit(code=2)


def _fmt_error(room_area: float, target: float) -> str:
    if target <= 0:
        return "—"
    return f"{100.0 * (room_area - target) / target:+.1f}"


@app.command()
def solve(
    out: Annotated[Path, typer.Option("--out", "-o", help="Folder for layout.json and layout.png.")],
    example: Annotated[
        Optional[Example], typer.Option(help="Solve a built-in example floor.")
    ] = None,
    graph: Annotated[
        Optional[Path], typer.Option(help="Room graph JSON file (with --footprint).")
    ] = None,
    footprint: Annotated[
        Optional[Path], typer.Option(help="Footprint JSON file (with --graph).")
    ] = None,
    seed: Annotated[int, typer.Option(help="Random seed; the same seed gives the same layout.")] = 0,
    cell_size: Annotated[float, typer.Option(help="Grid cell size in metres.")] = 0.5,
) -> None:
    """Solve one floor and write DIR/layout.json and DIR/layout.png."""
    # Imported here so `mansion --help` and `mansion version` stay quick.
    from mansion.examples import EXAMPLES
    from mansion.floorplan import solve_floor
    from mansion.models import Footprint, RoomGraph
    from mansion.plot import plot_layout

    console = Console()
    try:
        if example is not None:
            if graph is not None or footprint is not None:
                raise _fail("give either --example or --graph and --footprint, not both")
            room_graph, fp = EXAMPLES[example.value]()
            name = example.value
        elif graph is not None and footprint is not None:
            room_graph, fp = RoomGraph.load(graph), Footprint.load(footprint)
            name = graph.stem
        else:
            raise _fail("give --example NAME, or both --graph FILE and --footprint FILE")

        start = time.perf_counter()
        with console.status(f"Solving {name} ({len(room_graph.nodes)} rooms)…"):
            layout = solve_floor(room_graph, fp, cell_size=cell_size, rng_seed=seed)
        seconds = time.perf_counter() - start

        json_path = layout.to_json(out / "layout.json")
        png_path = plot_layout(layout, out / "layout.png", title=f"{name} (seed {seed})")
    except MansionError as exc:
        raise _fail(str(exc)) from None
    except OSError as exc:
        raise _fail(f"cannot write to {str(out)!r}: {exc.strerror or exc}") from None

    table = Table(title=f"{name}: {len(layout.rooms)} rooms")
    table.add_column("id")
    table.add_column("type")
    table.add_column("target m²", justify="right")
    table.add_column("area m²", justify="right")
    table.add_column("error %", justify="right")
    for room in layout.rooms:
        table.add_row(
            escape(room.id),
            escape(room.room_type),
            f"{room.target_area:.1f}",
            f"{room.area:.1f}",
            _fmt_error(room.area, room.target_area),
        )
    console.print(table)
    fallback = " (Monte Carlo fallback used)" if layout.diagnostics.fallback_used else ""
    console.print(f"Solved in {seconds:.2f} s{fallback}.")
    console.print(f"Wrote {escape(str(json_path))} and {escape(str(png_path))}")


@app.command()
def version() -> None:
    """Print the mansion version."""
    from mansion import __version__

    typer.echo(f"mansion {__version__}")
