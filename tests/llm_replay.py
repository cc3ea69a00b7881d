"""Replaying Messages API responses through the real Anthropic SDK, for the LLM tests.

An ``anthropic.Anthropic`` client is built on an ``httpx2.Client`` (the SDK's HTTP library since
1.0) whose ``MockTransport`` answers each POST /v1/messages from ``tests/fixtures/llm/``. The
SDK does everything it does in production (request building, response parsing, errors); only the
socket is replaced. The fixture file is chosen from the request itself:

- the agent, from the system instruction of its prompt template;
- a key within the agent: the floor index for the topology, the parent room for the seed planner;
- the attempt, from how many user turns the conversation has (a retry carries the previous answer
  and our list of problems), so ``<agent>_<key>.attempt1.json`` can be malformed and
  ``<agent>_<key>.json`` (any later attempt) corrected. For the scene editing agent's ReAct loop
  every turn is an attempt: ``editor_<variant>.attempt<k>.json`` answers after the k-th user turn
  (the request, then each round of tool results).

Every request the client sent is kept in ``Replay.requests`` so tests can look at what the model
was told (the validation errors fed back, the preview image).
"""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import anthropic
import httpx2

FIXTURES = Path(__file__).parent / "fixtures" / "llm"

_AGENTS = {
    "program a complete multi-floor building": "program",
    "abstract topological connectivity": "topology",
    "seed planning assistant": "seed",
    "You are a floor plan reader": "t2d",
    "interior object planner": "objects",
    "scene editing agent": "editor",
}


def _text(content: Any) -> str:
    if isinstance(content, str):
        return content
    return "".join(b.get("text", "") for b in content if isinstance(b, dict))


class Replay:
    """A mock transport serving fixtures, and the client that uses it."""

    def __init__(self, folder: Path = FIXTURES, overrides: dict[str, Any] | None = None) -> None:
        self.folder = folder
        #: fixture name → a response dict or an ``httpx2.Response`` served instead of the file.
        self.overrides = overrides or {}
        self.requests: list[dict[str, Any]] = []
        self.served: list[str] = []

    def key(self, body: dict[str, Any]) -> str:
        system = body.get("system", "")
        system = system if isinstance(system, str) else _text(system)
        agent = next((a for phrase, a in _AGENTS.items() if phrase in system), None)
        if agent is None:
            raise AssertionError(f"unknown agent for system prompt {system[:80]!r}")
        first = _text(body["messages"][0]["content"])
        if agent == "topology":
            m = re.search(r"Floor index (\d+)", first)
            assert m, "the topology prompt names its floor"
            return f"topology_floor{m.group(1)}"
        if agent == "t2d":
            m = re.search(r"Plan (\S+)\.", first)
            assert m, "the test descriptions name their plan"
            return f"t2d_{m.group(1)}"
        if agent == "objects":
            m = re.search(r"Room id: (\S+),", first)
            assert m, "the object planner prompt names its room"
            return f"objects_{m.group(1)}"
        if agent == "editor":
            m = re.search(r"Variant: (\S+)", first)
            assert m, "the scene editor prompt names its variant"
            return f"editor_{m.group(1)}"
        if agent == "seed":
            m = re.search(r"Parent room ID: (\S+),", first)
            assert m, "the seed prompt names its parent"
            return f"seed_{m.group(1)}"
        return "program"

    def handler(self, request: httpx2.Request) -> httpx2.Response:
        assert request.url.path == "/v1/messages", request.url
        body = json.loads(request.content)
        self.requests.append(body)
        key = self.key(body)
        attempt = sum(1 for m in body["messages"] if m["role"] == "user")
        for name in (f"{key}.attempt{attempt}", key):
            if name in self.overrides:
                self.served.append(name)
                found = self.overrides[name]
                return found if isinstance(found, httpx2.Response) else httpx2.Response(200, json=found)
            path = self.folder / f"{name}.json"
            if path.exists():
                self.served.append(name)
                return httpx2.Response(200, json=json.loads(path.read_text()))
        raise AssertionError(f"no fixture for {key} (attempt {attempt}) in {self.folder}")

    def client(self) -> anthropic.Anthropic:
        http = httpx2.Client(transport=httpx2.MockTransport(self.handler))
        # No SDK-level retries: a failing fixture should fail once, loudly.
        return anthropic.Anthropic(api_key="test", http_client=http, max_retries=0)


def message(text: str, *, stop_reason: str = "end_turn") -> dict[str, Any]:
    """A Messages API response whose only content is ``text`` (for inline overrides)."""
    return {
        "id": "msg_replay", "type": "message", "role": "assistant", "model": "claude-sonnet-5-5",
        "content": [{"type": "text", "text": text}], "stop_reason": stop_reason,
        "stop_sequence": None, "usage": {"input_tokens": 10, "output_tokens": 10},
    }
