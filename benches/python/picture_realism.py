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

DESCRIPTION = "a three-storey office building"
BUILDING_TYPE = "office"
FLOORS = 3
SEED = 3
FLOOR = 1


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="docs/realism_before_after.png")
    ap.add_argument("--description", default=DESCRIPTION)
    ap.add_argument("--type", default=BUILDING_TYPE, help="building type")
    ap.add_argument("--floors", type=int, default=FLOORS)
    ap.add_argument("--seed", type=int, default=SEED)
    ap.add_argument("--floor", type=int, default=FLOOR, help="which floor to draw")
    args = ap.parse_args()
    panels = []
    for label, width in (("without width rules", None), ("with the width rules (default)", 1.5)):
        b = generate_building(args.description, building_type=args.type, floors=args.floors, seed=args.seed,
                              min_width=width)
        panels.append((label, b.floors[args.floor].layout))
    boxes = [layout_bounds(layout) for _, layout in panels]
    bounds = (min(b[0] for b in boxes), min(b[1] for b in boxes), max(b[2] for b in boxes), max(b[3] for b in boxes))
    width = bounds[2] - bounds[0]
    fig = Figure(figsize=(16, 16 * (bounds[3] - bounds[1]) / (2 * width) + 1.2))
    for k, (label, layout) in enumerate(panels):
        ax = fig.add_subplot(1, 2, k + 1)
        draw_layout(ax, layout, 72.0 * 0.85 * 8 / width, title=f'"{args.description}", seed {args.seed}, floor {args.floor}: {label}',
                    bounds=bounds)
    fig.tight_layout()
    print(save_figure(fig, args.out))


if __name__ == "__main__":
    main()
