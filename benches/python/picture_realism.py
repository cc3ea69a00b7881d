"""The README's before/after picture of issue 14: one description, the same seed, laid out without
width rules (``min_width=None``: the solver as the paper describes it) and with the generator's
defaults (1.5 m floor-wide clear width, rooms' widths from the design table, no one-cell necks).

    python benches/python/picture_realism.py [--out docs/realism_before_after.png]

With ``--banks`` the two panels are a floor laid out by the cut rounds and as banks
(``steps.BANKS``, :mod:`mansion.building.banks`), both with the default widths:

    python benches/python/picture_realism.py --banks --description "a 5-storey hotel" \
        --type hotel --floors 5 --seed 12 --floor 1 --out docs/hotel_banks.png
"""

from __future__ import annotations

import argparse

from matplotlib.figure import Figure

from mansion.building import generate_building, steps
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
    ap.add_argument("--banks", action="store_true", help="cut rounds against banks, not widths")
    args = ap.parse_args()
    panels = []
    cases = (
        (("laid out by the cut rounds", 1.5, False), ("as banks (default)", 1.5, True)) if args.banks
        else (("without width rules", None, True), ("with the width rules (default)", 1.5, True))
    )
    for label, width, banks in cases:
        steps.BANKS = banks
        b = generate_building(args.description, building_type=args.type, floors=args.floors, seed=args.seed,
                              min_width=width)
        panels.append((label, b.floors[args.floor].layout))
    steps.BANKS = True
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
