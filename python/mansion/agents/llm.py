"""The one LLM client of mansion: Claude through the Anthropic SDK, answering in validated JSON.

Every agent asks through :meth:`LLMClient.ask`: a system instruction, a user message (text and,
for the seed planner, a rendered preview as an image block), the pydantic model the answer must
match, and an optional ``check`` that goes beyond the schema (areas that fit, ids that exist,
cores where the building has them). An answer that is not JSON, does not match the model or fails
the check is sent back to the model with the list of problems, up to ``attempts`` times; then a
:class:`PlannerError` names the agent and what was still wrong. API failures (no key, network,
refusal) are :class:`PlannerError` too: nothing an LLM says can crash the pipeline.

The key is ``ANTHROPIC_API_KEY`` and the model ``MANSION_MODEL`` (default :data:`DEFAULT_MODEL`).
Tests hand in an ``anthropic.Anthropic`` whose HTTP client replays recorded responses.
"""

from __future__ import annotations

import base64
import json
import os
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, TypeVar

from pydantic import BaseModel, ValidationError

from mansion.exceptions import MansionError, PlannerError
from mansion.models._validation import describe_validation_error

if TYPE_CHECKING:
    import anthropic

__all__ = [
    "DEFAULT_MODEL",
    "AnswerRejected",
    "LLMClient",
    "Usage",
    "image_block",
]

#: The newest Sonnet when this was written: a good balance of spatial reasoning, cost and speed.
DEFAULT_MODEL = "claude-sonnet-5-5"
#: Answers per question (the first and the retries after validation errors).
DEFAULT_ATTEMPTS = 3
DEFAULT_MAX_TOKENS = 16000

A = TypeVar("A", bound=BaseModel)
R = TypeVar("R")


class AnswerRejected(MansionError):
    """Raised by a ``check`` when a well-formed answer is still unusable; ``problems`` are sent
    back to the model, one line each."""

    def __init__(self, problems: list[str]) -> None:
        super().__init__("; ".join(problems))
        self.problems = problems


@dataclass
class Usage:
    """What the client has spent so far (for progress and cost reports)."""

    calls: int = 0
    retries: int = 0
    input_tokens: int = 0
    output_tokens: int = 0
    by_agent: dict[str, int] = field(default_factory=dict)


def image_block(png: bytes) -> dict[str, Any]:
    """A Messages API image content block holding a PNG."""
    return {
        "type": "image",
        "source": {"type": "base64", "media_type": "image/png", "data": base64.b64encode(png).decode()},
    }


def _json_text(text: str) -> str:
    """The JSON object inside ``text``: models sometimes wrap it in a fence or a sentence."""
    start, end = text.find("{"), text.rfind("}")
    if start < 0 or end < start:
        raise AnswerRejected(["the answer contains no JSON object; reply with the JSON object only"])
    return text[start : end + 1]


