"""The sim stage: a headless multi-floor environment over the scenes, its skills, tasks,
agents and their evaluation (the paper's cross-floor tasks)."""

from mansion.sim.env import SKILLS, BuildingEnv, SkillResult

__all__ = ["SKILLS", "BuildingEnv", "SkillResult"]
