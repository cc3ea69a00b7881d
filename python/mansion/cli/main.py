"""``mansion generate``, ``mansion solve`` and ``mansion version``."""

from __future__ import annotations

import time
from enum import Enum
from pathlib import Path
from typing import Annotated, Optional

import typer
from rich.console import Console
from rich.markup import escape
from rich.table import Table

from mansion.building.generate import RELAYOUTS
from mansion.exceptions import MansionError

app = typer.Typer(
    name="mansion",
    help="Generate multi-floor buildings from a description, or lay out one floor (MANSION).",
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


class PlannerName(str, Enum):
    offline = "offline"
    anthropic = "anthropic"


@app.command()
def generate(
    description: Annotated[str, typer.Argument(help='What to build, e.g. "a four-storey hospital with two elevators".')],
    out: Annotated[Path, typer.Option("--out", "-o", help="Folder for building.json and the pictures.")],
    floors: Annotated[Optional[int], typer.Option(help="Number of floors (1-10); default: from the description.")] = None,
    area: Annotated[Optional[float], typer.Option(help="Gross area per floor in m2 (at most 500).")] = None,
    footprint: Annotated[Optional[Path], typer.Option(help="Footprint JSON whose outline every floor uses.")] = None,
    planner: Annotated[PlannerName, typer.Option(help="Who plans the building.")] = PlannerName.offline,
    seed: Annotated[int, typer.Option(help="Random seed; the same seed and inputs give the same building.")] = 0,
    scenes: Annotated[bool, typer.Option("--scenes/--no-scenes", help="Write AI2-THOR scenes (DIR/scenes/).")] = True,
    render: Annotated[bool, typer.Option("--render/--no-render", help="Draw the scenes (DIR/scenes/floor_<k>.png).")] = True,
    objects: Annotated[bool, typer.Option("--objects/--no-objects", help="Furnish every room of the scenes (offline object plans, reachable placement).")] = True,
    relayouts: Annotated[int, typer.Option(min=0, max=5, help="Lay a floor left with rooms below their minimum area or width out again whole up to N times, keeping the better (offline; 0 is faster).")] = RELAYOUTS,
) -> None:
    """Generate a multi-floor building: DIR/building.json, DIR/floor_<k>.png, DIR/overview.png,
    and its AI2-THOR scenes, furnished: DIR/scenes/floor_<k>.json, DIR/scenes/manifest.json and
    their pictures."""
    from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

    from mansion.building import generate_building, plot_building, plot_floors

    console = Console()
    start = time.perf_counter()
    try:
        with Progress(
            TextColumn("{task.description}"), BarColumn(), TextColumn("{task.completed}/{task.total}"),
            TimeElapsedColumn(), console=console, transient=True,
        ) as bar:
            task = bar.add_task("planning the building…", total=None)

            def progress(message: str, done: int, total: int) -> None:
                bar.update(task, description=f"solving {message}…", completed=done, total=total)

            building = generate_building(
                description, floors=floors, area=area, footprint=footprint,
                planner=planner.value, seed=seed, relayouts=relayouts, progress=progress,
            )
            bar.update(task, description="drawing…")
            json_path = building.to_json(out / "building.json")
            pictures = plot_floors(building, out)
            overview = plot_building(building, out / "overview.png")
            manifest = None
            if scenes:
                from mansion.scene import write_scenes

                bar.update(task, description="writing scenes…")
                manifest = write_scenes(building, out / "scenes", objects=objects)
                if render:
                    from mansion.scene.render import render_folder

                    bar.update(task, description="drawing scenes…")
                    render_folder(manifest.parent)
    except MansionError as exc:
        raise _fail(str(exc)) from None
    except OSError as exc:
        raise _fail(f"cannot write to {str(out)!r}: {exc.strerror or exc}") from None
    seconds = time.perf_counter() - start

    program = building.program
    table = Table(title=f"{program.building_type.replace('_', ' ')}: {program.floor_count} floors, {program.method or 'no cores'}")
    table.add_column("floor", justify="right")
    table.add_column("rooms", justify="right")
    table.add_column("area m²", justify="right")
    table.add_column("hub")
    table.add_column("notes")
    for floor in building.floors:
        notes = [f"copy of floor {floor.copy_of}"] if floor.copy_of is not None else []
        if floor.footprint.fixed_walls:
            notes.append(f"{len(floor.footprint.fixed_walls)} load-bearing walls kept")
        notes += floor.relaxations
        table.add_row(
            str(floor.index), str(len(floor.layout.rooms)),
            f"{sum(r.area for r in floor.layout.rooms):.0f}", escape(floor.graph.hub.id),
            escape("; ".join(notes)),
        )
    console.print(table)
    for request in program.requests:
        if not request.honoured:
            console.print(f"Not honoured: {escape(repr(request.phrase))}: {escape(request.reason)}")
    console.print(f"Generated in {seconds:.2f} s (palette: {escape(building.palette.name)}).")
    console.print(f"Wrote {escape(str(json_path))}, {len(pictures)} floor pictures and {escape(str(overview))}")
    if manifest is not None:
        console.print(f"Scenes: {escape(str(manifest.parent))}/floor_<k>.json and {escape(str(manifest))}")
        if objects:
            console.print(_furnishing_summary(manifest))


def _furnishing_summary(manifest_path: Path) -> str:
    """One line on the objects of a building's scenes, read back from the written floors."""
    from mansion.scene import BuildingManifest, House

    manifest = BuildingManifest.load(manifest_path)
    count = small = furnished = 0
    failed: list[str] = []
    for floor in manifest.floors:
        house = House.load(manifest_path.parent / floor.house)
        count += len(house.objects)
        small += sum(len(o.children) for o in house.objects)
        record = house.metadata.mansion.furnishing if house.metadata.mansion else None
        if record is not None:
            furnished += sum(r.status == "furnished" for r in record.rooms.values())
            failed += [f"{floor.index}:{r}" for r in record.failed]
    line = f"Objects: {count} floor objects and {small} small ones in {furnished} rooms"
    if failed:
        line += f"; {len(failed)} rooms could not be furnished ({escape(', '.join(failed))}; see metadata.mansion.furnishing)"
    return line


@app.command()
def validate(
    paths: Annotated[list[Path], typer.Argument(help="House JSONs, manifest.json files, or building folders (with manifest.json, scenes/manifest.json, MansionWorld floor_1.json, floor_2.json, ... or house JSONs).")],
    strict: Annotated[bool, typer.Option("--strict", help="Fail on warnings too.")] = False,
    json_out: Annotated[Optional[Path], typer.Option("--json", help="Write every problem (severity, rule, element, message, source) here as JSON.")] = None,
) -> None:
    """Check house JSONs or whole buildings as AI2-THOR's loader would: errors (the loader fails,
    or the robot cannot move) exit 1; warnings are quality findings (--strict fails on them)."""
    import json

    from mansion._io import atomic_write_text
    from mansion.scene.validate import errors, validate_path

    console = Console()
    problems = []
    for path in paths:
        try:
            found = validate_path(path)
        except MansionError as exc:
            raise _fail(str(exc)) from None
        problems += found
        for problem in found:
            style = "red" if problem.severity == "error" else "yellow"
            console.print(f"[{style}]{escape(str(problem))}[/{style}]", soft_wrap=True)
        if not found:
            console.print(f"{escape(str(path))}: valid")
    if json_out is not None:
        atomic_write_text(json_out, json.dumps([p.to_dict() for p in problems], indent=1) + "\n")
    n_err = len(errors(problems))
    n_warn = len(problems) - n_err
    if problems:
        console.print(f"{n_err} error(s), {n_warn} warning(s)")
    if n_err or (strict and n_warn):
        raise typer.Exit(code=1)


@app.command()
def render(
    folder: Annotated[Path, typer.Argument(help="A building's output folder (with scenes/manifest.json), a scenes folder, or a folder of house JSONs.")],
) -> None:
    """Draw every floor top-down (rooms, walls, doors, windows, objects, spawn) to PNG."""
    from mansion.scene.render import render_folder

    try:
        pictures = render_folder(folder)
    except MansionError as exc:
        raise _fail(str(exc)) from None
    except OSError as exc:
        raise _fail(f"cannot write to {str(folder)!r}: {exc.strerror or exc}") from None
    for p in pictures:
        Console().print(f"Wrote {escape(str(p))}")


@app.command()
def schema(
    out: Annotated[Optional[Path], typer.Option("--out", "-o", help="Write the JSON Schema here instead of printing it.")] = None,
) -> None:
    """The JSON Schema of the AI2-THOR house format (schema 1.0.0) as mansion writes it."""
    import json

    from mansion._io import atomic_write_text
    from mansion.scene import house_json_schema

    text = json.dumps(house_json_schema(), indent=2) + "\n"
    if out is None:
        typer.echo(text, nl=False)
    else:
        atomic_write_text(out, text)


@app.command()
def version() -> None:
    """Print the mansion version."""
    from mansion import __version__

    typer.echo(f"mansion {__version__}")
