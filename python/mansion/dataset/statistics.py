"""The dataset's statistics picture, as the paper draws MansionWorld's: what the buildings are
(types within the residential / office / public mix), their functional composition (room area by
function within each category) and the floor-area distribution by floor count."""

from __future__ import annotations

import os
from collections import Counter, defaultdict
from pathlib import Path
from typing import Any

from mansion.dataset.mix import CATEGORIES

__all__ = ["plot_statistics"]

_CATEGORY_COLOURS = {"residential": "#4C72B0", "office": "#DD8452", "public": "#55A868"}

#: Functions in drawing order (the vocabulary's roles, cores last); others follow by name.
_FUNCTION_ORDER = (
    "living", "bedroom", "kitchen", "wet", "work", "learning", "clinical", "retail", "public",
    "sport", "service", "circulation", "core",
)


def _functions(records: list[dict[str, Any]]) -> list[str]:
    seen = {f for r in records for f in r.get("functions", {})}
    return [f for f in _FUNCTION_ORDER if f in seen] + sorted(seen - set(_FUNCTION_ORDER))


def plot_statistics(
    records: list[dict[str, Any]], path: str | os.PathLike[str], *, max_floor_area: float | None = None
) -> Path:
    """Draw the statistics of the buildings ``records`` (their ``record.json`` contents) to a PNG;
    ``max_floor_area`` draws the cap on the floor-area panel."""
    from matplotlib import colormaps
    from matplotlib.figure import Figure

    from mansion.plot import save_figure

    fig = Figure(figsize=(16, 5.2))
    types_ax, comp_ax, area_ax = fig.subplots(1, 3, gridspec_kw={"width_ratios": [1.1, 1.2, 1.3]})
    categories = [c for c in CATEGORIES if any(r["category"] == c for r in records)]

    # (a) building types, coloured by category
    counts = Counter((r["category"], r["type"]) for r in records)
    rows = sorted(counts, key=lambda k: (list(CATEGORIES).index(k[0]), -counts[k], k[1]))
    ys = range(len(rows))
    types_ax.barh(
        list(ys), [counts[k] for k in rows], color=[_CATEGORY_COLOURS[k[0]] for k in rows]
    )
    types_ax.set_yticks(list(ys), [k[1].replace("_", " ") for k in rows])
    types_ax.invert_yaxis()
    types_ax.set_xlabel("buildings")
    share = Counter(r["category"] for r in records)
    n = max(1, len(records))
    types_ax.set_title(
        "building types: " + ", ".join(f"{c} {100 * share[c] / n:.0f} %" for c in categories),
        fontsize=10,
    )

    # (b) functional composition: share of room area by function, per category
    functions = _functions(records)
    cmap = colormaps["tab20"]
    area: dict[str, Counter[str]] = defaultdict(Counter)
    for r in records:
        area[r["category"]].update(r.get("functions", {}))
    left = [0.0] * len(categories)
    for i, name in enumerate(functions):
        widths = [
            100 * area[c][name] / max(sum(area[c].values()), 1e-9) for c in categories
        ]
        comp_ax.barh(categories, widths, left=left, color=cmap(i % 20), label=name)
        left = [a + b for a, b in zip(left, widths, strict=True)]
    comp_ax.invert_yaxis()
    comp_ax.set_xlim(0, 100)
    comp_ax.set_xlabel("share of room area (%)")
    comp_ax.set_title("functional composition", fontsize=10)
    if functions:
        comp_ax.legend(fontsize=7, ncols=4, loc="upper center", bbox_to_anchor=(0.5, -0.14), frameon=False)

    # (c) floor area (largest floor) by floor count
    by_floors: dict[int, list[float]] = defaultdict(list)
    for r in records:
        by_floors[r["floors"]].append(r["floor_area"])
    keys = sorted(by_floors)
    if keys:
        area_ax.boxplot([by_floors[k] for k in keys], positions=keys, widths=0.6)
        for k in keys:
            area_ax.annotate(
                f"n={len(by_floors[k])}", (k, 0), xycoords=("data", "axes fraction"),
                xytext=(0, 3), textcoords="offset points", ha="center", fontsize=7,
            )
    if max_floor_area is not None:
        area_ax.axhline(max_floor_area, color="grey", linestyle="--", linewidth=1)
    area_ax.set_xlabel("floors")
    area_ax.set_ylabel("floor area (m², largest floor)")
    area_ax.set_title("floor area by floor count", fontsize=10)
    fig.suptitle(f"{len(records)} buildings, {sum(r['floors'] for r in records)} floors")
    fig.tight_layout()
    return save_figure(fig, path)
