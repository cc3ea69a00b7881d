"""The ReAct controller: Claude with the eight tools in a LangGraph loop (``--planner anthropic``).

::

    model ──tool_use──▶ tools ──▶ model ... ──SubmitTask accepted──▶ end

``model`` asks Claude (through the one LLM client, :mod:`mansion.agents.llm`) for its next step
given the conversation so far; ``tools`` runs every ``tool_use`` block against the building
(:class:`~mansion.edit.tools.SceneTools`) and answers with ``tool_result`` blocks, an error
result carrying the typed error's message so the model can correct itself. The model ends by
calling ``SubmitTask`` with the structured task (:class:`~mansion.edit.spec.EditSpec`); the
caller then checks it as the offline controller does, on the building as the model left it.
Every tool call is logged as a check, every change as an edit.
"""

from __future__ import annotations

import json
from typing import Any, TypedDict

from pydantic import ValidationError

from mansion.agents.llm import LLMClient
from mansion.agents.prompts import load_prompt
from mansion.edit.provision import EditLog
from mansion.edit.spec import EditSpec
from mansion.edit.tools import TOOL_SPECS, SceneTools
from mansion.exceptions import PlannerError
from mansion.models._validation import describe_validation_error

__all__ = ["SUBMIT", "react_edit"]

#: Model turns before the loop gives up.
MAX_TURNS = 30
#: The finishing tool: its input is the structured task.
SUBMIT = "SubmitTask"
#: Longest tool answer sent back, in characters (the rest is cut, saying so).
ANSWER_CHARS = 6000


class EditState(TypedDict, total=False):
    messages: list[dict[str, Any]]
    pending: list[dict[str, Any]]
    turns: int
    spec: EditSpec | None
    stopped: str


def _submit_spec() -> dict[str, Any]:
    return {"name": SUBMIT, "description": "Finish: the task, structured. Call once every precondition holds.",
            "input_schema": EditSpec.model_json_schema(by_alias=True)}


def _blocks(content: Any) -> list[dict[str, Any]]:
    """The assistant's content as request blocks (text and tool_use only)."""
    out = []
    for b in content:
        kind = getattr(b, "type", "")
        if kind == "text":
            out.append({"type": "text", "text": b.text})
        elif kind == "tool_use":
            out.append({"type": "tool_use", "id": b.id, "name": b.name, "input": dict(b.input)})
    return out


def _short(answer: dict[str, Any]) -> str:
    text = json.dumps(answer)
    return text if len(text) <= ANSWER_CHARS else text[:ANSWER_CHARS] + f"... (cut: {len(text)} characters)"


def _summary(name: str, ok: bool, answer: dict[str, Any]) -> str:
    if not ok:
        return str(answer.get("error", ""))
    if "count" in answer:
        return f"{answer['count']} objects"
    if "assets" in answer:
        return ", ".join(a["asset_id"] for a in answer["assets"]) or "no asset"
    if "receptacles" in answer:
        parts = []
        for r in answer["receptacles"]:
            items = r.get("on_top", r.get("inside", []))
            parts.append(f"{r['id']}: {', '.join(i['type'] for i in items) or 'nothing'}")
        return "; ".join(parts)
    if "ok" in answer:
        return f"{answer.get('metres')} m via {', '.join(answer.get('cores', [])) or 'no core'}" if answer["ok"] else answer["reason"]
    return "done"


def _rooms(tools: SceneTools) -> str:
    lines = []
    for k in tools.ws.floors:
        st = tools.ws.floor(k)
        lines.append(f"floor {k}: " + ", ".join(f"{r.id}: {r.room_type}" for r in st.rooms.values()))
    return "\n".join(lines)


def build_graph(client: LLMClient, tools: SceneTools, system: str, log: EditLog, max_turns: int) -> Any:
    from langgraph.graph import END, START, StateGraph

    specs = [*TOOL_SPECS, _submit_spec()]

    def model(state: EditState) -> EditState:
        turns = state.get("turns", 0)
        if turns >= max_turns:
            return {"stopped": f"no SubmitTask after {max_turns} turns", "pending": []}
        response = client.converse("scene_editor", system, state["messages"], specs)
        blocks = _blocks(response.content)
        uses = [b for b in blocks if b["type"] == "tool_use"]
        out: EditState = {"messages": [*state["messages"], {"role": "assistant", "content": blocks}],
                          "pending": uses, "turns": turns + 1}
        if not uses:
            text = " ".join(b["text"] for b in blocks if b["type"] == "text").strip()
            out["stopped"] = f"the model stopped without SubmitTask: {text[:300] or response.stop_reason}"
        return out

    def run_tools(state: EditState) -> EditState:
        results = []
        spec = None
        for use in state["pending"]:
            name, args = use["name"], use["input"]
            if name == SUBMIT:
                try:
                    spec = EditSpec.model_validate(args)
                    ok, answer = True, {"accepted": "the task is checked next"}
                except ValidationError as exc:
                    ok, answer = False, {"error": describe_validation_error(exc)}
                log.check(f"{SUBMIT}: {'accepted' if ok else answer['error']}", ok)
            else:
                done = len(tools.edits)
                ok, answer = tools.run(name, args)
                shown = ", ".join(f"{k}={v!r}" for k, v in args.items())
                log.check(f"{name}({shown}): {_summary(name, ok, answer)}", ok)
                for e in tools.edits[done:]:
                    log.edit(e.text)
            block: dict[str, Any] = {"type": "tool_result", "tool_use_id": use["id"], "content": _short(answer)}
            if not ok:
                block["is_error"] = True
            results.append(block)
        return {"messages": [*state["messages"], {"role": "user", "content": results}], "pending": [], "spec": spec}

    def after_model(state: EditState) -> str:
        return "tools" if state.get("pending") else END

    def after_tools(state: EditState) -> str:
        return END if state.get("spec") is not None else "model"

    g = StateGraph(EditState)
    g.add_node("model", model)
    g.add_node("tools", run_tools)
    g.add_edge(START, "model")
    g.add_conditional_edges("model", after_model, ["tools", END])
    g.add_conditional_edges("tools", after_tools, ["model", END])
    return g.compile()


def react_edit(tools: SceneTools, request: str, log: EditLog, *, name: str, client: Any = None,
               max_turns: int = MAX_TURNS) -> EditSpec:
    """Let Claude check and provision the building for ``request``; returns the task it
    submitted. ``client``: an ``anthropic.Anthropic`` (tests replay recorded answers through it)
    or an :class:`LLMClient`; default from ``ANTHROPIC_API_KEY``."""
    if not request.strip():
        raise PlannerError("the scene editing agent needs the task in words")
    llm = client if isinstance(client, LLMClient) else LLMClient(client)
    ws = tools.ws
    system, user = load_prompt("scene_editor").render(
        name=name, request=request, building=ws.building.manifest.id, floor_count=len(ws.floors), rooms=_rooms(tools))
    log.precondition(f"Claude ({llm.model}) decomposes the request and checks and provisions it with the tools")
    graph = build_graph(llm, tools, system, log, max_turns)
    state = graph.invoke({"messages": [{"role": "user", "content": [{"type": "text", "text": user}]}], "turns": 0},
                         {"recursion_limit": 2 * max_turns + 5})
    spec = state.get("spec")
    if spec is None:
        raise PlannerError(f"the scene editing agent failed: {state.get('stopped', 'no task submitted')}")
    return spec  # type: ignore[no-any-return]
