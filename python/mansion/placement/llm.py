"""The LLM object planner: Claude writes the object plan of a room, in the offline planner's
schema, through :meth:`mansion.agents.llm.LLMClient.ask` (validated, retried with the problems)."""

from __future__ import annotations

from pydantic import BaseModel, Field
from shapely.geometry import Polygon

from mansion.agents.llm import AnswerRejected, LLMClient
from mansion.agents.prompts import load_prompt
from mansion.models.objects import ObjectItem, ObjectPlan
from mansion.placement.assets import TUCKABLE, database

__all__ = ["LLMObjectPlanner", "ObjectPlanAnswer"]


class ObjectPlanAnswer(BaseModel):
    items: list[ObjectItem] = Field(min_length=1, max_length=80)


class LLMObjectPlanner:
    """``plan(room_id, room_type, polygon, building_type)`` like :func:`plan_objects`."""

    def __init__(self, client: LLMClient) -> None:
        self.client = client

    def plan(
        self, room_id: str, room_type: str, polygon: list[tuple[float, float]], building_type: str = "",
        seed: int = 0,
    ) -> ObjectPlan:
        db = database()
        floor = db.floor_types()
        receptacles = sorted(set(db.receptacles) & set(floor))
        poly = Polygon(polygon)
        x0, y0, x1, y1 = poly.bounds
        system, user = load_prompt("object_planner").render(
            building_type=building_type or "unspecified",
            room_id=room_id,
            room_type=room_type,
            polygon=", ".join(f"({x:g}, {y:g})" for x, y in polygon),
            area=f"{poly.area:.1f}",
            width=f"{x1 - x0:.1f}",
            height=f"{y1 - y0:.1f}",
            floor_types=", ".join(floor),
            receptacles=", ".join(receptacles),
        )

        def check(answer: ObjectPlanAnswer) -> ObjectPlan:
            problems = []
            for it in answer.items:
                if it.object_type not in floor:
                    problems.append(f"item {it.id}: {it.object_type!r} is not one of the floor object types")
                if it.small_objects and it.object_type not in receptacles:
                    problems.append(f"item {it.id}: {it.object_type} cannot hold small objects")
                if it.tuck and it.object_type not in TUCKABLE:
                    problems.append(f"item {it.id}: only chairs and stools may be tucked")
                if it.structure == "matrix" and min(it.row_gap, it.col_gap) < 0.6 and it.rows * it.cols > 1:
                    # shelves side by side in one run are fine; aisles between rows must pass a robot
                    if it.rows > 1 and it.row_gap < 0.6:
                        problems.append(f"item {it.id}: row_gap {it.row_gap} m is narrower than a robot needs (0.6)")
            if problems:
                raise AnswerRejected(problems)
            # the plan's own validation (partners, targets) raises InvalidInputError, which the
            # client feeds back to the model as well
            return ObjectPlan(room_id=room_id, room_type=room_type, items=answer.items)

        content = [{"type": "text", "text": user}]
        return self.client.ask("object_planner", system, content, ObjectPlanAnswer, check)  # type: ignore[return-value]
