#!/usr/bin/env python3
"""Rays per second by kind from a gpu_ab.sh run whose B side added --count-rays to A's render (device_run.sh rays).

    rays_table.py OUT_DIR RENDERS_FILE

For each render of RENDERS_FILE: the B side's rays by kind (the fastest round's stats), in millions per second of
the GPU's own clock (gpu_seconds; the stats' own rates use the host's), the segments per path, and what counting
cost: the fastest A time over the fastest B time (1.00: nothing). Prints a Markdown table.
"""
import json
import sys


def main(out, renders):
    names = [line.split()[0] for line in open(renders) if line.strip() and not line.lstrip().startswith("#")]
    print("| render | Mpaths/s | camera Mrays/s | extension Mrays/s | shadow Mrays/s | total Mrays/s | rays/path | "
          "time with counting / without |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for name in names:
        rounds = {}
        for side in "ab":
            runs = []
            r = 1
            while True:
                try:
                    runs.append(json.load(open(f"{out}/{name}-{side}-{r}.json")))
                except FileNotFoundError:
                    break
                r += 1
            rounds[side] = min(runs, key=lambda j: j["gpu_seconds"])
        b = rounds["b"]
        rays, seconds = b["rays"], b["gpu_seconds"]
        rate = {k: rays[k] / seconds * 1e-6 for k in ("camera", "extension", "shadow", "total")}
        print(f"| {name} | {b['paths'] / seconds * 1e-6:.0f} | {rate['camera']:.0f} | {rate['extension']:.0f} | "
              f"{rate['shadow']:.0f} | {rate['total']:.0f} | {rays['total'] / b['paths']:.2f} | "
              f"{b['gpu_seconds'] / rounds['a']['gpu_seconds']:.2f} |")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
