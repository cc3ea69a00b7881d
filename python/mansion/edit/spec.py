"""The structured task a scene is edited for (JSON, pydantic), as the issue gives it::

    {"text": "I need a task where ...",
     "start": {"floor": 0, "room": "lobby"},
     "fetch": [{"object_type": "Apple", "floor": 1, "on": "DiningTable", "in": null},
               {"object_type": "WineBottle", "floor": 1, "on": null, "in": "Fridge"}],
     "deliver": {"floor": 0, "on": "Sofa"}}

``on`` / ``in`` name a receptacle object type (AI2-THOR's, e.g. DiningTable, Fridge); a fetch with
neither may be anywhere on its floor. Rooms are room ids or room types.
"""

from __future__ import annotations

import json
from pathlib import Path

from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

from mansion.exceptions import InvalidInputError
from mansion.models._validation import describe_validation_error

__all__ = ["Deliver", "EditSpec", "Fetch", "StartRoom"]


class _Spec(BaseModel):
    model_config = ConfigDict(extra="forbid", populate_by_name=True, serialize_by_alias=True)


class StartRoom(_Spec):
    floor: int = Field(ge=0)
    room: str = Field(min_length=1, description="Room id or room type.")


class Fetch(_Spec):
    object_type: str = Field(min_length=1, description="AI2-THOR object type, e.g. Apple.")
    floor: int = Field(ge=0)
    on: str | None = Field(default=None, description="Receptacle type it lies on.")
    in_: str | None = Field(default=None, alias="in", description="Container type it lies in.")

    @model_validator(mode="after")
    def _one_place(self) -> Fetch:
        if self.on is not None and self.in_ is not None:
            raise ValueError(f"fetch {self.object_type}: give 'on' or 'in', not both")
        return self

    def where(self) -> str:
        for word, kind in (("on", self.on), ("in", self.in_)):
            if kind:
                return f"{word} {'an' if kind[:1].lower() in 'aeiou' else 'a'} {kind}"
        return "anywhere"


class Deliver(_Spec):
    floor: int = Field(ge=0)
    on: str = Field(min_length=1, description="Receptacle type to put the objects on.")


class EditSpec(_Spec):
    text: str
    start: StartRoom
    fetch: list[Fetch] = Field(min_length=1)
    deliver: Deliver

    @classmethod
    def load(cls, path: str | Path) -> EditSpec:
        p = Path(path)
        try:
            data = json.loads(p.read_text(encoding="utf-8"))
        except (OSError, ValueError) as exc:
            raise InvalidInputError(f"cannot read task spec {str(p)!r}: {exc}") from exc
        try:
            return cls.model_validate(data)
        except ValidationError as exc:
            raise InvalidInputError(f"{p}: {describe_validation_error(exc)}") from exc
