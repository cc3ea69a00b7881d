"""Running agents on tasks and scoring them as the paper's Table "Task success rates" does:
success, and a progress score split into object retrieval and navigation to the destination;
plus mean path length and steps."""

from __future__ import annotations

import statistics
from pathlib import Path
from typing import Any, Callable

from pydantic import BaseModel, Field

from mansion._io import atomic_write_text
from mansion.sim.env import BuildingEnv
from mansion.sim.tasks import TaskSpec

__all__ = ["TaskOutcome", "TaskScores", "run_task", "score"]


class TaskOutcome(BaseModel):
    id: str
    building: str
    success: bool
    retrieved: bool
    navigated: bool
    steps: int
    path_length: float
    floor_changes: int
    crosses_floors: bool
    last_reason: str = ""


class TaskScores(BaseModel):
    """What ``mansion eval tasks --json`` writes."""

    agent: str = ""
    tasks: int
    success: float = Field(description="% of tasks solved.")
    retrieved: float = Field(description="% of tasks whose objects the agent picked up.")
    navigated: float = Field(description="% of tasks whose destination the agent reached.")
    cross_floor: int = Field(description="Tasks crossing two or more floors.")
    mean_path_length: float
    mean_steps: float
    per_task: list[TaskOutcome]

    def to_json(self, path: str | Path) -> Path:
        return atomic_write_text(path, self.model_dump_json(indent=1) + "\n")


def run_task(env: BuildingEnv, task: TaskSpec, agent: Callable[..., Any],
             on_step: Callable[[BuildingEnv], None] | None = None) -> TaskOutcome:
    """One episode: reset to the task, ask the agent for actions until it stops, the task is
    done or the step budget is spent."""
    obs, info = env.reset(options={"task": task})
    policy = agent(env, task)
    for _ in range(task.max_steps):
        action = policy(obs, info)
        if action is None:
            break
        obs, _, terminated, truncated, info = env.step(action)
        if on_step is not None:
            on_step(env)
        if terminated or truncated:
            break
    r = env.task_result()
    return TaskOutcome(
        id=task.id, building=task.building, success=r["success"], retrieved=r["retrieved"],
        navigated=r["navigated"], steps=r["steps"], path_length=r["path_length"],
        floor_changes=r["floor_changes"], crosses_floors=task.crosses_floors, last_reason=env.last.reason,
    )


def score(outcomes: list[TaskOutcome], agent: str = "") -> TaskScores:
    n = len(outcomes)

    def pct(k: str) -> float:
        return round(100.0 * sum(getattr(o, k) for o in outcomes) / n, 2) if n else 0.0

    return TaskScores(
        agent=agent, tasks=n, success=pct("success"), retrieved=pct("retrieved"), navigated=pct("navigated"),
        cross_floor=sum(o.crosses_floors for o in outcomes),
        mean_path_length=round(statistics.fmean(o.path_length for o in outcomes), 2) if n else 0.0,
        mean_steps=round(statistics.fmean(o.steps for o in outcomes), 2) if n else 0.0,
        per_task=outcomes,
    )
