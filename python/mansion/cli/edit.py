"""``mansion edit`` (a building edited for a task, saved as a variant) and ``mansion variants``
(list, apply, revert)."""

from __future__ import annotations

from enum import Enum
from pathlib import Path
from typing import Annotated, Optional

import typer
from rich.console import Console
from rich.markup import escape

from mansion.cli.main import _fail
from mansion.exceptions import MansionError

variants_app = typer.Typer(help="Task variants of a building (mansion edit): list, show, apply, revert.", no_args_is_help=True)

BuildingArg = Annotated[Path, typer.Argument(help="A `mansion generate` output folder (or its scenes/ folder, or a manifest.json).")]


class EditPlanner(str, Enum):
    offline = "offline"
    anthropic = "anthropic"


_MARK = {True: "[green]✓[/green]", False: "[red]✗[/red]", None: " "}


def edit(
    building: BuildingArg,
    request: Annotated[Optional[str], typer.Argument(help='The task in plain words ("I need a task where ..."), with --planner anthropic.')] = None,
    spec: Annotated[Optional[Path], typer.Option("--spec", help="The structured task (JSON: text, start, fetch, deliver) for the offline controller.")] = None,
    name: Annotated[Optional[str], typer.Option("--name", help="Variant name (default: from the task's words).")] = None,
    planner: Annotated[EditPlanner, typer.Option(help="Who checks and provisions: the offline controller or Claude.")] = EditPlanner.offline,
    settle: Annotated[bool, typer.Option("--settle", help="Let AI2-THOR settle the placed objects and write their poses back (needs the simulator: the ai2thor extra).")] = False,
    semantic: Annotated[bool, typer.Option("--semantic", help="SearchAssets ranks by meaning with an embedding model (the semantic extra; $MANSION_EMBEDDING_MODEL picks the model).")] = False,
) -> None:
    """Edit a building for a task: check each precondition, provision what is missing, confirm
    the oracle agent can do the task, and save the variant under BUILDING/variants/NAME/."""
    from mansion.edit import EditSpec, edit_building

    console = Console(soft_wrap=True)
    try:
        task = EditSpec.load(spec) if spec is not None else None
        if task is None and request is None:
            raise _fail("give the task: --spec FILE (offline) or a request in words with --planner anthropic")
        if planner is EditPlanner.offline and task is None:
            raise _fail("a request in words needs --planner anthropic; the offline controller takes --spec FILE")
        controller = None
        if settle:
            from mansion.sim.thor import thor_controller

            controller = thor_controller()
        embedder = None
        if semantic:
            from mansion.edit.asset_search import sentence_embedder

            embedder = sentence_embedder()
        result = edit_building(building, task, text=request, name=name, planner=planner.value, settle_with=controller,
                               embedder=embedder)
    except MansionError as exc:
        raise _fail(str(exc)) from None
    except OSError as exc:
        raise _fail(f"cannot write the variant: {exc.strerror or exc}") from None
    _print_log(console, [(line.kind, line.text, line.ok) for line in result.log.lines])
    if not result.ok:
        Console(stderr=True, soft_wrap=True).print(f"[bold red]cannot make the task executable:[/bold red] {escape(result.failed or '')}")
        raise typer.Exit(code=1)
    variant = result.variant or Path()
    console.print(f"variant: {escape(str(variant))} ({len(result.edits)} edits; "
                  f"the task: {escape(str(variant / 'task.json'))})")


@variants_app.command("list")
def list_(building: BuildingArg) -> None:
    """The building's task variants: name, edits, task text."""
    from mansion.edit.variants import applied, list_variants

    try:
        found = list_variants(building)
        now = applied(building)
    except MansionError as exc:
        raise _fail(str(exc)) from None
    console = Console(soft_wrap=True)
    if not found:
        console.print("no variants")
    for v in found:
        mark = " (applied)" if v.name == now else ""
        console.print(f"[bold]{escape(v.name)}[/bold]{mark}: {escape(v.summary())} — {escape(v.text)}")


@variants_app.command("show")
def show(building: BuildingArg, name: Annotated[str, typer.Argument(help="The variant.")]) -> None:
    """A variant's task, its edits per floor and the log of checks and edits it was made with."""
    from mansion.edit.variants import load_variant

    try:
        v = load_variant(building, name)
    except MansionError as exc:
        raise _fail(str(exc)) from None
    console = Console(soft_wrap=True)
    console.print(f"[bold]{escape(v.name)}[/bold] ({escape(v.planner)}): {escape(v.text)}")
    for p in v.patch:
        console.print(f"floor {p.floor} ({escape(p.house)}): {len(p.added)} added, {len(p.moved)} moved, "
                      f"{len(p.removed)} removed, {len(p.changed)} changed")
    _print_log(console, [(line["kind"], line["text"], line["ok"]) for line in v.log])


def _print_log(console: Console, lines: list[tuple[str, str, bool | None]]) -> None:
    for kind, raw, ok in lines:
        text = escape(raw)
        if kind == "precondition":
            console.print(f"[bold]precondition[/bold]: {text}")
        elif kind == "check":
            console.print(f"  {_MARK[ok]} {text}")
        elif kind == "edit":
            console.print(f"  [cyan]+[/cyan] {text}")


@variants_app.command("apply")
def apply(building: BuildingArg, name: Annotated[str, typer.Argument(help="The variant.")]) -> None:
    """Write the variant's edited house JSONs over the building's (revert restores them)."""
    from mansion.edit.variants import apply_variant

    try:
        written = apply_variant(building, name)
    except MansionError as exc:
        raise _fail(str(exc)) from None
    Console(soft_wrap=True).print(f"applied {escape(name)}: wrote {', '.join(escape(str(p)) for p in written) or 'nothing'}")


@variants_app.command("revert")
def revert(building: BuildingArg) -> None:
    """Restore the building's own house JSONs, byte for byte, after apply."""
    from mansion.edit.variants import revert_variant

    try:
        name, written = revert_variant(building)
    except MansionError as exc:
        raise _fail(str(exc)) from None
    Console(soft_wrap=True).print(f"reverted {escape(name)}: restored {', '.join(escape(str(p)) for p in written)}")
