"""The dataset stage: MansionWorld-scale datasets of generated buildings (``mansion dataset``),
on worker processes of one machine or on a Ray cluster, resumable, with an index, a summary
and the paper's statistics picture."""

from mansion.dataset.job import JobSettings, run_job
from mansion.dataset.mix import CATEGORIES, BuildingSpec, building_spec, parse_floors, parse_mix
from mansion.dataset.run import DEFAULT_MIX, DatasetSettings, dataset_specs, make_dataset
from mansion.dataset.statistics import plot_statistics

__all__ = [
    "CATEGORIES",
    "DEFAULT_MIX",
    "BuildingSpec",
    "DatasetSettings",
    "JobSettings",
    "building_spec",
    "dataset_specs",
    "make_dataset",
    "parse_floors",
    "parse_mix",
    "plot_statistics",
    "run_job",
]
