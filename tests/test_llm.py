"""The LLM planners, replayed: recorded Messages API responses through the real Anthropic SDK.

No network: ``llm_replay.Replay`` answers the SDK's HTTP requests from ``tests/fixtures/llm``.
"""

from __future__ import annotations

import base64
import json
import random
from pathlib import Path

import httpx2
import pytest
from llm_replay import Replay, message
from typer.testing import CliRunner

from mansion import Building, Footprint, PlannerError, generate_building
from mansion.agents.llm import DEFAULT_MODEL, AnswerRejected, LLMClient
from mansion.agents.prompts import PROMPTS, load_prompt
from mansion.building.checks import check_building
from mansion.models.seeds import SeedRequest
from mansion.planning import planners as planner_module
from mansion.planning.llm import AnthropicBuildingPlanner
from mansion.planning.llm_program import Frame, ProgramAnswer, program_from_answer
from mansion.planning.llm_seeds import SeedAnswer, plan_from_answer
from mansion.planning.llm_topology import TopologyAnswer, graph_from_answer
from mansion.planning.planner import Constraints, read_brief

FIXTURES = Path(__file__).parent / "fixtures" / "llm"
OUTLINE = [(0.0, 0.0), (20.0, 0.0), (20.0, 12.0), (0.0, 12.0)]
DESCRIPTION = "a two-storey office with a lift"


def _answer(name: str) -> dict:
    return json.loads(json.loads((FIXTURES / f"{name}.json").read_text())["content"][0]["text"])


def _planner(replay: Replay, **kw: object) -> AnthropicBuildingPlanner:
    return AnthropicBuildingPlanner(LLMClient(replay.client(), **kw))  # type: ignore[arg-type]


def _frame(floors: int = 2) -> Frame:
    rng = random.Random(0)
    constraints = Constraints(floors=floors, outline=(OUTLINE, []), load_bearing=False)
    brief = read_brief(DESCRIPTION, constraints, rng)
    return Frame.resolve(brief.request, brief.key, brief.typology, brief.options, brief.palette, rng)


@pytest.fixture(scope="module")
def replayed() -> tuple[Building, Replay, AnthropicBuildingPlanner]:
    replay = Replay()
    planner = _planner(replay)
    building = generate_building(
        DESCRIPTION, floors=2, footprint=Footprint(polygon=OUTLINE), planner=planner, seed=0
    )
    return building, replay, planner


# -- prompts ------------------------------------------------------------------------------------


def test_every_prompt_renders_every_placeholder() -> None:
    for name in PROMPTS:
        prompt = load_prompt(name)
        assert prompt.placeholders(), name
        system, user = prompt.render(**{k: f"<{k}>" for k in prompt.placeholders()})
        assert "$" not in system + user and "=== user ===" not in user
        with pytest.raises(PlannerError, match="needs values for"):
            prompt.render()


# -- the end-to-end building --------------------------------------------------------------------


def test_two_floor_building_from_recorded_responses(replayed) -> None:
    building, replay, planner = replayed
    assert building.planner == "anthropic" and len(building.floors) == 2
    check_building(building)
    ids = [{r.id for r in f.layout.rooms} for f in building.floors]
    assert ids[0] == {"lobby", "stair_1", "elevator_1", "office_1", "office_2", "meeting", "toilets"}
    assert ids[1] == {"corridor", "stair_1", "elevator_1", "office_3", "office_4", "kitchen", "toilets_1"}
    assert building.floors[1].graph.node("kitchen").room_type == "kitchenette"
    # One program, two topologies (one retried), one seed plan per cut round.
    assert sorted(replay.served) == sorted(
        ["program", "topology_floor0", "topology_floor1.attempt1", "topology_floor1", "seed_lobby", "seed_corridor"]
    )
    assert planner.llm.usage.calls == 6 and planner.llm.usage.retries == 1


def test_cores_are_checked_not_trusted(replayed) -> None:
    building, _, _ = replayed
    cores = {c.id: c for c in building.program.cores}
    # The stair stood in a corner and is kept; the elevator was proposed mid-floor and moved.
    assert cores["stair_1"].x == (0.0, 3.0) and cores["stair_1"].y == (0.0, 6.0)
    assert (cores["elevator_1"].x, cores["elevator_1"].y) != ((8.0, 11.0), (4.0, 7.0))
    assert "elevator_1" in building.program.reasoning and "re-placed" in building.program.reasoning
    for floor in building.floors:
        boxes = {c.id: (c.x, c.y) for c in floor.footprint.cores}
        assert boxes == {k: (c.x, c.y) for k, c in cores.items()}


