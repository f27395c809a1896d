#!/usr/bin/env bash
# Usage: thesis_figures.sh RAY_TRACING_GPU
# tests/Bench/thesis_figures.sh (issue 39's one command for the thesis' figures) shrunk for lavapipe: Table
# 5.4 with the thesis' values beside ours, a '-' where one side rendered no such count, the CPU's and GPU's
# images alike, figure 4.6's runs on 1 and 2 cores (taskset) named by the cores they had, and every figure.
set -eu
app=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
WIDTH=48 SPP_LIST=10,50,100 CPU_SPP_LIST=10,50 CORE_SPP_LIST=4,8 THREADS="1 2" REFERENCE_SPP=512 ROUNDS=1 \
    CPU_ROUNDS=1 RT_REFERENCE_CACHE="$work/cache" bash "$here/../Bench/thesis_figures.sh" "$work/out" \
    "$(dirname "$app")" >"$work/log.txt" 2>&1 || { cat "$work/log.txt"; fail "thesis_figures.sh failed"; }
for f in table-5.4.md thesis.json figure-5.2.png figure-4.6.png tables-5.1-5.3.png; do
    [ -s "$work/out/$f" ] || { cat "$work/log.txt"; fail "no $f"; }
done
python3 - "$work/out" "$(nproc)" <<'PY' || fail "the thesis' table and figures"
import json, sys
out, cores = sys.argv[1], int(sys.argv[2])
summary = json.load(open(f"{out}/thesis.json"))
rows = {r["spp"]: r for r in summary["table_5_4"]}
# The thesis' Table 5.4, every count of it, beside ours where rendered.
assert sorted(rows) == [10, 50, 100, 250, 500, 1000, 2000, 5000, 7500, 10000, 15000, 20000], sorted(rows)
assert (rows[10]["thesis_cpu_ms"], rows[10]["thesis_gpu_ms"]) == (2000, 10), rows[10]
assert (rows[20000]["thesis_cpu_ms"], rows[20000]["thesis_gpu_ms"]) == (3311000, 20440), rows[20000]
for spp in (10, 50):
    assert rows[spp]["cpu_ms"] > 0 and rows[spp]["gpu_ms"] > 0, rows[spp]
assert rows[100]["cpu_ms"] is None and rows[100]["gpu_ms"] > 0 and rows[250]["gpu_ms"] is None, rows
# The same seeds on both engines: images that differ far less than either differs from the reference.
for spp, between in summary["cpu_gpu_image_relmse"].items():
    assert between < 0.05 * rows[int(spp)]["gpu_relmse"], (spp, between, rows[int(spp)])
# relMSE falls about as 1/spp (an unbiased estimator).
assert 3 < rows[10]["gpu_relmse"] / rows[50]["gpu_relmse"] < 9, rows
table = open(f"{out}/table-5.4.md").read().splitlines()
line = next(l for l in table if l.startswith("| 10 |"))
assert "| 2,000 |" in line and "| 10.0 |" in line and "200.0x" in line, line
line = next(l for l in table if l.startswith("| 250 |"))
assert line.count("| - ") >= 5 and "| 42,000 |" in line, line
# Figure 4.6: a run per core count up to the machine's, each on as many threads as cores it was given.
runs = {r["cores"]: r for r in summary["figure_4_6"]}
assert sorted(runs) == [n for n in (1, 2) if n <= cores], runs
for n, run in runs.items():
    assert run["device"].endswith(f"({n} thread{'s' if n > 1 else ''})"), run["device"]
    assert [p[0] for p in run["points"]] == [4, 8] and all(p[1] > 0 for p in run["points"]), run
PY
echo "thesis figures ok"
