"""``mansion tasks sample``, ``mansion eval tasks`` and ``mansion eval setting``: tasks in a
building and agents scored on them."""

from __future__ import annotations

import tempfile
from enum import Enum
from pathlib import Path
from typing import Annotated, Any, Optional

import typer
from rich.console import Console
from rich.markup import escape
from rich.table import Table

from mansion.cli.evaluate import eval_app
from mansion.cli.main import _fail
from mansion.exceptions import MansionError

tasks_app = typer.Typer(help="Tasks in a building (the paper's cross-floor retrieval and delivery).", no_args_is_help=True)

BuildingArg = Annotated[Path, typer.Argument(help="A `mansion generate` output folder (or its scenes/ folder, or a manifest.json), or a MansionWorld folder (floor_1.json, ...).")]


@tasks_app.command("sample")
def sample(
    building: BuildingArg,
    out: Annotated[Path, typer.Option("--out", "-o", help="Write the tasks here (JSON).")],
    n: Annotated[int, typer.Option("--n", help="How many tasks.")] = 10,
    seed: Annotated[int, typer.Option(help="Random seed; the same seed gives the same tasks.")] = 0,
) -> None:
    """Sample valid tasks (every other one crossing floors in a building of several)."""
    from mansion.sim.tasks import TaskSet, sample_tasks

    try:
        report = sample_tasks(building, n, seed)
        path = TaskSet(building=report.tasks[0].building if report.tasks else "", seed=seed, tasks=report.tasks,
                       candidates=report.candidates, rejected=dict(report.rejected),
                       excluded=dict(report.excluded)).to_json(out)
    except MansionError as exc:
        raise _fail(str(exc)) from None
    except OSError as exc:
        raise _fail(f"cannot write {str(out)!r}: {exc.strerror or exc}") from None
    console = Console()
    crossing = sum(t.crosses_floors for t in report.tasks)
    console.print(f"{len(report.tasks)} tasks ({crossing} crossing floors) from {report.candidates} candidates; "
                  f"wrote {escape(str(path))}")
    for why, k in report.rejected.most_common():
        console.print(f"  rejected {k:4d}: {escape(why)}")
    for why, k in report.excluded.most_common():
        console.print(f"  objects not offered {k:4d}: {escape(why)}")


AgentOption = Annotated[str, typer.Option("--agent", help="oracle, baseline, or module:callable (a factory (env, task) -> policy).")]


def _run(building: Path, tasks: list[Any], agent: str, pictures: Path | None) -> Any:
    from mansion.sim.agents import load_agent
    from mansion.sim.env import BuildingEnv
    from mansion.sim.evaluate import run_task, score

    factory = load_agent(agent)
    env = BuildingEnv(building)
    outcomes = []
    for task in tasks:
        outcomes.append(run_task(env, task, factory))
        if pictures is not None:
            from mansion.sim.pictures import draw_task

            draw_task(env, task, pictures / f"{task.id}.png")
    return score(outcomes, agent)


def _table(title: str, rows: list[tuple[str, Any]]) -> Table:
    table = Table(title=title)
    for col in ("setting", "tasks", "success % (retrieved, navigated)", "crossing floors", "mean path m", "mean steps"):
        table.add_column(col)
    for name, s in rows:
        table.add_row(escape(name), str(s.tasks), f"{s.success:.0f} ({s.retrieved:.0f}, {s.navigated:.0f})",
                      str(s.cross_floor), f"{s.mean_path_length:.1f}", f"{s.mean_steps:.1f}")
    return table


@eval_app.command("tasks")
def eval_tasks(
    building: BuildingArg,
    agent: AgentOption = "oracle",
    tasks: Annotated[Optional[Path], typer.Option("--tasks", help="Tasks file (mansion tasks sample).")] = None,
    n: Annotated[Optional[int], typer.Option("--n", help="Sample this many tasks instead of --tasks.")] = None,
    seed: Annotated[int, typer.Option(help="Seed for --n.")] = 0,
    json_out: Annotated[Optional[Path], typer.Option("--json", help="Write the scores as JSON.")] = None,
    pictures: Annotated[Optional[Path], typer.Option(help="Draw each task's walk across floors here (PNG).")] = None,
) -> None:
    """Run an agent on a building's tasks: success % with progress (object retrieved %,
    destination reached %), mean path length and steps."""
    from mansion.sim.tasks import load_tasks, sample_tasks

    try:
        if tasks is not None and n is not None:
            raise _fail("give --tasks FILE or --n N, not both")
        task_list = load_tasks(tasks) if tasks is not None else sample_tasks(building, 10 if n is None else n, seed).tasks
        scores = _run(building, task_list, agent, pictures)
        if json_out is not None:
            scores.to_json(json_out)
    except MansionError as exc:
        raise _fail(str(exc)) from None
    except OSError as exc:
        raise _fail(f"cannot write: {exc.strerror or exc}") from None
    Console().print(_table(f"{agent} on {building}", [(str(building.name), scores)]))


class SettingName(str, Enum):
    single = "single-floor"
    double = "two-floor"
    four = "four-floor"
    all = "all"


@eval_app.command("setting")
def eval_setting(
    setting: Annotated[SettingName, typer.Argument(help="The paper's setting (Table 'Task Settings and Prompts').")],
    agent: AgentOption = "oracle",
    n: Annotated[int, typer.Option("--n", help="Tasks per setting (the paper ran 10 trials).")] = 10,
    out: Annotated[Optional[Path], typer.Option("--out", help="Keep the generated buildings here.")] = None,
    json_out: Annotated[Optional[Path], typer.Option("--json", help="Write the scores as JSON (one entry per setting).")] = None,
) -> None:
    """One of the paper's three settings end to end: generate its building offline, sample its
    tasks, run the agent."""
    import json

    from mansion._io import atomic_write_text
    from mansion.sim.settings import run_setting
    from mansion.sim.tasks import SETTINGS

    names = list(SETTINGS) if setting is SettingName.all else [setting.value]
    rows = []
    try:
        with tempfile.TemporaryDirectory() as tmp:
            root = out if out is not None else Path(tmp)
            for name in names:
                rows.append((name, run_setting(SETTINGS[name], root / name, agent, n)))
        if json_out is not None:
            atomic_write_text(json_out, json.dumps({k: s.model_dump(mode="json") for k, s in rows}, indent=1) + "\n")
    except MansionError as exc:
        raise _fail(str(exc)) from None
    Console().print(_table(f"{agent}: the paper's task settings", rows))
