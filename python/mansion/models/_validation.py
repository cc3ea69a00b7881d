"""Turning pydantic's ValidationError into mansion's InvalidInputError.

Pydantic wraps every ``ValueError`` raised inside a validator -- including our own
``InvalidInputError`` -- into a ``pydantic.ValidationError``. Users of ``solve_floor`` and the CLI
should see one exception type with a readable message instead, so every entry point that accepts
user data goes through :func:`validate_input`.
"""

from __future__ import annotations

import json
import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any, TypeVar

from pydantic import BaseModel, ValidationError

from mansion.exceptions import InvalidInputError, MansionError

__all__ = ["describe_validation_error", "load_input", "validate_input"]

M = TypeVar("M", bound=BaseModel)


def describe_validation_error(exc: ValidationError) -> str:
    """One readable line per problem, joined by '; '.

    Errors our own validators raised keep their message unchanged (it already names the room,
    edge or core); pydantic's field errors are prefixed with the field path, e.g.
    ``nodes.2.area: Input should be greater than 0``.
    """
    parts: list[str] = []
    for err in exc.errors(include_url=False):
        original = (err.get("ctx") or {}).get("error")
        if isinstance(original, MansionError):
            parts.append(str(original))
            continue
        loc = ".".join(str(p) for p in err.get("loc", ()))
        parts.append(f"{loc}: {err['msg']}" if loc else str(err["msg"]))
    return "; ".join(parts) if parts else str(exc)


def validate_input(model: type[M], value: object, what: str) -> M:
    """Validate ``value`` (an instance of ``model`` or a mapping) as ``model``.

    An instance is validated again from its dump, because pydantic models are mutable and a caller
    may have changed a field after construction. Raises :class:`InvalidInputError` naming ``what``
    (e.g. "room graph") on any problem.
    """
    if isinstance(value, model):
        data: object = value.model_dump()
    elif isinstance(value, BaseModel):
        raise InvalidInputError(
            f"{what} must be a {model.__name__} or a dict, got a {type(value).__name__}"
        )
    elif isinstance(value, Mapping):
        data = value
    else:
        raise InvalidInputError(
            f"{what} must be a {model.__name__} or a dict, got {type(value).__name__}"
        )
    try:
        return model.model_validate(data)
    except ValidationError as exc:
        raise InvalidInputError(f"invalid {what}: {describe_validation_error(exc)}") from exc


def load_input(model: type[M], path: str | os.PathLike[str], what: str) -> M:
    """Read a JSON file and validate it as ``model``; every failure is an InvalidInputError."""
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except OSError as exc:
        raise InvalidInputError(f"cannot read {what} file {str(p)!r}: {exc.strerror or exc}") from exc
    try:
        data: Any = json.loads(text)
    except json.JSONDecodeError as exc:
        raise InvalidInputError(
            f"{what} file {str(p)!r} is not valid JSON: {exc.msg} (line {exc.lineno}, column {exc.colno})"
        ) from exc
    if not isinstance(data, Mapping):
        raise InvalidInputError(f"{what} file {str(p)!r} must hold a JSON object")
    try:
        return model.model_validate(data)
    except ValidationError as exc:
        raise InvalidInputError(
            f"invalid {what} in {str(p)!r}: {describe_validation_error(exc)}"
        ) from exc


def load_written(model: type[M], path: str | os.PathLike[str], what: str) -> M:
    """Read back a JSON file that mansion wrote (``model_dump_json``): validated in JSON mode, so
    it round-trips exactly; an unreadable or invalid file is an InvalidInputError naming it."""
    p = Path(path)
    try:
        return model.model_validate_json(p.read_bytes())
    except OSError as exc:
        raise InvalidInputError(f"cannot read {what} {str(p)!r}: {exc}") from exc
    except ValidationError as exc:
        raise InvalidInputError(f"invalid {what} {str(p)!r}: {describe_validation_error(exc)}") from exc
