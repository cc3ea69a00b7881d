"""``mansion eval floorplan`` and ``mansion tune-weights``: the solver on real plans (T2D)."""

from __future__ import annotations

from enum import Enum
from pathlib import Path
from typing import Annotated, Optional

import typer
from rich.console import Console
from rich.markup import escape
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

from mansion.cli.main import _fail
from mansion.building.generate import RELAYOUTS
from mansion.exceptions import MansionError

eval_app = typer.Typer(help="Measure the solver.", no_args_is_help=True)

#: Rooms below their minimums ``mansion eval realism`` names on the terminal (the JSON has all).
UNDERSIZED_SHOWN = 20


class ModeChoice(str, Enum):
    hierarchical = "hierarchical"
    flat = "flat"


class SeedChoice(str, Enum):
    ground_truth = "ground-truth"
    anthropic = "anthropic"
    text = "text"


def _progress(console: Console) -> Progress:
    return Progress(
        TextColumn("[bold]{task.description}"),
        BarColumn(),
        MofNCompleteColumn(),
        TimeElapsedColumn(),
        console=console,
        transient=True,
    )


DataOption = Annotated[
    Path, typer.Option("--data", help="Folder of T2D plans (DIR/plans/<id>.json).")
]
WeightsOption = Annotated[
    Optional[Path], typer.Option("--weights", help="Energy weights JSON (from tune-weights).")
]


@eval_app.command("floorplan")
def eval_floorplan(
    data: DataOption,
    mode: Annotated[ModeChoice, typer.Option(help="Cut rounds from the hub, or all rooms at once.")] = ModeChoice.hierarchical,
    limit: Annotated[Optional[int], typer.Option(help="Evaluate the first N plans only.")] = None,
    json_out: Annotated[Optional[Path], typer.Option("--json", help="Write the scores as JSON.")] = None,
    gallery: Annotated[
        Optional[Path], typer.Option(help="Write PNGs of the best and worst plans here.")
    ] = None,
    weights: WeightsOption = None,
    seed: Annotated[int, typer.Option(help="Solver random seed.")] = 0,
    workers: Annotated[Optional[int], typer.Option(help="Processes (default: all cores).")] = None,
    planner: Annotated[
        SeedChoice,
        typer.Option(
            help="Seeds: the ground-truth centroids (MA protocol), Claude reading "
            "DIR/text/<id>.txt (needs ANTHROPIC_API_KEY), or the same text read offline (text)."
        ),
    ] = SeedChoice.ground_truth,
) -> None:
    """Reproduce real floor plans under the paper's MA protocol and print micro/macro IoU."""
    from mansion.eval.floorplan import evaluate_floorplans, write_gallery
    from mansion.floorplan import EnergyWeights

    console = Console()
    try:
        w = EnergyWeights.load(weights) if weights is not None else None
        with _progress(console) as bar:
            task = bar.add_task(f"{mode.value} solve", total=None)
            report = evaluate_floorplans(
                data,
                mode=mode.value,
                limit=limit,
                weights=w,
                rng_seed=seed,
                workers=workers,
                progress=lambda done, total: bar.update(task, completed=done, total=total),
                seeds={"ground-truth": "ground_truth"}.get(planner.value, planner.value),  # type: ignore[arg-type]
            )
        if json_out is not None:
            report.save(json_out)
        pictures = write_gallery(data, report, gallery) if gallery is not None else []
    except MansionError as exc:
        raise _fail(str(exc)) from None
    except OSError as exc:
        raise _fail(f"cannot write output: {exc.strerror or exc}") from None

    console.print(
        f"[bold]{report.mode}[/bold]: micro-IoU [bold]{report.micro:.2f}[/bold], "
        f"macro-IoU [bold]{report.macro:.2f}[/bold] over {report.plans} plans; "
        f"{report.failures} failures, {report.fallbacks} used the fallback; "
        f"{report.seconds:.1f} s"
    )
    if report.plans > 1 and all(p.id.isdigit() for p in report.per_plan):
        for name, rest in (("odd", 1), ("even", 0)):
            micro, macro, n = report.subset(lambda pid, r=rest: int(pid) % 2 == r)
            if n:
                console.print(f"  {name} ids: micro {micro:.2f}, macro {macro:.2f} ({n} plans)")
    for failure in (p for p in report.per_plan if p.failed):
        console.print(f"  failed {escape(failure.id)}: {escape(failure.error or '')}", soft_wrap=True)
    if json_out is not None:
        console.print(f"Wrote {escape(str(json_out))}")
    if pictures:
        console.print(f"Wrote {len(pictures)} pictures to {escape(str(gallery))}")


