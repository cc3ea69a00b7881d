"""Pictures of an episode: the agent's walk across the floors it visited."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from mansion.sim.render import draw_episode
from mansion.sim.world import FloorState

__all__ = ["draw_task"]


def draw_task(env: Any, task: Any, out: str | Path) -> Path:
    """Draw the env's last episode (after ``run_task``): one panel per floor visited, the walk in
    blue, the target's first place and the destination marked."""
    floors = sorted({f for f, _ in env.trace})
    states = {f: (env.state if f == env.floor else env.building.floor_state(f, env.cell)) for f in floors}
    marks: dict[int, list[tuple[float, float, str]]] = {}
    for t in task.targets:
        pos = _object_position(env._pristine, t.floor, t.object_id)
        if pos is not None:
            marks.setdefault(t.floor, []).append((pos[0], pos[1], t.object_type))
    d = task.destination
    st = states.get(d.floor)
    if st is not None:
        if d.receptacle and d.receptacle in st.objects:
            x, z = st.objects[d.receptacle].centre
        else:
            x, z = st.landmarks[d.room]
        marks.setdefault(d.floor, []).append((x, z, "goal"))
    title = f"{task.instruction}  ({'solved' if env.task_result()['success'] else 'not solved'} in {env.steps} steps, {env.path_length:.0f} m)"
    return draw_episode(states, env.trace, out, title=title, marks=marks)


def _object_position(building: Any, floor: int, object_id: str) -> tuple[float, float] | None:
    st = FloorState(building.house(floor), {})
    info = st.objects.get(object_id)
    return info.centre if info else None
