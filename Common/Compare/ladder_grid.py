#!/usr/bin/env python3
"""Draws the ladder figure of `ray-tracing-gpu --compare --spp-list ... --output GRID.png` (the thesis' Tables
5.1-5.3, the CPU's and the GPU's images side by side, redone with their errors): the reference, then for each
engine x strategy of the comparison a row of its images at every spp of the ladder (sRGB-encoded as the app's
PNGs), each captioned with its time and relMSE, and under that row the false-colour per-pixel relative squared
error (I - R)^2 / (R^2 + epsilon), averaged over RGB, on one logarithmic scale. Of several seeds, the first's.

    ladder_grid.py IMAGES.json GRID.png

IMAGES.json: the index of --compare's --images folder (Compare/ImageFolder.h); its paths are relative to it.
The figure is at most max_pixels (6000) wide: a long ladder of large images is drawn smaller, never cropped.
"""
import json
import os
import sys
from collections import OrderedDict

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402

from equal_time_grid import read_pfm, srgb  # noqa: E402

def main(index_path, png_path, max_pixels=6000):
    index = json.load(open(index_path))
    folder = os.path.dirname(os.path.abspath(index_path))
    if "reference" not in index or not index["images"]:
        sys.exit(f"{index_path}: no reference or no image to draw")
    reference = read_pfm(os.path.join(folder, index["reference"]["path"]))
    epsilon = index.get("epsilon", 1e-2)
    devices = index.get("devices", {})
    # One row per engine x strategy, in the comparison's order; one column per spp; the first seed's image.
    series = OrderedDict()
    for image in index["images"]:
        row = series.setdefault((image["engine"], image["label"]), OrderedDict())
        if image["spp"] not in row:
            row[image["spp"]] = image
    # The CPU engines before the GPU, as the thesis' tables put them.
    order = {"single": 0, "multi": 1, "gpu": 2}
    series = OrderedDict(sorted(series.items(), key=lambda item: order.get(item[0][0], 3)))
    spps = sorted({spp for row in series.values() for spp in row})
    columns = len(spps) + 1
    height, width = reference.shape[:2]
    tile_inches = 2.4
    fig_width = tile_inches * columns + 1.0
    fig, axes = plt.subplots(2 * len(series), columns, squeeze=False, layout="constrained",
                             figsize=(fig_width, 2 * len(series) * (tile_inches * height / width + 0.55) + 0.6))
    for axis in axes.flat:
        axis.set_xticks([])
        axis.set_yticks([])
        axis.set_frame_on(False)
    reference_text = f'{index["reference"]["spp"]} spp' if index["reference"].get("spp") else "given"
    axes[0][0].imshow(srgb(reference), interpolation="nearest")
    axes[0][0].set_title(f"reference ({reference_text})", fontsize=9)
    norm = LogNorm(vmin=1e-4, vmax=1e1)
    shown = None
    for r, ((engine, label), row) in enumerate(series.items()):
        name = f"{engine}: {devices[engine]}" if engine in devices else engine
        axes[2 * r][1].set_ylabel(f"{name}\n{label}", fontsize=8)
        for c, spp in enumerate(spps, start=1):
            if spp not in row:
                continue
            tile = row[spp]
            image = read_pfm(os.path.join(folder, tile["path"]))
            error = ((image - reference) ** 2 / (reference ** 2 + epsilon)).mean(axis=2)
            axes[2 * r][c].imshow(srgb(image), interpolation="nearest")
            ms = f"{tile['ms']:,.0f}" if tile["ms"] >= 100 else f"{tile['ms']:.3g}"
            axes[2 * r][c].set_title(f"{spp} spp, {ms} ms", fontsize=8)
            shown = axes[2 * r + 1][c].imshow(np.maximum(error, 1e-12), norm=norm, cmap="inferno",
                                              interpolation="nearest")
            axes[2 * r + 1][c].set_xlabel(f"relMSE {tile['relmse']:.3g}", fontsize=8)
    if shown is not None:
        fig.colorbar(shown, ax=axes[:, -1], orientation="vertical", shrink=0.6,
                     label="relative squared error")
    fig.suptitle(f'{index["scene"]}, {width}x{height}: each engine x strategy at every spp, and its error',
                 fontsize=10)
    dpi = max(50, min(int(round(width / tile_inches)), int(max_pixels / fig_width)))
    fig.savefig(png_path, dpi=dpi, format="png")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
