#!/usr/bin/env python3
"""Time to the thesis' error from equal_error.sh's CSVs: the mixture-1000 render's relMSE (mean over seeds and
rounds) is the target; for every other strategy, its mean relMSE and median GPU time at each spp of its ladder, and
the spp and GPU time at which it reaches the target: relMSE taken as inversely proportional to spp from the
largest rung still above the target (from the smallest rung if every rung is below it), the time interpolated
linearly between rungs. Prints a Markdown table. Usage: equal_error_table.py OUT_DIR"""
import csv
import statistics
import sys
from pathlib import Path


def ladder(path):
    rows = {}
    device = None
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            device = r["device"]
            rung = rows.setdefault(r["strategy"], {}).setdefault(int(r["spp"]), ([], []))
            rung[0].append(float(r["relmse"]))
            rung[1].append(float(r["gpu_ms"]))
    return device, {s: {spp: (statistics.mean(e), statistics.median(t)) for spp, (e, t) in rungs.items()}
                    for s, rungs in rows.items()}


def time_at(rungs, target):
    spps = sorted(rungs)
    above = [s for s in spps if rungs[s][0] > target]
    base = above[-1] if above else spps[0]
    spp = base * rungs[base][0] / target
    lo = max([s for s in spps if s <= spp], default=spps[0])
    hi = min([s for s in spps if s >= spp], default=spps[-1])
    if hi == lo:
        return spp, rungs[lo][1] * spp / lo
    return spp, rungs[lo][1] + (spp - lo) / (hi - lo) * (rungs[hi][1] - rungs[lo][1])


def main(out_dir):
    out = Path(out_dir)
    device, mixture = ladder(out / "mixture-1000.csv")
    (name, rungs), = mixture.items()
    target, mixture_ms = rungs[1000]
    print(f"Time to the mixture-1000 error ({name}: relMSE {target:.4f} in {mixture_ms:.1f} ms), {device}")
    print()
    print("| strategy | relMSE at its ladder (spp: relMSE) | spp to reach it | GPU ms to reach it |")
    print("|---|---|---:|---:|")
    for path in sorted(out.glob("run-*.csv")):
        for strategy, rungs in ladder(path)[1].items():
            spp, ms = time_at(rungs, target)
            steps = ", ".join(f"{s}: {e:.4f}" for s, (e, _) in sorted(rungs.items()))
            print(f"| {strategy} | {steps} | {spp:.0f} | {ms:.1f} |")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
