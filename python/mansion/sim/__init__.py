"""The sim stage: a headless multi-floor environment over the scenes, its skills, tasks,
agents and their evaluation (the paper's cross-floor tasks)."""

from mansion.sim.agents import BaselineAgent, OracleAgent, load_agent
from mansion.sim.env import SKILLS, BuildingEnv, SkillResult
from mansion.sim.evaluate import TaskOutcome, TaskScores, run_task, score
from mansion.sim.tasks import SETTINGS, TaskSet, TaskSpec, load_tasks, sample_tasks

__all__ = [
    "SETTINGS",
    "SKILLS",
    "BaselineAgent",
    "BuildingEnv",
    "OracleAgent",
    "SkillResult",
    "TaskOutcome",
    "TaskScores",
    "TaskSet",
    "TaskSpec",
    "load_agent",
    "load_tasks",
    "run_task",
    "sample_tasks",
    "score",
]