def tune_weights(
    data: DataOption,
    out: Annotated[Path, typer.Option("--out", "-o", help="Where to write the best weights (JSON).")] = Path("weights.json"),
    samples: Annotated[int, typer.Option(help="Random weight vectors to try.")] = 40,
    refine: Annotated[int, typer.Option(help="Local perturbations of the best, after the samples.")] = 20,
    seed: Annotated[int, typer.Option(help="Seed of the search.")] = 0,
    mode: Annotated[ModeChoice, typer.Option(help="Solver mode to tune for.")] = ModeChoice.hierarchical,
    report: Annotated[Optional[Path], typer.Option(help="Write every trial as JSON.")] = None,
    workers: Annotated[Optional[int], typer.Option(help="Processes (default: all cores).")] = None,
) -> None:
    """Random search of the energy weights on the simplex (even plan ids; odd ids held out)."""
    from mansion.eval.tune import TuneTrial, tune_weights as run

    console = Console()

    def show(k: int, trial: TuneTrial, best: TuneTrial) -> None:
        w = trial.weights
        mark = " [green]best[/green]" if trial is best else ""
        console.print(
            f"{k:3d}  ratio {w.ratio:6.2f} seed {w.seed:6.2f} drift {w.drift:6.2f} "
            f"wall {w.wall:6.2f} corner {w.corner:6.2f}  →  micro {trial.micro:.2f} "
            f"macro {trial.macro:.2f} fail {trial.failures}{mark}"
        )

    try:
        result = run(data, samples=samples, refine=refine, seed=seed, mode=mode.value, workers=workers, on_trial=show)
        result.best.save(out)
        if report is not None:
            result.save(report)
    except MansionError as exc:
        raise _fail(str(exc)) from None
    except OSError as exc:
        raise _fail(f"cannot write output: {exc.strerror or exc}") from None
    console.print(
        f"best on even ids: micro {result.even[0]:.2f}, macro {result.even[1]:.2f} ({result.even[2]} plans)\n"
        f"held-out odd ids: micro {result.odd[0]:.2f}, macro {result.odd[1]:.2f} ({result.odd[2]} plans)\n"
        f"all plans:        micro {result.all[0]:.2f}, macro {result.all[1]:.2f} ({result.all[2]} plans), "
        f"{result.failures} failures"
    )
    console.print(f"Wrote {escape(str(out))}")


class ObjectPlannerChoice(str, Enum):
    offline = "offline"
    anthropic = "anthropic"


@eval_app.command("placement")
def eval_placement(
    runs: Annotated[int, typer.Option(min=1, help="Runs (seeds) per room.")] = 10,
    json_out: Annotated[Optional[Path], typer.Option("--json", help="Write the figures as JSON.")] = None,
    seed: Annotated[int, typer.Option(help="First seed; run k uses seed + k.")] = 0,
    planner: Annotated[
        ObjectPlannerChoice, typer.Option(help="Object plans: offline rules, or Claude (needs ANTHROPIC_API_KEY).")
    ] = ObjectPlannerChoice.offline,
) -> None:
    """The paper's object-placement benchmark on its four rooms: mean floor and small objects,
    #OB, #CN, #Rch (%) and seconds per room."""
    import json

    from rich.table import Table

    from mansion._io import atomic_write_text
    from mansion.eval.placement import PAPER, ROOMS, evaluate_placement

    console = Console()
    try:
        object_planner = None
        if planner is ObjectPlannerChoice.anthropic:
            from mansion.agents.llm import LLMClient
            from mansion.placement.llm import LLMObjectPlanner

            object_planner = LLMObjectPlanner(LLMClient())
        rooms: dict[str, dict[str, float]] = {}
        with _progress(console) as bar:
            task = bar.add_task("placement", total=len(ROOMS))
            for name in ROOMS:
                rooms.update(evaluate_placement(runs=runs, seed=seed, rooms=[name], planner=object_planner))
                bar.advance(task)
    except MansionError as exc:
        raise _fail(str(exc)) from exc
    table = Table(title=f"Object placement, {runs} runs per room (paper: floor + small)")
    for col in ("room", "floor obj", "small obj", "#OB", "#CN", "#Rch %", "seconds", "paper"):
        table.add_column(col, justify="left" if col == "room" else "right")
    for name, r in rooms.items():
        pf, ps = PAPER[name]
        table.add_row(
            name, f"{r['floor_obj']:.1f}", f"{r['small_obj']:.1f}", f"{r['ob']:.1f}", f"{r['cn']:.1f}",
            f"{r['rch']:.1f}", f"{r['seconds']:.3f}", f"{pf} + {ps}",
        )
    console.print(table)
    if json_out is not None:
        atomic_write_text(json_out, json.dumps({"rooms": rooms}, indent=2) + "\n")
        console.print(f"Wrote {escape(str(json_out))}")


