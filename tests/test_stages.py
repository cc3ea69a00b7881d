"""The package's stages import one way: no import circle between them (ARCHITECTURE: "a stage
imports only the stages before it and models"). Every ``from mansion.X ...`` of every module is
read, lazy ones inside functions too (a lazy import is still a circle: the building stage once
reached back into the agents for the LLM planners' graph)."""

from __future__ import annotations

import ast
from collections import defaultdict
from pathlib import Path

import mansion

PACKAGE = Path(mansion.__file__).parent


def _stage(module: str) -> str:
    """``mansion.building.steps`` → ``building``; a top-level module is its own stage."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else parts[0]


def stage_imports() -> dict[str, set[str]]:
    """Each stage → the other stages its modules import (the package root, which re-exports the
    public API, left out)."""
    found: dict[str, set[str]] = defaultdict(set)
    for path in PACKAGE.rglob("*.py"):
        parts = path.relative_to(PACKAGE).with_suffix("").parts
        if parts == ("__init__",):
            continue
        stage = parts[0]
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("mansion."):
                other = _stage(node.module)
                if other != stage:
                    found[stage].add(other)
    return found


def test_no_stage_imports_a_stage_that_imports_it_back() -> None:
    imports = stage_imports()
    assert {"planning", "floorplan", "building", "agents", "scene"} <= set(imports)

    def reached(start: str) -> set[str]:
        seen: set[str] = set()
        todo = [start]
        while todo:
            for nxt in imports.get(todo.pop(), ()):
                if nxt not in seen:
                    seen.add(nxt)
                    todo.append(nxt)
        return seen

    circles = sorted(s for s in imports if s in reached(s))
    assert circles == [], f"stages in an import circle: {circles}"


def test_the_llm_client_and_prompts_depend_on_nothing_but_the_models() -> None:
    # the one home of the LLM client and the prompts: any stage may import it
    assert stage_imports()["agents"] <= {"models", "exceptions"}
