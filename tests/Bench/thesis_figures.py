#!/usr/bin/env python3
"""The thesis' figures and Table 5.4 from the runs of tests/Bench/thesis_figures.sh, with the thesis' values
beside ours where the thesis printed them (Table 5.4, whose values figure 5.2 plots; figure 4.6 and Tables
5.1-5.3 are pictures only).

    thesis_figures.py OUT [SCRIPTS] [GRID_PIXELS]

OUT: thesis_figures.sh's folder (cpu-gpu.json, gpu.json, cores-N.json, images/). SCRIPTS: the apps' scripts
folder (<bin>/scripts, for ladder_grid.py; default: Common/Compare beside this script). GRID_PIXELS: the width
of the image tables' figure (default 6000: 600-px images at full size). Writes to OUT:
table-5.4.md, figure-5.2.png, figure-4.6.png, tables-5.1-5.3.png and thesis.json (every value of the table and
figures, for tests/Bench/results_page.py). Times: the GPU's from its timestamp queries (its wall time beside),
the CPU's from the host clock; each the median of the run's rounds.
"""
import glob
import json
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# Table 5.4 of the thesis (section 5.2): spp -> (CPU ms, GPU ms), on the thesis' machine (not named there; its
# section 4.3.4 renders on an Intel i9-14900HX, 32 threads).
THESIS_TABLE_5_4 = {
    10: (2000, 10), 50: (9000, 44), 100: (19000, 83), 250: (42000, 250), 500: (94000, 546),
    1000: (146000, 1092), 2000: (358000, 2310), 5000: (888000, 5730), 7500: (1313000, 7900),
    10000: (1617000, 11160), 15000: (2370000, 15800), 20000: (3311000, 20440),
}


def load(path):
    with open(path) as f:
        return json.load(f)


def gpu_ms(entry):
    return entry["gpu_ms"] if entry.get("gpu_ms", -1) >= 0 else entry["render_ms"]


def fmt_ms(value):
    if value is None:
        return "-"
    return f"{value:,.0f}" if value >= 100 else f"{value:.1f}"


def table_rows(out):
    both = load(os.path.join(out, "cpu-gpu.json"))
    gpu = load(os.path.join(out, "gpu.json"))
    cpu_by_spp = {r["spp"]: r["multi"] for r in both["rows"] if "multi" in r}
    gpu_by_spp = {r["spp"]: r["gpu"] for r in gpu["rows"]}
    rows = []
    for spp in sorted(set(cpu_by_spp) | set(gpu_by_spp) | set(THESIS_TABLE_5_4)):
        thesis_cpu, thesis_gpu = THESIS_TABLE_5_4.get(spp, (None, None))
        cpu = cpu_by_spp.get(spp)
        g = gpu_by_spp.get(spp)
        rows.append({
            "spp": spp,
            "thesis_cpu_ms": thesis_cpu,
            "thesis_gpu_ms": thesis_gpu,
            "cpu_ms": cpu["render_ms"] if cpu else None,
            "cpu_relmse": cpu["relmse"] if cpu else None,
            "gpu_ms": gpu_ms(g) if g else None,
            "gpu_wall_ms": g["render_ms"] if g else None,
            "gpu_relmse": g["relmse"] if g else None,
        })
    devices = dict(both.get("devices", {}))
    devices.update(gpu.get("devices", {}))
    return rows, devices, both


