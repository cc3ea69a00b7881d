"""The building stage: plan, solve every floor, carry load-bearing walls, check, draw."""

from mansion.building.checks import check_building
from mansion.building.generate import generate_building
from mansion.building.render import plot_building, plot_floors

__all__ = ["check_building", "generate_building", "plot_building", "plot_floors"]