class LLMClient:
    """Claude behind one method; see the module doc."""

    def __init__(
        self,
        client: anthropic.Anthropic | None = None,
        *,
        model: str | None = None,
        attempts: int = DEFAULT_ATTEMPTS,
        max_tokens: int = DEFAULT_MAX_TOKENS,
        structured_output: bool = True,
    ) -> None:
        if attempts < 1:
            raise PlannerError(f"attempts must be at least 1, got {attempts}")
        if client is None:
            key = os.environ.get("ANTHROPIC_API_KEY", "").strip()
            if not key:
                raise PlannerError(
                    "the anthropic planner needs an API key: set ANTHROPIC_API_KEY "
                    "(or use the offline planner or ground-truth seeds, which need none)"
                )
            try:
                import anthropic
            except ImportError as exc:  # a broken install; the package depends on anthropic
                raise PlannerError(f"the anthropic SDK cannot be imported: {exc}") from exc
            client = anthropic.Anthropic(api_key=key)
        self.client = client
        self.model = model or os.environ.get("MANSION_MODEL", "").strip() or DEFAULT_MODEL
        self.attempts = attempts
        self.max_tokens = max_tokens
        # Structured outputs constrain decoding to the schema; our own validation still runs,
        # because the checks (areas, ids, geometry) are beyond what a JSON schema says.
        self.structured_output = structured_output
        self.usage = Usage()

    def _format(self, answer: type[BaseModel]) -> dict[str, Any] | None:
        if not self.structured_output:
            return None
        import anthropic

        return {"format": {"type": "json_schema", "schema": anthropic.transform_schema(answer.model_json_schema())}}

    def _send(self, agent: str, system: str, messages: list[dict[str, Any]], answer: type[BaseModel] | None,
              tools: list[dict[str, Any]] | None = None) -> Any:
        import anthropic

        extra: dict[str, Any] = {}
        fmt = self._format(answer) if answer is not None else None
        if fmt is not None:
            extra["output_config"] = fmt
        if tools is not None:
            extra["tools"] = tools
        try:
            response = self.client.messages.create(
                model=self.model, max_tokens=self.max_tokens, system=system,
                messages=messages,  # type: ignore[arg-type]
                **extra,
            )
        except anthropic.APIStatusError as exc:
            raise PlannerError(
                f"the Anthropic API refused the {agent} request (HTTP {exc.status_code}): "
                f"{_api_message(exc)}"
            ) from exc
        except anthropic.APIError as exc:
            raise PlannerError(f"the Anthropic API failed for the {agent} request: {exc}") from exc
        self.usage.calls += 1
        self.usage.by_agent[agent] = self.usage.by_agent.get(agent, 0) + 1
        if getattr(response, "usage", None) is not None:
            self.usage.input_tokens += response.usage.input_tokens or 0
            self.usage.output_tokens += response.usage.output_tokens or 0
        return response

    def converse(self, agent: str, system: str, messages: list[dict[str, Any]], tools: list[dict[str, Any]]) -> Any:
        """One turn of a tool-use conversation (a ReAct loop): the model's message, whose content
        may hold ``tool_use`` blocks for the caller to run and answer with ``tool_result`` blocks.
        API failures and refusals are :class:`PlannerError`, as in :meth:`ask`."""
        response = self._send(agent, system, messages, None, tools)
        if response.stop_reason == "refusal":
            text = "".join(b.text for b in response.content if getattr(b, "type", "") == "text")
            raise PlannerError(f"the model declined the {agent} request: {text.strip() or 'no reason given'}")
        return response

    def ask(
        self,
        agent: str,
        system: str,
        content: list[dict[str, Any]],
        answer: type[A],
        check: Callable[[A], R] | None = None,
    ) -> R | A:
        """Ask ``agent``'s question and return the validated answer (``check``'s result when a
        check is given). See the module doc for the retries and errors."""
        messages: list[dict[str, Any]] = [{"role": "user", "content": content}]
        problems: list[str] = []
        for attempt in range(self.attempts):
            if attempt:
                self.usage.retries += 1
            response = self._send(agent, system, messages, answer)
            text = "".join(b.text for b in response.content if getattr(b, "type", "") == "text")
            if response.stop_reason == "refusal":
                raise PlannerError(f"the model declined the {agent} request: {text.strip() or 'no reason given'}")
            try:
                if response.stop_reason == "max_tokens":
                    raise AnswerRejected(
                        [f"the answer was cut off at {self.max_tokens} tokens; answer more briefly"]
                    )
                parsed = answer.model_validate_json(_json_text(text))
                return check(parsed) if check is not None else parsed
            except ValidationError as exc:
                problems = describe_validation_error(exc).split("; ")
            except AnswerRejected as exc:
                problems = exc.problems
            except MansionError as exc:
                # A model validator or our geometry code refusing the answer (InvalidInputError,
                # PlannerError): the message names what is wrong, so the model can fix it.
                problems = [str(exc)]
            messages += [
                {"role": "assistant", "content": text or "(empty answer)"},
                {"role": "user", "content": _feedback(problems)},
            ]
        raise PlannerError(
            f"the {agent} answer was still invalid after {self.attempts} attempts "
            f"(model {self.model}): " + "; ".join(problems)
        )


def _feedback(problems: list[str]) -> str:
    lines = "\n".join(f"- {p}" for p in problems)
    return (
        "Your answer could not be used:\n"
        f"{lines}\n"
        "Reply with the corrected JSON object only, following the same schema."
    )


def _api_message(exc: Any) -> str:
    body = getattr(exc, "body", None)
    if isinstance(body, dict):
        err = body.get("error")
        if isinstance(err, dict) and err.get("message"):
            return str(err["message"])
    try:
        return json.dumps(body) if body is not None else str(exc)
    except (TypeError, ValueError):
        return str(exc)
