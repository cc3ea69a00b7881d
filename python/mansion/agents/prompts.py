"""The prompt templates of the LLM agents, one file per agent in ``mansion/prompts/``.

The files live inside the package (the repository's top-level ``prompts/`` is a link to them) so
that an installed wheel finds them through :mod:`importlib.resources`, not through a path next to
a source checkout. A template file starts with ``#`` comment lines, then the system instruction,
then a ``=== user ===`` line, then the user message; placeholders are ``$name``
(:class:`string.Template`), so the JSON examples inside need no escaping.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache
from importlib import resources
from string import Template

from mansion.exceptions import PlannerError

__all__ = ["PROMPTS", "Prompt", "load_prompt"]

#: Agent name → template file.
PROMPTS = {
    "building_program": "building_program.md",
    "floor_topology": "floor_topology.md",
    "object_planner": "object_planner.md",
    "scene_editor": "scene_editor.md",
    "seed_planner": "seed_planner.md",
    "t2d_seeds": "t2d_seeds.md",
}

_SPLIT = "=== user ==="


@dataclass(frozen=True)
class Prompt:
    """One agent's template: the system instruction and the user message."""

    name: str
    system: Template
    user: Template

    def placeholders(self) -> set[str]:
        """Every ``$name`` the template expects."""
        return set(self.system.get_identifiers()) | set(self.user.get_identifiers())

    def render(self, **values: object) -> tuple[str, str]:
        """(system, user) with every placeholder filled; a missing value is a PlannerError (a bug
        in the caller, named here rather than sent to the model as a literal ``$name``)."""
        missing = sorted(self.placeholders() - values.keys())
        if missing:
            raise PlannerError(f"prompt {self.name!r} needs values for {', '.join(missing)}")
        text = {k: str(v) for k, v in values.items()}
        return self.system.substitute(text), self.user.substitute(text)


@cache
def load_prompt(name: str) -> Prompt:
    """The template of agent ``name`` (a key of :data:`PROMPTS`)."""
    if name not in PROMPTS:
        raise PlannerError(f"no prompt template for agent {name!r}; known: {', '.join(PROMPTS)}")
    try:
        raw = resources.files("mansion").joinpath("prompts", PROMPTS[name]).read_text("utf-8")
    except OSError as exc:
        raise PlannerError(
            f"the prompt template {PROMPTS[name]!r} is missing from the installed package: {exc}"
        ) from exc
    lines = raw.splitlines()
    while lines and lines[0].startswith("#"):
        lines.pop(0)
    body = "\n".join(lines)
    if _SPLIT not in body:
        raise PlannerError(f"prompt template {PROMPTS[name]!r} has no '{_SPLIT}' line")
    system, user = body.split(_SPLIT, 1)
    return Prompt(name, Template(system.strip()), Template(user.strip() + "\n"))