def test_room_areas_fill_the_free_area(replayed) -> None:
    building, _, _ = replayed
    for floor in building.program.floors:
        free = 240.0 - 18.0 - 9.0
        assert sum(r.area for r in floor.rooms) == pytest.approx(free, abs=0.1)  # type: ignore[union-attr]
        assert floor.rooms[0].id in ("lobby", "corridor")  # type: ignore[union-attr]


def test_malformed_answer_is_sent_back_with_its_errors(replayed) -> None:
    _, replay, _ = replayed
    retry = next(
        r for r in replay.requests
        if "Floor index 1" in json.dumps(r["messages"][0]) and len(r["messages"]) == 3
    )
    assert retry["messages"][1]["role"] == "assistant" and "```json" in retry["messages"][1]["content"]
    feedback = retry["messages"][2]["content"]
    assert "could not be used" in feedback and "nodes.5.type" in feedback and "'main'" in feedback


def test_requests_carry_model_schema_and_preview_images(replayed, monkeypatch) -> None:
    _, replay, _ = replayed
    assert all(r["model"] == DEFAULT_MODEL for r in replay.requests)
    assert all(r["output_config"]["format"]["type"] == "json_schema" for r in replay.requests)
    images = [
        b for r in replay.requests for b in r["messages"][0]["content"]
        if isinstance(b, dict) and b.get("type") == "image"
    ]
    # The program sees the ground-floor outline; each seed round sees its parent region.
    assert len(images) == 3
    assert all(base64.b64decode(b["source"]["data"]).startswith(b"\x89PNG") for b in images)
    seed = next(r for r in replay.requests if "Parent room ID: lobby" in json.dumps(r["messages"][0]))
    text = seed["messages"][0]["content"][1]["text"]
    assert "x in [0, 20], y in [0, 12]" in text and "office_1, office_2, meeting, toilets" in text
    monkeypatch.setenv("MANSION_MODEL", "claude-opus-5-5")
    assert LLMClient(Replay().client()).model == "claude-opus-5-5"


# -- errors -------------------------------------------------------------------------------------


def test_still_invalid_after_every_attempt_is_a_planner_error() -> None:
    replay = Replay(overrides={"program": message("I would suggest a lovely office.")})
    with pytest.raises(PlannerError, match=r"building_program answer was still invalid after 2 attempts.*no JSON object"):
        _planner(replay, attempts=2).plan_program(DESCRIPTION, Constraints(floors=2), random.Random(0))
    assert replay.served == ["program", "program"]


def test_api_failures_and_refusals_are_planner_errors(monkeypatch) -> None:
    error = httpx2.Response(401, json={"type": "error", "error": {"type": "authentication_error", "message": "invalid x-api-key"}})
    with pytest.raises(PlannerError, match="HTTP 401.*invalid x-api-key"):
        _planner(Replay(overrides={"program": error})).plan_program(DESCRIPTION, Constraints(floors=2), random.Random(0))
    refusal = message("", stop_reason="refusal")
    with pytest.raises(PlannerError, match="declined the building_program request"):
        _planner(Replay(overrides={"program": refusal})).plan_program(DESCRIPTION, Constraints(floors=2), random.Random(0))
    monkeypatch.delenv("ANTHROPIC_API_KEY", raising=False)
    with pytest.raises(PlannerError, match="set ANTHROPIC_API_KEY"):
        LLMClient()


def test_truncated_answer_is_retried() -> None:
    replay = Replay(overrides={"program.attempt1": message('{"building_type": "off', stop_reason="max_tokens")})
    program, _ = _planner(replay).plan_program(
        DESCRIPTION, Constraints(floors=2, outline=(OUTLINE, [])), random.Random(0)
    )
    assert program.floor_count == 2 and replay.served == ["program.attempt1", "program"]
    assert "cut off" in replay.requests[1]["messages"][2]["content"]


# -- the checks behind each agent ---------------------------------------------------------------


