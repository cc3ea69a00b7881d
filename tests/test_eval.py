"""The T2D evaluation: IoU arithmetic, the protocol's inputs and frames, end-to-end runs on
synthetic plans, the weight search and the CLI."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from mansion import EnergyWeights, InvalidInputError
from mansion.cli import app
from mansion.eval import T2DPlan, evaluate_floorplans, plan_iou, protocol_inputs, solve_plan, tune_weights
from mansion.eval.t2d import GRID, solver_to_mask
from synthetic_plans import make_plan, write_plans

# -- IoU arithmetic -------------------------------------------------------------------------------


def test_iou_of_identical_maps_is_one() -> None:
    gt = np.array([[0, 1, 1], [2, 2, 3]])
    assert plan_iou(gt, gt) == (1.0, 1.0)


def test_iou_by_hand() -> None:
    gt = np.array([[1, 1, 2, 2], [1, 1, 2, 2], [0, 0, 0, 0]])
    pred = np.array([[1, 1, 1, 2], [1, 1, 1, 2], [0, 0, 0, 0]])
    # class 1: inter 4, union 6; class 2: inter 2, union 4
    micro, macro = plan_iou(pred, gt)
    assert micro == pytest.approx(6 / 10)
    assert macro == pytest.approx((4 / 6 + 2 / 4) / 2)


def test_iou_counts_classes_present_in_either_map() -> None:
    gt = np.array([[1, 1], [1, 1]])
    pred = np.array([[1, 1], [1, 3]])
    # class 1: 3/4; class 3 (only predicted): 0/1
    micro, macro = plan_iou(pred, gt)
    assert micro == pytest.approx(3 / 5)
    assert macro == pytest.approx((3 / 4 + 0.0) / 2)


def test_iou_ignores_outside_and_merges_same_type_rooms() -> None:
    gt = np.array([[0, 2, 2], [0, 2, 2]])  # two rooms of type 2 side by side count as one class
    pred = np.array([[2, 2, 2], [0, 2, 2]])  # an outside cell predicted as a room hurts class 2
    micro, macro = plan_iou(pred, gt)
    assert micro == pytest.approx(4 / 5) and macro == pytest.approx(4 / 5)


def test_iou_rejects_mismatched_maps() -> None:
    with pytest.raises(InvalidInputError, match="shape"):
        plan_iou(np.zeros((2, 2)), np.zeros((3, 3)))


# -- the protocol ------------------------------------------------------------------------------


def test_protocol_inputs_and_frames() -> None:
    plan = T2DPlan.model_validate(make_plan(3))
    inputs = protocol_inputs(plan)
    labels = plan.label_array()
    free = int((labels != 0).sum())
    # targets: area shares of the free cells (1 m = 1 cell)
    assert sum(n.area for n in inputs.graph.nodes) == pytest.approx(free)
    assert inputs.footprint.area == pytest.approx(free)
    assert [n.id for n in inputs.graph.nodes if n.type == "main"] == ["living_room_0"]
    # every seed lies in its own room: mask (row r, col c) ↔ solver point (c + .5, 64 − r − .5)
    for room in plan.rooms:
        x, y = inputs.seeds[f"{room.type}_{room.id}"]
        r, c = int(GRID - y), int(x)
        assert labels[r, c] == plan.classes.index(room.type)


def test_the_solver_sees_only_what_the_protocol_allows() -> None:
    raw = make_plan(5)
    blank = json.loads(json.dumps(raw))
    blank["footprint"] = blank["outer_footprint"] = blank["front_door"] = None
    for room in blank["rooms"]:
        room["polygon"] = None
        room["bbox"] = None
    # the label map only as its free mask: any room class will do
    blank["label64"] = [[1 if v else 0 for v in row] for row in raw["label64"]]
    a, _ = solve_plan(T2DPlan.model_validate(raw))
    b, _ = solve_plan(T2DPlan.model_validate(blank))
    assert np.array_equal(a, b)


def test_prediction_maps_back_onto_the_free_mask() -> None:
    plan = T2DPlan.model_validate(make_plan(8))
    pred, layout = solve_plan(plan)
    assert np.array_equal(pred != 0, plan.label_array() != 0)
    inputs = protocol_inputs(plan)
    assert np.array_equal(solver_to_mask(layout.grid, inputs.classes), pred)


def test_bad_plans_are_named() -> None:
    raw = make_plan(1)
    raw["adjacency"].append([0, 99])
    with pytest.raises(Exception, match="unknown room 99"):
        T2DPlan.model_validate(raw)
    raw = make_plan(1)
    raw["rooms"][0]["type"] = "kitchen"
    with pytest.raises(Exception, match="exactly one living_room"):
        T2DPlan.model_validate(raw)


# -- end to end ------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def plans_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return write_plans(tmp_path_factory.mktemp("t2d"), range(8))


@pytest.mark.parametrize("mode", ["hierarchical", "flat"])
def test_evaluation_reproduces_synthetic_plans(plans_dir: Path, mode: str) -> None:
    report = evaluate_floorplans(plans_dir, mode=mode, workers=1)  # type: ignore[arg-type]
    assert report.plans == 8 and report.failures == 0
    # rectangles seeded at their centroids with exact areas: the solver should get them nearly right
    assert report.micro > 80 and report.macro > 75
    assert all(0 <= p.micro <= 100 and not p.failed for p in report.per_plan)
    assert report.micro == pytest.approx(sum(p.micro for p in report.per_plan) / 8)


def test_worker_count_does_not_change_scores(plans_dir: Path) -> None:
    one = evaluate_floorplans(plans_dir, limit=4, workers=1)
    two = evaluate_floorplans(plans_dir, limit=4, workers=2)
    assert [(p.id, p.micro, p.macro) for p in one.per_plan] == [(p.id, p.micro, p.macro) for p in two.per_plan]


def test_weight_search_writes_weights_the_eval_accepts(plans_dir: Path, tmp_path: Path) -> None:
    result = tune_weights(plans_dir, samples=2, refine=2, seed=1, workers=1)
    assert len(result.trials) == 5 and result.trials[0].weights == EnergyWeights()
    assert result.even[2] == 4 and result.odd[2] == 4 and result.all[2] == 8
    best = max(result.trials, key=lambda t: t.objective)
    assert result.best == best.weights
    for trial in result.trials[1:]:  # samples of the simplex, scaled to one total
        assert sum(trial.weights.model_dump().values()) == pytest.approx(20.0, abs=0.01)
    path = result.best.save(tmp_path / "w.json")
    report = evaluate_floorplans(plans_dir, limit=2, weights=EnergyWeights.load(path), workers=1)
    assert report.weights == result.best


def test_cli_eval_writes_json_and_gallery(plans_dir: Path, tmp_path: Path) -> None:
    out = tmp_path / "scores.json"
    gallery = tmp_path / "gallery"
    res = CliRunner().invoke(
        app,
        ["eval", "floorplan", "--data", str(plans_dir), "--limit", "3", "--json", str(out),
         "--gallery", str(gallery), "--workers", "1"],
    )
    assert res.exit_code == 0, res.output
    assert "micro-IoU" in res.output and "3 plans" in res.output
    data = json.loads(out.read_text())
    assert {"micro", "macro", "plans", "failures", "seconds", "per_plan", "fallbacks"} <= set(data)
    assert data["plans"] == 3 and len(data["per_plan"]) == 3
    # three plans: all of them are among the five worst, none is left for the best
    assert len(list(gallery.glob("worst_*.png"))) == 3 and not list(gallery.glob("best_*.png"))


def test_cli_tune_weights(plans_dir: Path, tmp_path: Path) -> None:
    out = tmp_path / "best.json"
    res = CliRunner().invoke(
        app, ["tune-weights", "--data", str(plans_dir), "--samples", "1", "--refine", "1", "--out", str(out),
         "--workers", "1"]
    )
    assert res.exit_code == 0, res.output
    assert "held-out odd ids" in res.output
    EnergyWeights.load(out)


def test_cli_eval_on_a_missing_folder_fails_cleanly(tmp_path: Path) -> None:
    res = CliRunner().invoke(app, ["eval", "floorplan", "--data", str(tmp_path / "nope")])
    assert res.exit_code == 2
    assert "no T2D plans" in res.output


# -- seeds from the description (the paper's end-to-end setting), replayed through the SDK ------


def test_text_seeds_from_recorded_answers(plans_dir: Path) -> None:
    from llm_replay import Replay, message

    from mansion.agents.llm import LLMClient
    from mansion.eval.t2d import iter_plans

    overrides = {}
    for pid, plan in iter_plans(plans_dir, ["0", "1"]):
        (plans_dir / "text").mkdir(exist_ok=True)
        (plans_dir / "text" / f"{pid}.txt").write_text(f"Plan {pid}. The living room is in the middle.")
        # the model's answer: each room's true centre, nudged by half a cell (mask frame, y down)
        points = {f"{r.type}_{r.id}": (r.centroid[0] / 4 + 0.5, r.centroid[1] / 4 - 0.5) for r in plan.rooms}
        answer = {"rooms": [{"id": k, "x": x, "y": y, "reason": "from the text"} for k, (x, y) in points.items()]}
        overrides[f"t2d_{pid}"] = message(json.dumps(answer))
    # plan 1's first answer puts a room outside the interior: it is sent back with the problem
    bad = json.loads(overrides["t2d_1"]["content"][0]["text"])
    bad["rooms"][0]["x"], bad["rooms"][0]["y"] = 0.5, 0.5
    overrides["t2d_1.attempt1"] = message(json.dumps(bad))
    replay = Replay(overrides=overrides)
    report = evaluate_floorplans(
        plans_dir, ids=["0", "1"], seeds="anthropic", client=LLMClient(replay.client()), workers=1
    )
    assert report.failures == 0 and report.seeds == "anthropic"
    assert report.micro > 75
    assert replay.served == ["t2d_0", "t2d_1.attempt1", "t2d_1"]
    retry = replay.requests[2]["messages"][-1]["content"]
    assert "is not on a '#' cell" in (retry if isinstance(retry, str) else json.dumps(retry))
    # the seeds the solver used are in the report, in the solver's frame (y up)
    first = report.per_plan[0].seeds
    assert first is not None and set(first) == {n.id for n in protocol_inputs(next(iter_plans(plans_dir, ["0"]))[1]).graph.nodes}


def test_text_seeds_that_never_validate_fail_that_plan_only(plans_dir: Path) -> None:
    from llm_replay import Replay, message

    from mansion.agents.llm import LLMClient

    for pid in ("2", "3"):
        (plans_dir / "text").mkdir(exist_ok=True)
        (plans_dir / "text" / f"{pid}.txt").write_text(f"Plan {pid}. Two bedrooms.")
    replay = Replay(overrides={"t2d_2": message('{"rooms": [{"id": "nobody", "x": 1, "y": 1}]}'),
                               "t2d_3": message("not json at all")})
    report = evaluate_floorplans(
        plans_dir, ids=["2", "3"], seeds="anthropic", client=LLMClient(replay.client(), attempts=2), workers=1
    )
    assert report.failures == 2 and report.micro == 0.0
    assert all("seed planning failed" in (p.error or "") for p in report.per_plan)
