"""``mansion dataset``: MansionWorld-scale datasets on this machine or a Ray cluster."""

from __future__ import annotations

import time
from enum import Enum
from pathlib import Path
from typing import Annotated, Any, Optional

import typer
from rich.console import Console
from rich.markup import escape

from mansion.cli.main import _fail
from mansion.building.generate import RELAYOUTS
from mansion.exceptions import MansionError


class EngineName(str, Enum):
    local = "local"
    ray = "ray"


def dataset(
    out: Annotated[Path, typer.Option("--out", "-o", help="Dataset folder (buildings/, index.jsonl, summary.json, statistics.png).")],
    n: Annotated[int, typer.Option("--n", help="Number of buildings.")] = 1000,
    mix: Annotated[str, typer.Option(help="Shares of residential, office and public buildings.")] = "residential=0.5,office=0.3,public=0.2",
    floors: Annotated[str, typer.Option(help="Floor counts, LOW-HIGH (or N).")] = "2-10",
    max_floor_area: Annotated[float, typer.Option(help="Largest gross area of a floor, m2.")] = 500.0,
    seed: Annotated[int, typer.Option(help="Building i is generated from seed + i.")] = 0,
    workers: Annotated[int, typer.Option(help="Worker processes (local), or CPUs of a Ray started here.")] = 2,
    engine: Annotated[EngineName, typer.Option(help="local: worker processes; ray: Ray tasks (pip install 'mansion\\[ray]').")] = EngineName.local,
    address: Annotated[Optional[str], typer.Option(help="Ray cluster address (e.g. auto or ray://host:10001); default: start Ray here.")] = None,
    pictures: Annotated[bool, typer.Option("--pictures/--no-pictures", help="Draw each building's floor plans (DIR/buildings/<id>/overview.png; `mansion render` draws the scenes).")] = False,
    validate: Annotated[bool, typer.Option("--validate/--no-validate", help="Validate every building's scenes as AI2-THOR's loader would; errors fail the building.")] = True,
    relayouts: Annotated[int, typer.Option(min=0, max=5, help="Lay a floor left with rooms below their minimum area or width out again whole up to N times (see mansion generate --relayouts).")] = RELAYOUTS,
) -> None:
    """Generate a dataset of N buildings (building i: seed S+i, type drawn from the mix) into
    DIR/buildings/<id>/, with DIR/index.jsonl, failures.jsonl, summary.json and statistics.png.
    Rerunning the command resumes: finished buildings are kept, the rest are generated."""
    from rich.progress import (
        BarColumn,
        MofNCompleteColumn,
        Progress,
        TextColumn,
        TimeElapsedColumn,
        TimeRemainingColumn,
    )

    from mansion.dataset import DatasetSettings, make_dataset

    console = Console()
    try:
        settings = DatasetSettings.parse(
            mix=mix, floors=floors, max_floor_area=max_floor_area, seed=seed, pictures=pictures,
            validate=validate, relayouts=relayouts,
        )
    except MansionError as exc:
        raise _fail(str(exc)) from None
    failures: list[dict[str, Any]] = []
    made: list[float] = []  # the start, then when each building of this run finished
    with Progress(
        TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
        TextColumn("[red]{task.fields[failed]} failed[/red]"),
        TextColumn("{task.fields[rate]}"), TimeElapsedColumn(), TextColumn("ETA"),
        TimeRemainingColumn(), console=console,
    ) as bar:
        task = bar.add_task("buildings", total=n, failed=0, rate="")

        def started(total: int, done: int) -> None:
            made.append(time.perf_counter())
            bar.reset(task, total=total, completed=done, failed=0, rate="")
            if done:
                console.print(f"{done} of {total} buildings already finished in {escape(str(out))}")

        def finished(record: dict[str, Any]) -> None:
            if record.get("failed"):
                failures.append(record)
                console.print(
                    f"[red]building {escape(record['id'])} ({escape(record['type'])}, seed "
                    f"{record['seed']}) failed: {escape(record['error'])}: {escape(record['message'][:200])}[/red]",
                    soft_wrap=True,
                )
            made.append(time.perf_counter())
            # the rate of this run: buildings finished found at the start do not count
            minutes = (made[-1] - made[0]) / 60.0
            rate = f"{(len(made) - 1) / minutes:.1f}/min" if minutes > 0 else ""
            bar.update(task, advance=1, failed=len(failures), rate=rate)

        try:
            summary = make_dataset(
                out, n, settings, workers=workers, engine=engine.value, address=address,
                on_start=started, on_result=finished,
            )
        except MansionError as exc:
            raise _fail(str(exc)) from None
        except OSError as exc:
            raise _fail(f"cannot write to {str(out)!r}: {exc.strerror or exc}") from None
        except KeyboardInterrupt:
            console.print("interrupted: finished buildings are kept; rerun the command to go on")
            raise typer.Exit(code=130) from None
    console.print(
        f"{summary['buildings']} buildings ({summary['total_floors']} floors, {summary['rooms']} rooms, "
        f"{summary['objects']} objects) in {escape(str(out))}; {summary['failures']} failed"
        + (f" (see {escape(str(out / 'failures.jsonl'))})" if summary["failures"] else "")
    )
    if summary["failures"]:
        raise typer.Exit(code=1)
