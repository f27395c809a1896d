#!/usr/bin/env python3
"""relMSE per plate x light region of Veach's MIS scene (Veach 1997, fig. 9.2), from --compare --images folders.

Regions come from the scene's geometry, not from the images: a camera ray through each pixel centre
(Common/Scene/Camera.cpp's pinhole) hits a plate or not; on a plate, the pixel belongs to the light whose
centre is nearest in angle to the mirror direction of the camera ray about the plate's normal, i.e. the
light whose highlight it shows. Each folder is one equal-time comparison (one seed); a region's relMSE is
Common/Image/Metrics.h's, (I - R)^2 / (R^2 + 0.01) averaged over its pixels and channels, scaled to the
budget by ms / budget (relMSE falls as 1 / time for these unbiased estimators) and averaged over the
seeds, with its standard error.

Usage: veach_regions.py --scene veach.json --budget-ms 1000 DIR [DIR ...] [--json OUT.json]
       [--markdown OUT.md] [--figure OUT.png] [--grid OUT.png]
       veach_regions.py --scene veach.json --result OUT.json DIR --figure OUT.png --grid OUT.png
The scene file is `--export-scene`'s; every DIR holds images.json and the PFMs of `--compare --images DIR`.
--result draws the figures of an earlier analysis (its JSON) from the first DIR's images (the reference and
the regions in the first figure; the equal-time grid of Common/Compare/equal_time_grid.py in the second).
"""
import argparse
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

EPSILON = 0.01  # Common/Image/Metrics.h's kRelMseEpsilon


def read_pfm(path):
    """A colour PFM as float64 rows top first (the writer, Common/Image/ImageIO.cpp, stores the bottom row
    first)."""
    with open(path, "rb") as f:
        if f.readline().strip() != b"PF":
            sys.exit(f"error: {path} is not a colour PFM")
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4", count=width * height * 3)
    return np.flipud(data.reshape(height, width, 3)).astype(np.float64)


