"""Measuring the solver on real floor plans: the T2D protocol, IoU scores, weight search."""

from mansion.eval.floorplan import EvalReport, PlanResult, evaluate_floorplans, solve_plan, write_gallery
from mansion.eval.iou import PlanIoU, plan_iou
from mansion.eval.t2d import T2DPlan, protocol_inputs
from mansion.eval.tune import TuneReport, tune_weights

__all__ = [
    "EvalReport",
    "PlanIoU",
    "PlanResult",
    "T2DPlan",
    "TuneReport",
    "evaluate_floorplans",
    "plan_iou",
    "protocol_inputs",
    "solve_plan",
    "tune_weights",
    "write_gallery",
]
