"""Editing a building for a task, end to end: a controller checks and provisions (offline from a
structured spec, or Claude's ReAct loop from the plain request), the task is confirmed executable
by the simulator's oracle agent walking it on the edited building, and the variant is saved.

The oracle's walk is the last check: the edits are written as a variant only when the agent,
starting where the task starts, fetches every object and puts it on the destination.
"""

from __future__ import annotations

import re
import shutil
import tempfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from mansion.edit.provision import EditLog, PreconditionFailed, Provisioned, provision
from mansion.edit.spec import EditSpec
from mansion.edit.tools import SceneTools
from mansion.edit.variants import check_name, save_variant
from mansion.edit.workspace import Workspace
from mansion.exceptions import EditError
from mansion.sim.tasks import TaskSpec

__all__ = ["EditResult", "edit_building", "variant_name"]

#: The step budget the oracle gets for its check walk (the task keeps twice what it used + 10,
#: the sampler's rule).
CHECK_BUDGET = 400


@dataclass
class EditResult:
    ok: bool
    log: EditLog
    spec: EditSpec | None = None
    task: TaskSpec | None = None
    variant: Path | None = None
    failed: str | None = None
    edits: list[str] = field(default_factory=list)


def variant_name(text: str) -> str:
    """A default variant name from the task's words ("i-need-a-task-where-the-agent")."""
    words = re.findall(r"[a-z0-9]+", text.lower())[:7]
    return "-".join(words) or "task"


def _task_spec(ws: Workspace, name: str, spec: EditSpec, got: Provisioned, budget: int) -> TaskSpec:
    return TaskSpec(id=f"{ws.building.manifest.id}-{name}", building=ws.building.manifest.id, instruction=spec.text,
                    start=got.start, targets=got.targets, destination=got.destination, max_steps=budget)


def _oracle(scenes_dir: Path, task: TaskSpec) -> tuple[bool, int, float, str]:
    from mansion.sim.agents import OracleAgent
    from mansion.sim.env import BuildingEnv
    from mansion.sim.evaluate import run_task

    out = run_task(BuildingEnv(scenes_dir), task, OracleAgent)
    return out.success, out.steps, out.path_length, out.last_reason


def edit_building(building_dir: str | Path, spec: EditSpec | None = None, *, text: str | None = None,
                  name: str | None = None, planner: str = "offline", client: Any = None,
                  max_turns: int | None = None, settle_with: Any = None, embedder: Any = None) -> EditResult:
    """Edit the building for the task (``spec`` offline; ``text`` with ``planner="anthropic"``)
    and save the variant when the task has become executable. Never changes the base files.
    ``settle_with``: an AI2-THOR controller in which the placed objects settle (optional);
    ``embedder``: SearchAssets ranks by meaning with it (:func:`mansion.edit.sentence_embedder`)."""
    ws = Workspace(building_dir)
    tools = SceneTools(ws, embedder=embedder)
    log = EditLog()
    if planner == "offline":
        if spec is None:
            raise EditError("the offline controller needs a structured task (--spec FILE); a plain request needs "
                            "--planner anthropic")
    elif planner == "anthropic":
        from mansion.edit.react import react_edit

        kwargs = {"max_turns": max_turns} if max_turns else {}
        spec = react_edit(tools, text or (spec.text if spec else ""), log, client=client,
                          name=name or variant_name(text or ""), **kwargs)
    else:
        raise EditError(f"unknown planner {planner!r}: offline or anthropic")
    name = check_name(name or variant_name(spec.text))
    result = EditResult(ok=False, log=log, spec=spec)
    try:
        got = provision(tools, spec, log)
    except PreconditionFailed as exc:
        log.result(str(exc), False)
        result.failed = str(exc)
        result.edits = [e.text for e in tools.edits]
        return result
    result.edits = [e.text for e in tools.edits]
    if settle_with is not None:
        from mansion.edit.settle import settle

        what = "the placed objects stay where they were placed in AI2-THOR"
        log.precondition(what)
        try:
            for line in settle(tools, settle_with):
                log.edit(line)
        except EditError as exc:
            result.failed = f"precondition not met: {what}: {exc}"
            log.result(result.failed, False)
            return result
    what = "the oracle agent completes the task on the edited building"
    log.precondition(what)
    task = _task_spec(ws, name, spec, got, CHECK_BUDGET)
    with tempfile.TemporaryDirectory(prefix="mansion-edit-") as tmp:
        probe = save_variant(ws, "probe", text=spec.text, planner=planner, spec=spec.model_dump(mode="json"),
                             log=[], task=task, root=Path(tmp))
        ok, steps, metres, reason = _oracle(probe / "scenes", task)
        shutil.rmtree(probe, ignore_errors=True)
    log.check(f"OracleAgent: {'done' if ok else 'failed'} in {steps} steps, {metres:.1f} m"
              + ("" if ok else f" ({reason})"), ok)
    if not ok:
        result.failed = f"precondition not met: {what}: {reason}"
        log.result(result.failed, False)
        return result
    task = task.model_copy(update={"max_steps": 2 * steps + 10})
    result.variant = ws.root / "variants" / name
    log.result(f"variant {name!r} saved in variants/{name}/ of the building", True)
    save_variant(ws, name, text=spec.text, planner=planner, spec=spec.model_dump(mode="json"),
                 log=[line.to_dict() for line in log.lines], task=task)
    result.ok, result.task = True, task
    return result
