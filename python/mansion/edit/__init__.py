"""The edit stage: the paper's Task-Semantic Scene Editing Agent. It turns a generated building
into a playground for a task without regenerating it: the task is decomposed into
preconditions, each is checked with eight tools on the static house JSONs and AI2-THOR's asset
database, what is missing is provisioned, the simulator's oracle confirms the task is
executable, and the edits are saved as a variant beside the base building.

Controllers: offline, from a structured task (:class:`EditSpec`), and Claude's ReAct loop
(LangGraph, tool use) from the plain request. It builds on ``sim`` and ``scene``; neither imports
it.
"""

from mansion.edit.asset_search import Embedder, search_assets, sentence_embedder
from mansion.edit.controller import EditResult, edit_building
from mansion.edit.spec import Deliver, EditSpec, Fetch, StartRoom
from mansion.edit.tools import TOOL_NAMES, TOOL_SPECS, SceneTools
from mansion.edit.variants import (
    Variant,
    apply_variant,
    list_variants,
    load_variant,
    revert_variant,
)
from mansion.edit.workspace import Workspace

__all__ = [
    "TOOL_NAMES",
    "TOOL_SPECS",
    "Deliver",
    "EditResult",
    "EditSpec",
    "Embedder",
    "Fetch",
    "SceneTools",
    "StartRoom",
    "Variant",
    "Workspace",
    "apply_variant",
    "edit_building",
    "list_variants",
    "load_variant",
    "revert_variant",
    "search_assets",
    "sentence_embedder",
]
