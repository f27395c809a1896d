#!/usr/bin/env python3
"""The GPU engine against the CPU engine of the same host at equal work (issue 42's GPU/CPU16 ratio), as Markdown.

    gpu_over_cpu.py GPU_STATS_DIR CPU_STATS_DIR RENDERS_FILE

GPU_STATS_DIR: a gpu_ab.sh run (NAME-a-R.json: the A side's rounds, the render without --count-rays, as
device_run.sh rays leaves them); CPU_STATS_DIR: one CPU render each (NAME.json, tests/Bench/cpu_rays.sh). Per
render: the CPU's render seconds over the GPU's fastest, on the GPU's own clock and on the host's, and the two
engines' rays per path (the same paths, so the same rays but for rounding).
"""
import json
import sys

from rays_table import fastest, render_names


def main(gpu_dir, cpu_dir, renders):
    print("| render | CPU s | GPU ms (GPU clock) | CPU / GPU | CPU / GPU (host clock) | rays/path CPU | rays/path GPU |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for name in render_names(renders):
        gpu = fastest(gpu_dir, name, "a")
        counted = json.load(open(f"{gpu_dir}/{name}-b-1.json"))
        cpu = json.load(open(f"{cpu_dir}/{name}.json"))
        print(f"| {name} | {cpu['render_seconds']:.2f} | {gpu['gpu_seconds'] * 1e3:.1f} | "
              f"{cpu['render_seconds'] / gpu['gpu_seconds']:.1f} | {cpu['render_seconds'] / gpu['render_seconds']:.1f} | "
              f"{cpu['rays']['total'] / cpu['paths']:.3f} | {counted['rays']['total'] / counted['paths']:.3f} |")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
