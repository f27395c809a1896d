#!/usr/bin/env python3
"""Draws the equal-time figure of `ray-tracing-gpu --compare --equal-time MS --output GRID.png`: the reference
and each strategy's image rendered in the same time (top row, sRGB-encoded as the app's PNGs are), each
labelled with its strategy, spp, time and relMSE, and under each a false-colour image of its per-pixel
relative squared error (I - R)^2 / (R^2 + epsilon), averaged over RGB, on one logarithmic scale.

    equal_time_grid.py TILES.json GRID.png

TILES.json: {"scene", "device", "budget_ms", "epsilon", "reference": {"path", "spp"},
             "tiles": [{"label", "spp", "ms", "relmse", "path"}]}; paths are linear PFMs.
"""
import json
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402


def read_pfm(path):
    with open(path, "rb") as f:
        kind = f.readline().strip()
        if kind != b"PF":
            raise SystemExit(f"{path}: not an RGB PFM")
        width, height = (int(v) for v in f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4", count=width * height * 3)
    return np.flipud(data.reshape(height, width, 3)).astype(np.float64)  # PFM rows run bottom to top


def srgb(linear):
    x = np.clip(linear, 0.0, 1.0)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1.0 / 2.4) - 0.055)


def main(tiles_path, png_path):
    meta = json.load(open(tiles_path))
    reference = read_pfm(meta["reference"]["path"])
    tiles = meta["tiles"]
    epsilon = meta.get("epsilon", 1e-2)
    columns = len(tiles) + 1
    height, width = reference.shape[:2]
    tile_inches = 2.6
    fig, axes = plt.subplots(2, columns, figsize=(tile_inches * columns + 0.8, 2 * tile_inches * height / width + 1.4),
                             squeeze=False, layout="constrained")
    for axis in axes.flat:
        axis.set_xticks([])
        axis.set_yticks([])
    axes[0][0].imshow(srgb(reference), interpolation="nearest")
    axes[0][0].set_title("reference", fontsize=9)
    axes[0][0].set_xlabel(f'{meta["reference"]["spp"]} spp', fontsize=8)
    axes[1][0].axis("off")
    norm = LogNorm(vmin=1e-4, vmax=1e1)
    shown = None
    for i, tile in enumerate(tiles, start=1):
        image = read_pfm(tile["path"])
        error = ((image - reference) ** 2 / (reference ** 2 + epsilon)).mean(axis=2)
        axes[0][i].imshow(srgb(image), interpolation="nearest")
        axes[0][i].set_title(tile["label"], fontsize=9)
        axes[0][i].set_xlabel(f'{tile["spp"]} spp, {tile["ms"]:.0f} ms\nrelMSE {tile["relmse"]:.3g}', fontsize=8)
        shown = axes[1][i].imshow(np.maximum(error, 1e-12), norm=norm, cmap="inferno", interpolation="nearest")
        axes[1][i].set_xlabel("relative squared error", fontsize=8)
    if shown is not None:
        fig.colorbar(shown, ax=axes[:, -1], orientation="vertical", shrink=0.8)
    fig.suptitle(f'{meta["scene"]}: each strategy given {meta["budget_ms"]:.0f} ms on {meta["device"]}',
                 fontsize=10)
    fig.savefig(png_path, dpi=max(100, int(round(width / tile_inches))), format="png")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
