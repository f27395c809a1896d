#!/usr/bin/env python3
"""Rays per second by kind, as a Markdown table, from the --stats of the renders of RENDERS_FILE.

    rays_table.py OUT_DIR RENDERS_FILE          a gpu_ab.sh run whose B side added --count-rays to A's render
                                                (device_run.sh rays)
    rays_table.py --cpu OUT_DIR RENDERS_FILE    one CPU render each, OUT_DIR/NAME.json (tests/Bench/cpu_rays.sh)

GPU: for each render the B side's rays by kind (the fastest round), in millions per second of the GPU's own clock
(gpu_seconds; the stats' own rates use the host's), the rays per path, and what counting cost: the fastest B time
over the fastest A time (1.00: nothing). CPU: the same rates over the host's render seconds.
"""
import json
import sys


def render_names(renders):
    """The names of a renders file's renders (gpu_ab.sh's format: NAME ARGS..., `#` comments)."""
    return [line.split()[0] for line in open(renders) if line.strip() and not line.lstrip().startswith("#")]


def fastest(out, name, side):
    """The stats of gpu_ab.sh's fastest round of side `side` ("a" or "b") of render `name`, by GPU time."""
    runs = []
    r = 1
    while True:
        try:
            runs.append(json.load(open(f"{out}/{name}-{side}-{r}.json")))
        except FileNotFoundError:
            break
        r += 1
    return min(runs, key=lambda j: j["gpu_seconds"])


def row(name, stats, seconds, extra=""):
    rays = stats["rays"]
    rate = {k: rays[k] / seconds * 1e-6 for k in ("camera", "extension", "shadow", "total")}
    digits = 0 if rate["total"] >= 100 else 1
    cells = [f"{stats['paths'] / seconds * 1e-6:.{digits}f}"] + [f"{rate[k]:.{digits}f}" for k in
                                                                 ("camera", "extension", "shadow", "total")]
    return f"| {name} | " + " | ".join(cells) + f" | {rays['total'] / stats['paths']:.2f} |" + extra


def main(args):
    cpu = args[0] == "--cpu"
    if cpu:
        args = args[1:]
    if len(args) != 2:
        sys.exit(__doc__)
    out, renders = args
    names = render_names(renders)
    head = "| render | Mpaths/s | camera Mrays/s | extension Mrays/s | shadow Mrays/s | total Mrays/s | rays/path |"
    print(head + ("" if cpu else " time with counting / without |"))
    print("|---|---:|---:|---:|---:|---:|---:|" + ("" if cpu else "---:|"))
    for name in names:
        if cpu:
            stats = json.load(open(f"{out}/{name}.json"))
            print(row(name, stats, stats["render_seconds"]))
        else:
            a, b = fastest(out, name, "a"), fastest(out, name, "b")
            print(row(name, b, b["gpu_seconds"], f" {b['gpu_seconds'] / a['gpu_seconds']:.2f} |"))


if __name__ == "__main__":
    main(sys.argv[1:])