@eval_app.command("realism")
def eval_realism(
    buildings: Annotated[
        Optional[list[Path]], typer.Argument(help="Building folders (with building.json) or files.")
    ] = None,
    generate: Annotated[
        int, typer.Option("--generate", min=0, help="Also generate N offline buildings (the benchmark's seeds).")
    ] = 0,
    seed: Annotated[int, typer.Option(help="First benchmark seed of --generate.")] = 0,
    reference: Annotated[
        Optional[Path], typer.Option("--reference", help="T2D plans folder to measure beside (DIR/plans/<id>.json).")
    ] = None,
    json_out: Annotated[Optional[Path], typer.Option("--json", help="Write the figures as JSON.")] = None,
    narrow: Annotated[
        float, typer.Option(min=0.1, help="Sliver width and usable square side, metres (parts this wide or narrower are slivers).")
    ] = 1.0,
    relayouts: Annotated[
        int, typer.Option(min=0, max=5, help="--generate: relayouts per floor (see mansion generate --relayouts).")
    ] = RELAYOUTS,
) -> None:
    """Room realism: slivers, elongated and unusable rooms, rooms below their type's minimum area
    or width, corridor widths and rooms without a corridor door, per building type and overall,
    beside real plans' figures."""
    from rich.table import Table

    from mansion.eval.realism import Figures, evaluate_realism

    console = Console()
    # The table has ten columns: keep it readable when the output is piped (80 columns).
    console = Console(width=max(console.width, 132))
    try:
        with _progress(console) as bar:
            task = bar.add_task("buildings", total=(len(buildings or []) + generate) or None)
            report = evaluate_realism(
                buildings or [], generate=generate, seed=seed, reference=reference, narrow=narrow,
                relayouts=relayouts, progress=lambda done: bar.update(task, completed=done),
            )
        if json_out is not None:
            report.save(json_out)
    except MansionError as exc:
        raise _fail(str(exc)) from None
    except OSError as exc:
        raise _fail(f"cannot write output: {exc.strerror or exc}") from None

    table = Table(
        title=f"Room realism (% of rooms; sliver and square: {narrow:g} m; elongated: of "
        "non-circulation rooms; no corridor door: of rooms that need one)"
    )
    for col in (
        "group", "bldgs", "rooms", "sliver", "elongated", "no 1 m sq", "< min area", "< min width",
        "no corr. door", "corridor m med/min",
    ):
        table.add_column(col, justify="left" if col == "group" else "right")

    def row(name: str, f: Figures) -> None:
        c = f.corridors
        widths = f"{c.median:.2f} / {c.min:.2f}" if c.count else "-"
        table.add_row(
            name, str(f.buildings), str(f.rooms), f"{f.sliver_pct:.1f}", f"{f.elongated_pct:.1f}",
            f"{f.no_square_pct:.1f}", f"{f.below_area_pct:.1f}", f"{f.below_width_pct:.1f}",
            f"{f.no_corridor_door_pct:.1f}", widths,
        )

    for kind, figures in report.by_type.items():
        row(kind, figures)
    row("[bold]overall[/bold]", report.overall)
    if report.reference is not None:
        row(f"[bold]reference[/bold] ({report.reference_plans} plans)", report.reference)
    console.print(table)
    narrow = ", ".join(f"{k} {v}" for k, v in list(report.overall.sliver_types.items())[:10])
    if narrow:
        console.print(f"Sliver rooms by type: {escape(narrow)}", soft_wrap=True)
    small = report.overall.undersized_rooms
    if small:
        console.print(f"Rooms below their minimum area or width ({len(small)}):")
        for line in small[:UNDERSIZED_SHOWN]:
            console.print(f"  {escape(line)}", soft_wrap=True)
        if len(small) > UNDERSIZED_SHOWN:
            console.print(f"  … and {len(small) - UNDERSIZED_SHOWN} more (--json lists them all)")
    for failure in report.failures:
        console.print(f"  failed {escape(failure)}", soft_wrap=True)
    if json_out is not None:
        console.print(f"Wrote {escape(str(json_out))}")
