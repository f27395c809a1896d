#!/usr/bin/env python3
"""Russian roulette's rules against each other from roulette.sh's CSVs: per scene, each rule's relMSE (less the
reference's own, which every row's relMSE holds) and time, averaged over seeds, its efficiency 1/(relMSE s), and
sqrt's efficiency over pbrt-v4's with a 95 % Student-t interval over the seeds' log ratios (seed k of one rule
against seed k of the other; the renders are independent). Prints a Markdown table.
Usage: roulette_table.py OUT_DIR [TITLE]"""
import csv
import math
import statistics
import sys
from pathlib import Path

# Student's t at 97.5 % for 1..9 degrees of freedom.
T975 = [12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262]


def rows_of(path):
    by_rule = {}
    scene = device = None
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            scene, device = r["scene"], r["device"]
            error = float(r["relmse"]) - float(r["reference_relmse"])
            by_rule.setdefault(r["label"], []).append((int(r["seed"]), error, float(r["wall_ms"]) * 1e-3, int(r["spp"])))
    return scene, device, by_rule


def main(out_dir, title=None):
    files = sorted(Path(out_dir).glob("*.csv"))
    if not files:
        sys.exit(f"error: no CSV in {out_dir}")
    lines = []
    ratios = []
    device = None
    for path in files:
        scene, device, by_rule = rows_of(path)
        on, sq = sorted(by_rule.get("rr-on", [])), sorted(by_rule.get("rr-sqrt", []))
        if not on or not sq or len(on) != len(sq):
            sys.exit(f"error: {path}: expected the same seeds for rr-on and rr-sqrt")
        eff = lambda runs: [1.0 / (e * s) if e > 0 else math.inf for _, e, s, _ in runs]
        logs = [math.log(b / a) for a, b in zip(eff(on), eff(sq)) if math.isfinite(a) and math.isfinite(b)]
        ratio = math.exp(statistics.mean(logs))
        if len(logs) > 1:
            half = T975[min(len(logs) - 2, len(T975) - 1)] * statistics.stdev(logs) / math.sqrt(len(logs))
            interval = f"[{math.exp(statistics.mean(logs) - half):.2f}, {math.exp(statistics.mean(logs) + half):.2f}]"
        else:
            interval = "(one seed)"
        ratios.append(ratio)
        mean = lambda runs, i: statistics.mean(x[i] for x in runs)
        lines.append(f"| {scene} | {mean(on, 3):.0f} | {mean(on, 1):.3g} | {mean(sq, 3):.0f} | {mean(sq, 1):.3g} | "
                     f"{ratio:.2f} {interval} |")
    print(title or f"Russian roulette: Cycles' sqrt rule over pbrt-v4's, equal time, {device}")
    print()
    print("| scene | pbrt-v4 spp | relMSE | sqrt spp | relMSE | efficiency sqrt / pbrt-v4 [95 %] |")
    print("|---|---:|---:|---:|---:|---:|")
    print("\n".join(lines))
    print()
    geo = math.exp(statistics.mean(math.log(r) for r in ratios))
    print(f"Geometric mean over {len(ratios)} scenes: {geo:.2f}; range {min(ratios):.2f}-{max(ratios):.2f}; "
          f"sqrt ahead on {sum(r > 1 for r in ratios)}.")


if __name__ == "__main__":
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    main(*sys.argv[1:])
