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
    rr = settings["russian_roulette"]  # a word, or true / false in files written before the sqrt rule
    rr = "rr-" + (("on" if rr else "off") if isinstance(rr, bool) else rr)
    return f'{settings["estimator"]} {settings["light_sampler"]} {settings["light_selection"]} {settings["sampling"]} {rr}'


def best_of(eff):
    grid = {k: v for k, v in eff.items() if k != "auto"}
    return max(grid, key=grid.get)


def scene_rows(out):
    """One dict per scene of OUT_DIR: scene, strategies, best, best_full, best_again, own, own_eff, chosen, auto_eff."""
    rows = []
    for path in sorted(Path(out).glob("*.csv")):
        if "recheck" in path.stem:
            continue
        scene = path.stem
        full, _ = efficiencies(path)
        best = best_of(full)
        own_name = strategy_of(json.load((Path(out) / f"{scene}-defaults.json").open())["settings"])
        recheck = Path(out) / f"{scene}-recheck.csv"
        again = Path(out) / f"{scene}-recheck-best.csv"
        if recheck.exists() and again.exists():
            r, chosen = efficiencies(recheck)
            b, _ = efficiencies(again)
            best_eff, own_eff, auto_eff = list(b.values())[0], r[own_name], r["auto"]
        else:
            chosen = []
            best_eff, own_eff, auto_eff = full[best], full.get(own_name, float("nan")), full["auto"]
        rows.append({"scene": scene, "strategies": len(full) - 1, "best": best, "best_full": full[best],
                     "best_again": best_eff, "own": own_name, "own_eff": own_eff, "chosen": chosen,
                     "auto_eff": auto_eff})
    return rows


def main():
    if sys.argv[1] == "--best":
        eff, _ = efficiencies(Path(sys.argv[2]))
        print(best_of(eff))
        return
    print("| scene | strategies | best (full comparison) | best, again | scene's own | own / best | auto chose "
          "(recheck seeds) | auto / best | auto / own |")
    print("|---|---:|---|---:|---|---:|---|---:|---:|")
    rows = scene_rows(sys.argv[1])
    for r in rows:
        print(f"| {r['scene']} | {r['strategies']} | {r['best']} ({r['best_full']:.4g}) | {r['best_again']:.4g} | "
              f"{r['own']} | {r['own_eff'] / r['best_again']:.2f} | {'; '.join(r['chosen'])} | "
              f"{r['auto_eff'] / r['best_again']:.2f} | {r['auto_eff'] / r['own_eff']:.2f} |")
    low = [r["scene"] for r in rows if r["auto_eff"] / r["best_again"] < 0.9]
    below = [r["scene"] for r in rows if r["auto_eff"] / r["own_eff"] < 1.0]
    print()
    print(f"auto below 0.9x the best: {', '.join(low) if low else 'none'}; below the scene's own strategy: "
          f"{', '.join(below) if below else 'none'}")


if __name__ == "__main__":
    main()