def markdown_table(rows, devices):
    cpu_name = devices.get("multi", "CPU")
    gpu_name = devices.get("gpu", "GPU")
    lines = [
        f"| spp | CPU ms, thesis | CPU ms, ours | thesis / ours | GPU ms, thesis | GPU ms, ours | GPU wall ms, ours "
        f"| thesis / ours | CPU/GPU, thesis | CPU/GPU, ours | relMSE, ours |",
        "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for r in rows:
        def ratio(a, b):
            return f"{a / b:.1f}x" if a and b else "-"
        relmse = r["gpu_relmse"] if r["gpu_relmse"] is not None else r["cpu_relmse"]
        lines.append(
            f'| {r["spp"]} | {fmt_ms(r["thesis_cpu_ms"])} | {fmt_ms(r["cpu_ms"])} | '
            f'{ratio(r["thesis_cpu_ms"], r["cpu_ms"])} | {fmt_ms(r["thesis_gpu_ms"])} | {fmt_ms(r["gpu_ms"])} | '
            f'{fmt_ms(r["gpu_wall_ms"])} | {ratio(r["thesis_gpu_ms"], r["gpu_ms"])} | '
            f'{ratio(r["thesis_cpu_ms"], r["thesis_gpu_ms"])} | {ratio(r["cpu_ms"], r["gpu_ms"])} | '
            f'{relmse:.3g} |' if relmse is not None else
            f'| {r["spp"]} | {fmt_ms(r["thesis_cpu_ms"])} | - | - | {fmt_ms(r["thesis_gpu_ms"])} | - | - | - | '
            f'{ratio(r["thesis_cpu_ms"], r["thesis_gpu_ms"])} | - | - |')
    lines.append("")
    lines.append(f"Ours: CPU {cpu_name} (multi engine), GPU {gpu_name}; thesis: its own machine (Table 5.4). "
                 "A '-' is a count one side did not render.")
    return "\n".join(lines) + "\n"


def figure_5_2(rows, devices, size, png):
    fig, axes = plt.subplots(1, 2, figsize=(13, 5), layout="constrained")
    series = [
        ("thesis CPU", "thesis_cpu_ms", "C0", "--", "s"),
        ("thesis GPU", "thesis_gpu_ms", "C1", "--", "s"),
        (f'ours CPU ({devices.get("multi", "multi")})', "cpu_ms", "C0", "-", "o"),
        (f'ours GPU ({devices.get("gpu", "gpu")})', "gpu_ms", "C1", "-", "o"),
    ]
    for axis, log in zip(axes, (False, True)):
        for label, key, colour, style, marker in series:
            points = [(r["spp"], r[key] / 1000.0) for r in rows if r[key]]
            if points:
                axis.plot([p[0] for p in points], [p[1] for p in points], style, marker=marker, color=colour,
                          label=label)
        if log:
            axis.set_xscale("log")
            axis.set_yscale("log")
        axis.set_xlabel("samples per pixel")
        axis.set_ylabel("render time (s)")
        axis.grid(True, which="both", alpha=0.3)
        axis.set_title("log-log" if log else "linear axes, as the thesis' figure 5.2")
    axes[0].legend(fontsize=8)
    fig.suptitle(f"Figure 5.2 redone: render time against spp, {size}", fontsize=11)
    fig.savefig(png, dpi=110)


def core_runs(out):
    runs = []
    for path in glob.glob(os.path.join(out, "cores-*.json")):
        n = int(re.search(r"cores-(\d+)\.json$", path).group(1))
        data = load(path)
        points = [(r["spp"], r["multi"]["render_ms"], r["multi"]["relmse"]) for r in data["rows"]]
        runs.append({"cores": n, "device": data.get("devices", {}).get("multi", ""), "points": points})
    return sorted(runs, key=lambda r: r["cores"])


def figure_4_6(runs, size, png):
    fig, axis = plt.subplots(figsize=(7, 5), layout="constrained")
    for run in runs:
        axis.plot([p[0] for p in run["points"]], [p[1] / 1000.0 for p in run["points"]], "o-",
                  label=f'{run["cores"]} core{"s" if run["cores"] > 1 else ""}')
    axis.set_xlabel("samples per pixel")
    axis.set_ylabel("render time (s)")
    axis.grid(True, alpha=0.3)
    axis.legend(fontsize=8)
    device = re.sub(r" \(\d+ threads?\)$", "", runs[0]["device"]) if runs else ""
    axis.set_title(f"Figure 4.6 redone: CPU render time against spp\n{device}, {size}", fontsize=10)
    fig.savefig(png, dpi=110)


def main(out, scripts, grid_pixels=6000):
    rows, devices, both = table_rows(out)
    size = f'{both["scene"]} {both["width"]}x{both["height"]}, depth {both["depth"]}, {both["estimator"]}'
    with open(os.path.join(out, "table-5.4.md"), "w") as f:
        f.write(markdown_table(rows, devices))
    figure_5_2(rows, devices, size, os.path.join(out, "figure-5.2.png"))
    runs = core_runs(out)
    if runs:
        figure_4_6(runs, size, os.path.join(out, "figure-4.6.png"))
    index = os.path.join(out, "images", "images.json")
    if os.path.exists(index):
        sys.path.insert(0, scripts)
        import ladder_grid
        ladder_grid.main(index, os.path.join(out, "tables-5.1-5.3.png"), grid_pixels)
    summary = {
        "scene": both["scene"], "width": both["width"], "height": both["height"], "depth": both.get("depth"),
        "estimator": both.get("estimator"), "reference_spp": both.get("reference_spp"),
        "reference_relmse": both.get("reference_relmse"), "devices": devices,
        "table_5_4": rows, "figure_4_6": runs,
        "cpu_gpu_image_relmse": {r["spp"]: r["relmse_cpu_gpu"] for r in both["rows"] if "relmse_cpu_gpu" in r},
    }
    with open(os.path.join(out, "thesis.json"), "w") as f:
        json.dump(summary, f, indent=1)
    print(markdown_table(rows, devices))


if __name__ == "__main__":
    if len(sys.argv) not in (2, 3, 4):
        sys.exit(__doc__)
    here = os.path.dirname(os.path.abspath(__file__))
    main(sys.argv[1], sys.argv[2] if len(sys.argv) >= 3 else os.path.join(here, "..", "..", "Common", "Compare"),
         int(sys.argv[3]) if len(sys.argv) == 4 else 6000)
