#!/usr/bin/env python3
"""Reads the --table JSON files of tests/Bench/efficiency.sh and prints a Markdown table per scene: for each
strategy and spp, time, relMSE and efficiency 1 / (relMSE x seconds), and each strategy's efficiency at its
largest spp relative to the mixture with Russian roulette off (book 3's estimator as the books run it). Where
the JSON holds the reference's own relMSE (`reference_relmse`, part of every relMSE measured against it), the
efficiencies are computed with it taken out."""
import glob
import json
import os
import sys


def main(folder):
    rows = {}
    for path in sorted(glob.glob(os.path.join(folder, "*-rr*.json"))):
        table = json.load(open(path))
        name = os.path.basename(path)[: -len(".json")]
        scene = table["scene"]
        strategy = name[len(scene) + 1:]
        engine = next(iter(table["devices"]))
        device = table["devices"][engine]
        floor = table.get("reference_relmse") or 0.0
        for row in table["rows"]:
            cell = row[engine]
            ms = cell["gpu_ms"] if cell.get("gpu_ms", -1.0) >= 0 else cell["render_ms"]
            rows.setdefault((scene, device), []).append((strategy, row["spp"], ms, cell["relmse"] - floor))
    for (scene, device), entries in rows.items():
        print(f"\n**{scene}** ({device}); efficiency = 1 / (relMSE x s), the reference's own relMSE taken out\n")
        print("| strategy | spp | ms | relMSE | efficiency | vs mixture, no RR |")
        print("|---|---:|---:|---:|---:|---:|")
        last = {}
        for strategy, spp, ms, relmse in entries:
            last[strategy] = (spp, ms, relmse)
        base = last.get("mixture-solid-angle-power-rroff")
        baseEff = 1.0 / (base[2] * base[1] / 1000.0) if base else None
        for strategy, (spp, ms, relmse) in last.items():
            eff = 1.0 / (relmse * ms / 1000.0)
            ratio = f"{eff / baseEff:.2f}x" if baseEff else ""
            print(f"| {strategy} | {spp} | {ms:.1f} | {relmse:.3g} | {eff:.1f} | {ratio} |")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else ".")
