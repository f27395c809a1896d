#!/usr/bin/env python3
"""Issue 37's table for --strategy auto from auto_strategy.sh's CSVs. Per scene, the efficiency 1/(relMSE s) of a
row is the inverse of its mean over seeds of relMSE x s (as --compare's equal-time table); the auto row (label
"auto: ..."; its time includes its pilot's). From the full comparison: the best strategy and auto; from the recheck
(fresh seeds, the same reference): the best again, the scene's own strategy and auto. The ratios use the recheck
where it exists. Standard library only.

    auto_strategy_table.py OUT_DIR          a Markdown table on stdout
    auto_strategy_table.py --best FILE.csv  the best strategy's words (estimator sampler selection sampling rr)
"""
import csv
import json
import statistics
import sys
from pathlib import Path


def efficiencies(path):
    """{strategy or 'auto': efficiency}, and the strategies auto chose."""
    rows = list(csv.DictReader(path.open()))
    cost, chosen = {}, []
    for r in rows:
        ms = float(r["gpu_ms"]) if float(r["gpu_ms"]) >= 0 else float(r["wall_ms"])
        key = "auto" if r["label"].startswith("auto") else r["strategy"]
        if key == "auto":
            chosen.append(r["strategy"])
        cost.setdefault(key, []).append(float(r["relmse"]) * ms * 1e-3)
    return {k: 1.0 / statistics.mean(v) for k, v in cost.items()}, chosen


def strategy_of(settings):
    rr = "rr-on" if settings["russian_roulette"] else "rr-off"
    return f'{settings["estimator"]} {settings["light_sampler"]} {settings["light_selection"]} {settings["sampling"]} {rr}'


def best_of(eff):
    grid = {k: v for k, v in eff.items() if k != "auto"}
    return max(grid, key=grid.get)


def main():
    if sys.argv[1] == "--best":
        eff, _ = efficiencies(Path(sys.argv[2]))
        print(best_of(eff))
        return
    out = Path(sys.argv[1])
    print("| scene | strategies | best (full comparison) | best, again | scene's own | own / best | auto chose "
          "(recheck seeds) | auto / best | auto / own |")
    print("|---|---:|---|---:|---|---:|---|---:|---:|")
    low, below = [], []
    for path in sorted(out.glob("*.csv")):
        if "recheck" in path.stem:
            continue
        scene = path.stem
        full, _ = efficiencies(path)
        best = best_of(full)
        own_name = strategy_of(json.load((out / f"{scene}-defaults.json").open())["settings"])
        recheck = out / f"{scene}-recheck.csv"
        again = out / f"{scene}-recheck-best.csv"
        if recheck.exists() and again.exists():
            r, chosen = efficiencies(recheck)
            b, _ = efficiencies(again)
            best_eff, own_eff, auto_eff = list(b.values())[0], r[own_name], r["auto"]
        else:
            chosen = []
            best_eff, own_eff, auto_eff = full[best], full.get(own_name, float("nan")), full["auto"]
        if auto_eff / best_eff < 0.9:
            low.append(scene)
        if auto_eff / own_eff < 1.0:
            below.append(scene)
        print(f"| {scene} | {len(full) - 1} | {best} ({full[best]:.4g}) | {best_eff:.4g} | {own_name} | "
              f"{own_eff / best_eff:.2f} | {'; '.join(chosen)} | {auto_eff / best_eff:.2f} | {auto_eff / own_eff:.2f} |")
    print()
    print(f"auto below 0.9x the best: {', '.join(low) if low else 'none'}; below the scene's own strategy: "
          f"{', '.join(below) if below else 'none'}")


if __name__ == "__main__":
    main()
