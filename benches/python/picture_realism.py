"""The README's before/after picture of issue 14: one description, the same seed, laid out without
width rules (``min_width=None``: the solver as the paper describes it) and with the generator's
defaults (1.5 m floor-wide clear width, rooms' widths from the design table, no one-cell necks).

    python benches/python/picture_realism.py [--out docs/realism_before_after.png]
"""

from __future__ import annotations

import argparse

from matplotlib.figure import Figure

from mansion.building import generate_building
from mansion.plot import draw_layout, layout_bounds, save_figure

DESCRIPTION = "a two-storey hotel"
SEED = 12
FLOOR = 1


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="docs/realism_before_after.png")
    args = ap.parse_args()
    panels = []
    for label, width in (("without width rules", None), ("with the width rules (default)", 1.5)):
        b = generate_building(DESCRIPTION, building_type="hotel", floors=2, seed=SEED, min_width=width)
        panels.append((label, b.floors[FLOOR].layout))
    boxes = [layout_bounds(layout) for _, layout in panels]
    bounds = (min(b[0] for b in boxes), min(b[1] for b in boxes), max(b[2] for b in boxes), max(b[3] for b in boxes))
    width = bounds[2] - bounds[0]
    fig = Figure(figsize=(16, 16 * (bounds[3] - bounds[1]) / (2 * width) + 1.2))
    for k, (label, layout) in enumerate(panels):
        ax = fig.add_subplot(1, 2, k + 1)
        draw_layout(ax, layout, 72.0 * 0.85 * 8 / width, title=f'"{DESCRIPTION}", seed {SEED}, floor {FLOOR}: {label}',
                    bounds=bounds)
    fig.tight_layout()
    print(save_figure(fig, args.out))


if __name__ == "__main__":
    main()