def normalize(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def camera_rays(camera, width, height):
    """Unit directions (height, width, 3) through the pixel centres and the origin."""
    look_from = np.array(camera["look_from"], float)
    look_at = np.array(camera["look_at"], float)
    up = np.array(camera.get("up", [0.0, 1.0, 0.0]), float)
    h = math.tan(math.radians(camera["vfov"]) / 2.0)
    viewport_h = 2.0 * h
    viewport_w = viewport_h * width / height
    w = normalize(look_from - look_at)
    u = normalize(np.cross(up, w))
    v = np.cross(w, u)
    du = viewport_w * u / width
    dv = -viewport_h * v / height
    upper_left = look_from - w - 0.5 * width * du - 0.5 * height * dv
    x = np.arange(width) + 0.5
    y = np.arange(height) + 0.5
    targets = upper_left + x[None, :, None] * du + y[:, None, None] * dv
    return look_from, normalize(targets - look_from)


def shapes_of(scene):
    materials = scene["materials"]
    plates, lights, others = [], [], []
    for group in scene["groups"]:
        for s in group["shapes"]:
            m = materials[s["material"]]
            if s["type"] == "sphere" and m["type"] == "diffuse_light":
                lights.append(s)
            elif s["type"] == "quad" and m["type"] == "conductor":
                plates.append((s, m["alpha"][0]))
            else:
                others.append(s)
    if len(plates) != 4 or len(lights) != 4:
        sys.exit(f"error: expected Veach's 4 conductor plates and 4 sphere lights, found {len(plates)} and {len(lights)}")
    return plates, lights, others


def hit_quad(origin, d, quad):
    q, u, v = (np.array(quad[k], float) for k in ("q", "u", "v"))
    n = np.cross(u, v)
    denom = d @ n
    with np.errstate(divide="ignore", invalid="ignore"):
        t = ((q - origin) @ n) / denom
    p = origin + t[..., None] * d
    # The quad's own coordinates: p = q + a u + b v.
    w = n / (n @ n)
    rel = p - q
    a = np.cross(rel, v) @ w
    b = np.cross(u, rel) @ w
    inside = (np.abs(denom) > 1e-12) & (t > 1e-6) & (a >= 0) & (a <= 1) & (b >= 0) & (b <= 1)
    return np.where(inside, t, np.inf), normalize(n)


def hit_sphere(origin, d, sphere):
    c = np.array(sphere["center"], float)
    oc = origin - c
    b = d @ oc
    disc = b * b - (oc @ oc - sphere["radius"] ** 2)
    with np.errstate(invalid="ignore"):
        t = -b - np.sqrt(disc)
    return np.where((disc >= 0) & (t > 1e-6), t, np.inf)


def region_map(scene, width, height):
    """(height, width) int array: plate * 4 + light, or -1 off the plates; plates ordered by alpha (smoothest
    first), lights by radius (largest first)."""
    plates, lights, others = shapes_of(scene)
    plates.sort(key=lambda p: p[1])
    lights.sort(key=lambda s: -s["radius"])
    origin, d = camera_rays(scene["camera"], width, height)
    nearest = np.full((height, width), np.inf)
    which = np.full((height, width), -1)
    normals = []
    for i, (quad, _) in enumerate(plates):
        t, n = hit_quad(origin, d, quad)
        normals.append(n)
        closer = t < nearest
        nearest = np.where(closer, t, nearest)
        which = np.where(closer, i, which)
    for s in lights:
        t = hit_sphere(origin, d, s)
        which = np.where(t < nearest, -1, which)
        nearest = np.minimum(nearest, t)
    for s in others:
        if s["type"] == "quad":
            t, _ = hit_quad(origin, d, s)
            which = np.where(t < nearest, -1, which)
            nearest = np.minimum(nearest, t)
    regions = np.full((height, width), -1)
    for i, n in enumerate(normals):
        on = which == i
        p = origin + nearest[..., None] * d
        mirror = d - 2.0 * (d @ n)[..., None] * n
        cosines = np.stack([np.einsum("ijk,ijk->ij", mirror, normalize(np.array(s["center"], float) - p)) for s in lights], axis=-1)
        regions = np.where(on, i * 4 + np.argmax(cosines, axis=-1), regions)
    return regions, [p[1] for p in plates], [s["radius"] for s in lights]


def relmse_map(image, reference):
    return ((image - reference) ** 2 / (reference ** 2 + EPSILON)).mean(axis=-1)


def analyse(scene, folders, budget_ms):
    indexes = [json.loads((Path(f) / "images.json").read_text()) for f in folders]
    width, height = indexes[0]["width"], indexes[0]["height"]
    regions, alphas, radii = region_map(scene, width, height)
    labels = [img["label"] for img in indexes[0]["images"]]
    per_seed = {label: [] for label in labels}  # label -> [seed][region 0..15 then whole image]
    runs = {label: [] for label in labels}
    for folder, index in zip(folders, indexes):
        if (index["width"], index["height"]) != (width, height):
            sys.exit(f"error: {folder} is {index['width']}x{index['height']}, not {width}x{height}")
        reference = read_pfm(Path(folder) / index["reference"]["path"])
        for img in index["images"]:
            error = relmse_map(read_pfm(Path(folder) / img["path"]), reference)
            scale = img["ms"] / budget_ms
            values = [error[regions == r].mean() * scale for r in range(16)] + [error.mean() * scale]
            per_seed[img["label"]].append(values)
            runs[img["label"]].append({"spp": img["spp"], "ms": img["ms"]})
    stats = {}
    for label, rows in per_seed.items():
        a = np.array(rows)
        sem = a.std(axis=0, ddof=1) / math.sqrt(len(a)) if len(a) > 1 else np.full(a.shape[1], np.nan)
        stats[label] = {"mean": a.mean(axis=0).tolist(), "sem": sem.tolist()}
    pixels = [int((regions == r).sum()) for r in range(16)]
    return {"width": width, "height": height, "budget_ms": budget_ms, "seeds": len(folders),
            "alphas": alphas, "radii": radii, "pixels": pixels, "labels": labels, "runs": runs, "relmse": stats,
            "reference": indexes[0]["reference"]}, regions


def verdict(result, mis="nee-mis", rivals=("bsdf", "nee"), factor=1.2):
    """Per region nee-mis / min(rivals); the whole image's nee-mis against each rival."""
    stats = result["relmse"]
    ratios = []
    for r in range(16):
        best = min(stats[x]["mean"][r] for x in rivals)
        ratios.append(stats[mis]["mean"][r] / best)
    whole = stats[mis]["mean"][16]
    return {"ratios": ratios, "worst_ratio": max(ratios), "within": max(ratios) <= factor, "factor": factor,
            "beats_both": all(whole < stats[x]["mean"][16] for x in rivals)}


def markdown(result, check):
    stats = result["relmse"]
    labels = result["labels"]
    lines = ["| plate α | light radius | pixels | " + " | ".join(f"{l} relMSE" for l in labels) +
             " | nee-mis / best |", "|---|---|---:|" + "---:|" * len(labels) + "---:|"]
    for r in range(16):
        plate, light = divmod(r, 4)
        cells = [f"{stats[l]['mean'][r]:.3g} ± {stats[l]['sem'][r]:.2g}" for l in labels]
        lines.append(f"| {result['alphas'][plate]:g} | {result['radii'][light]:g} | {result['pixels'][r]} | " +
                     " | ".join(cells) + f" | {check['ratios'][r]:.2f} |")
    cells = [f"**{stats[l]['mean'][16]:.3g}** ± {stats[l]['sem'][16]:.2g}" for l in labels]
    lines.append("| whole image | | " + str(result["width"] * result["height"]) + " | " + " | ".join(cells) + " | |")
    return "\n".join(lines) + "\n"


def figure(path, result, check, regions, folder):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    index = json.loads((Path(folder) / "images.json").read_text())
    reference = read_pfm(Path(folder) / index["reference"]["path"])
    tone = np.clip(reference / (1.0 + reference), 0, 1) ** (1 / 2.2)
    fig, axes = plt.subplots(1, 2, figsize=(13, 4.6))
    axes[0].imshow(tone)
    boundaries = np.zeros(regions.shape, bool)
    boundaries[:-1] |= regions[:-1] != regions[1:]
    boundaries[:, :-1] |= regions[:, :-1] != regions[:, 1:]
    overlay = np.zeros(regions.shape + (4,))
    overlay[boundaries] = (1.0, 0.8, 0.0, 0.9)
    axes[0].imshow(overlay)
    for r in range(16):
        ys, xs = np.nonzero(regions == r)
        if len(xs):
            axes[0].text(xs.mean(), ys.mean(), f"{check['ratios'][r]:.2f}", color="white", fontsize=7,
                         ha="center", va="center", bbox=dict(facecolor="black", alpha=0.5, pad=1, linewidth=0))
    axes[0].set_title("reference, regions, nee-mis relMSE / best of bsdf and nee")
    axes[0].axis("off")
    stats = result["relmse"]
    x = np.arange(16)
    width = 0.8 / len(result["labels"])
    for k, label in enumerate(result["labels"]):
        axes[1].bar(x + k * width, stats[label]["mean"][:16], width, yerr=stats[label]["sem"][:16], label=label)
    axes[1].set_yscale("log")
    axes[1].set_xticks(x + 0.4 - width / 2)
    axes[1].set_xticklabels([f"α{result['alphas'][r // 4]:g}\nr{result['radii'][r % 4]:g}" for r in range(16)],
                            fontsize=6)
    axes[1].set_ylabel(f"relMSE at {result['budget_ms']:g} ms")
    axes[1].legend()
    axes[1].set_title(f"per plate x light region, mean of {result['seeds']} seeds (± standard error)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def grid(path, folder, budget_ms, device):
    """The equal-time figure of --compare --equal-time from the first folder's images."""
    folder = Path(folder).resolve()
    index = json.loads((folder / "images.json").read_text())
    meta = {"scene": index["scene"], "device": device, "budget_ms": budget_ms, "epsilon": EPSILON,
            "reference": {"path": str(folder / index["reference"]["path"]), "spp": index["reference"]["spp"]},
            "tiles": [{"label": f"{img['engine']} {img['label']}", "spp": img["spp"], "ms": img["ms"],
                       "relmse": img["relmse"], "path": str(folder / img["path"])} for img in index["images"]]}
    script = Path(__file__).resolve().parents[2] / "Common" / "Compare" / "equal_time_grid.py"
    with tempfile.NamedTemporaryFile("w", suffix=".json") as tiles:
        json.dump(meta, tiles)
        tiles.flush()
        subprocess.run([sys.executable, str(script), tiles.name, str(path)], check=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--scene", required=True, help="veach-mis as --export-scene writes it")
    parser.add_argument("--budget-ms", type=float, help="the --equal-time budget (needed unless --result)")
    parser.add_argument("--json")
    parser.add_argument("--markdown")
    parser.add_argument("--figure")
    parser.add_argument("--grid")
    parser.add_argument("--device", default="", help="the GPU, for the grid's title")
    parser.add_argument("--result", help="an earlier analysis' JSON: draw its figures, measure nothing")
    parser.add_argument("folders", nargs="+")
    args = parser.parse_args()
    scene = json.loads(Path(args.scene).read_text())
    if args.result:
        result = json.loads(Path(args.result).read_text())
        regions, _, _ = region_map(scene, result["width"], result["height"])
        if args.figure:
            figure(args.figure, result, result["verdict"], regions, args.folders[0])
        if args.grid:
            grid(args.grid, args.folders[0], result["budget_ms"], args.device)
        return
    result, regions = analyse(scene, args.folders, args.budget_ms)
    check = verdict(result)
    result["verdict"] = check
    table = markdown(result, check)
    print(table)
    print(f"nee-mis / best per region: worst {check['worst_ratio']:.2f} (within {check['factor']}x: "
          f"{check['within']}); beats both over the whole image: {check['beats_both']}")
    if args.json:
        Path(args.json).write_text(json.dumps(result, indent=1) + "\n")
    if args.markdown:
        Path(args.markdown).write_text(table)
    if args.figure:
        figure(args.figure, result, check, regions, args.folders[0])
    if args.grid:
        grid(args.grid, args.folders[0], args.budget_ms, args.device)


if __name__ == "__main__":
    main()
