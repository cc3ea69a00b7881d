"""The paper's three task settings, end to end: generate the building offline, sample tasks in
the setting's shape, run an agent."""

from __future__ import annotations

from pathlib import Path

from mansion.sim.evaluate import TaskScores, run_task, score
from mansion.sim.tasks import Setting, sample_tasks

__all__ = ["build_setting", "run_setting"]


def build_setting(setting: Setting, folder: Path) -> Path:
    """The setting's building (written once; reused when the folder already holds it)."""
    from mansion.building import generate_building
    from mansion.scene import write_scenes

    manifest = folder / "scenes" / "manifest.json"
    if not manifest.is_file():
        b = generate_building(setting.description, floors=setting.floors, seed=setting.seed)
        b.to_json(folder / "building.json")
        write_scenes(b, folder / "scenes")
    return folder


def run_setting(setting: Setting, folder: Path, agent: str, n: int = 10) -> TaskScores:
    from mansion.sim.agents import load_agent
    from mansion.sim.env import BuildingEnv

    building = build_setting(setting, folder)
    tasks = sample_tasks(building, n, setting.seed, setting=setting).tasks
    env = BuildingEnv(building)
    factory = load_agent(agent)
    return score([run_task(env, t, factory) for t in tasks], agent)
