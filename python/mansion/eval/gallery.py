"""Pictures of evaluated plans: ground truth beside prediction, coloured by room type."""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import numpy.typing as npt

__all__ = ["plot_comparison"]

# Class 0 (outside) is white; room types get distinct, print-friendly colours.
_PALETTE = [
    "#ffffff", "#e6c36a", "#8fb8de", "#e3826f", "#9ad1c5", "#c7a0d9",
    "#a9c98b", "#f2b5d4", "#b8b8b8", "#d9a66c", "#7fa3a3", "#f0e68c",
]


def plot_comparison(
    gt: npt.ArrayLike,
    pred: npt.ArrayLike,
    classes: Sequence[str],
    path: str | os.PathLike[str],
    *,
    title: str = "",
) -> Path:
    """Write a PNG with the ground-truth and predicted class maps side by side, with a legend."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch

    g = np.asarray(gt)
    p = np.asarray(pred)
    colours = [_PALETTE[i % len(_PALETTE)] for i in range(len(classes))]
    cmap = ListedColormap(colours)
    fig, axes = plt.subplots(1, 2, figsize=(8, 4.4))
    for ax, data, name in ((axes[0], g, "ground truth"), (axes[1], p, "prediction")):
        ax.imshow(data, cmap=cmap, vmin=0, vmax=len(classes) - 1, interpolation="nearest")
        ax.set_title(name, fontsize=10)
        ax.set_xticks([])
        ax.set_yticks([])
    present = sorted(set(np.unique(g)) | set(np.unique(p)) - {0})
    handles = [Patch(color=colours[k], label=classes[k]) for k in present if k != 0]
    fig.legend(handles=handles, loc="lower center", ncol=min(5, max(1, len(handles))), fontsize=8)
    if title:
        fig.suptitle(title, fontsize=11)
    fig.tight_layout(rect=(0, 0.08, 1, 1))
    out = Path(path)
    out.parent.mkdir(parents=True, exist_ok=True)
    tmp = out.with_name(f".{out.name}.tmp")
    fig.savefig(tmp, dpi=80, format="png")
    plt.close(fig)
    os.replace(tmp, out)
    return out