def test_program_checks_name_what_is_wrong() -> None:
    frame = _frame()
    good = _answer("program")
    bad = json.loads(json.dumps(good))
    bad["floors"][1] = {"index": 1, "copy": 1}
    bad["floors"][0]["rooms"][1]["id"] = "stair_1"
    bad["vertical_connectivity"]["method"] = "stair"
    with pytest.raises(AnswerRejected) as info:
        program_from_answer(ProgramAnswer.model_validate(bad), frame, random.Random(0))
    text = str(info.value)
    assert "floor 1 copies floor 1" in text and "['stair_1'] are core ids" in text and "method stair" in text
    big = json.loads(json.dumps(good))
    big["floors"][0]["rooms"][1]["area_estimate"] = 400
    with pytest.raises(AnswerRejected, match="floor 0: the rooms add up to 550 m2 but the free area"):
        program_from_answer(ProgramAnswer.model_validate(big), frame, random.Random(0))
    short = json.loads(json.dumps(good))
    short["floors"] = short["floors"][:1]
    with pytest.raises(AnswerRejected, match="exactly 2 floors"):
        program_from_answer(ProgramAnswer.model_validate(short), frame, random.Random(0))


def test_topology_checks_cores_and_reachability(replayed) -> None:
    building, _, _ = replayed
    program = building.program
    answer = _answer("topology_floor0")
    through_core = json.loads(json.dumps(answer))
    through_core["edges"] = [e for e in through_core["edges"] if e["target"] != "toilets"]
    through_core["edges"].append({"source": "stair_1", "target": "toilets", "kind": "access"})
    with pytest.raises(AnswerRejected, match=r"\['toilets'\] are not reached from the hub 'lobby'"):
        graph_from_answer(TopologyAnswer.model_validate(through_core), program, 0)
    stray = json.loads(json.dumps(answer))
    stray["nodes"][1]["id"] = "stair_9"
    stray["edges"][0]["target"] = "stair_9"
    with pytest.raises(AnswerRejected) as info:
        graph_from_answer(TopologyAnswer.model_validate(stray), program, 0)
    assert "core 'stair_1' (stair) serves this floor" in str(info.value) and "['stair_9']" in str(info.value)
    graph = graph_from_answer(TopologyAnswer.model_validate(answer), program, 0)
    assert graph.node("stair_1").area == 18.0 and graph.hub.open_relation == "open"


def test_seed_checks_and_clipping() -> None:
    request = SeedRequest.model_validate({
        "round": 0, "parent": "lobby", "cell_size": 0.5,
        "region": {"polygon": [(0, 0), (10, 0), (10, 8), (0, 8)], "area": 80.0, "cells": 320},
        "layout": {"rooms": []},
        "children": [
            {"id": "a", "room_type": "office", "target_area": 20, "own_area": 20},
            {"id": "b", "room_type": "office", "target_area": 20, "own_area": 20},
        ],
    })
    ok = SeedAnswer.model_validate({"seeds": [
        {"room_id": "a", "x": [-3, 4], "y": [0, 4], "area": 0.25},
        {"room_id": "b", "x": [6, 10], "y": [4, 8], "area": 0.25},
    ]})
    plan = plan_from_answer(ok, request)
    assert plan.seeds["a"].box is not None and plan.seeds["a"].box.x == (0.0, 4.0)
    assert plan.seeds["b"].fraction == 0.25
    bad = SeedAnswer.model_validate({"seeds": [
        {"room_id": "a", "x": [30, 40], "y": [0, 4], "area": 0.7},
        {"room_id": "c", "x": [0, 1], "y": [0, 1]},
        {"room_id": "a", "x": [0, 1], "y": [0, 1], "area": 0.6},
    ]})
    with pytest.raises(AnswerRejected) as info:
        plan_from_answer(bad, request)
    text = str(info.value)
    assert "['c'] are not target rooms" in text and "no box for ['b']" in text
    assert "['a'] have more than one box" in text and "lies outside the parent region" in text


# -- the command line ---------------------------------------------------------------------------


def test_cli_generate_with_the_anthropic_planner(tmp_path, monkeypatch) -> None:
    from mansion.cli import app

    replay = Replay()
    monkeypatch.setitem(planner_module.PLANNERS, "anthropic", lambda: _planner(replay))
    footprint = tmp_path / "fp.json"
    footprint.write_text(Footprint(polygon=OUTLINE).model_dump_json())
    out = tmp_path / "out"
    result = CliRunner().invoke(app, [
        "generate", DESCRIPTION, "--floors", "2", "--footprint", str(footprint),
        "--planner", "anthropic", "--out", str(out),
    ])
    assert result.exit_code == 0, result.output
    building = Building.load(out / "building.json")
    assert building.planner == "anthropic" and (out / "floor_1.png").exists()
