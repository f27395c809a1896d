#!/usr/bin/env python3
"""Plots a convergence CSV of `ray-tracing-gpu --compare --csv` (ConvergenceCsv.h's columns): relMSE against
time and against spp on log-log axes, one line per engine x strategy, with the slope -1 that an unbiased
Monte Carlo estimator follows drawn through each line's first point; and the efficiency 1 / (relMSE x s) of
each line's largest spp as bars. Time is the GPU's own clock where the engine has one, else the host's. A
dashed grey line marks the reference's own relMSE (its `reference_relmse` column, when known): part of every
value, so lines that come near it flatten out there; the efficiency bars take it out. Rows measured against
references of their own (the window's plot: each at 4x its spp) have several; then no line is drawn, and each
bar takes out its own point's. Rows of several seeds
(`--seeds N`: the `seed` column) are drawn as their mean relMSE at their median time.

With METRIC (--compare's --metric: relmse, trimmed-relmse, mape or flip) the figure plots that column instead:
MAPE and FLIP fall about as 1/sqrt(spp), so their guide slope is -1/2 and their efficiency 1 / (error^2 x s);
the reference's own error is known for relMSE only. Rows without the metric (FLIP beyond round 0) are skipped.

    plot_convergence.py ROWS.csv [METRIC] FIGURE.png
"""
import csv
import statistics
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


# --metric's name: (CSV column, axis label, power k of the efficiency 1 / (error^k x s)).
METRICS = {
    "relmse": ("relmse", "relMSE", 1),
    "trimmed-relmse": ("trimmed_relmse", "relMSE, worst 0.1 % trimmed", 1),
    "mape": ("mape", "MAPE", 2),
    "flip": ("flip", "HDR-FLIP", 2),
}


def read_rows(path, column="relmse"):
    series = OrderedDict()
    scenes, devices = OrderedDict(), OrderedDict()
    floors = set()
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if column == "relmse" and float(row.get("reference_relmse") or -1) > 0:
                floors.add(float(row["reference_relmse"]))
            ms = float(row["gpu_ms"]) if float(row["gpu_ms"]) >= 0 else float(row["wall_ms"])
            relmse = float(row[column])
            if ms <= 0 or relmse <= 0:
                continue  # not on a log axis
            key = f'{row["engine"]} {row["label"]}'
            floor = float(row.get("reference_relmse") or -1) if column == "relmse" else -1
            series.setdefault(key, OrderedDict()).setdefault(int(row["spp"]), []).append(
                (ms / 1000.0, relmse, max(floor, 0.0)))
            scenes[row["scene"]] = True
            devices[f'{row["engine"]}: {row["device"]}'] = True
    # One point per spp: the seeds' mean relMSE at their median time.
    points = OrderedDict()
    for key, by_spp in series.items():
        points[key] = [(spp, statistics.median(s for s, _, _ in runs), statistics.fmean(r for _, r, _ in runs),
                        statistics.fmean(f for _, _, f in runs)) for spp, runs in by_spp.items()]
    return points, list(scenes), list(devices), sorted(floors)


def main(csv_path, png_path, metric="relmse"):
    column, name, power = METRICS[metric]
    series, scenes, devices, floors = read_rows(csv_path, column)
    if not series:
        sys.exit(f"{csv_path}: no rows to plot")
    fig, (by_time, by_spp, bars) = plt.subplots(1, 3, figsize=(17, 5.2))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    efficiency = []
    for i, (key, points) in enumerate(series.items()):
        points.sort()
        colour = colours[i % len(colours)]
        spp = [p[0] for p in points]
        seconds = [p[1] for p in points]
        relmse = [p[2] for p in points]
        by_time.loglog(seconds, relmse, "o-", color=colour, label=key)
        by_spp.loglog(spp, relmse, "o-", color=colour, label=key)
        # Slope -1/k through the first point: where an unbiased estimator's error goes with more samples.
        for axis, x in ((by_time, seconds), (by_spp, spp)):
            axis.loglog([x[0], x[-1]], [relmse[0], relmse[0] * (x[0] / x[-1]) ** (1.0 / power)], ":", color=colour,
                        alpha=0.6)
        # The reference's own error is part of every relMSE: the bars leave it out where it is known.
        own = relmse[-1] - points[-1][3]
        efficiency.append((key, 1.0 / (max(own, 1e-12) ** power * seconds[-1]), spp[-1], colour))
    by_time.set_xlabel("render time (s)")
    by_spp.set_xlabel("samples per pixel")
    for axis in (by_time, by_spp):
        for j, floor in enumerate(floors if len(floors) == 1 else []):
            axis.axhline(floor, linestyle="--", color="grey", linewidth=1,
                         label="the reference's own relMSE" if j == 0 else None)
        axis.set_ylabel(name)
        axis.grid(True, which="both", alpha=0.3)
    slope = "-1" if power == 1 else f"-1/{power}"
    by_time.set_title(f"{name} against time (dotted: slope {slope})")
    by_spp.set_title(f"{name} against spp (dotted: slope {slope})")
    by_time.legend(fontsize=8)
    names = [e[0] for e in efficiency]
    bars.barh(range(len(efficiency)), [e[1] for e in efficiency], color=[e[3] for e in efficiency])
    bars.set_yticks(range(len(efficiency)))
    bars.set_yticklabels([f"{n} ({e[2]} spp)" for n, e in zip(names, efficiency)], fontsize=8)
    bars.invert_yaxis()
    error = name if power == 1 else f"{name}^{power}"
    bars.set_xlabel(f"efficiency 1 / ({error} x s), at each line's largest spp"
                    + ("\n(the reference's own relMSE taken out)" if floors else ""))
    bars.set_title("efficiency (higher is better)")
    fig.suptitle(f'{", ".join(scenes)} - {"; ".join(devices)}', fontsize=10)
    fig.tight_layout()
    fig.savefig(png_path, dpi=110, format="png")


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4) or (len(sys.argv) == 4 and sys.argv[2] not in METRICS):
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[-1], sys.argv[2] if len(sys.argv) == 4 else "relmse")
