#!/usr/bin/env bash
# Usage: compare_scaling.sh BIN WORK [RANKS...]
# Issue 40's sweep on one host: a --compare of 24 rows (cornell-box-lights WIDTH (900) px, the GPU engine, light
# samplers area and projected x selections power and bvh x SPP_LIST (64,256,1024) spp x 2 seeds; 3 rounds each,
# the reference of 4x the largest spp rendered, not cached), by one process on one GPU (RANKS "1") and over mpirun's N ranks,
# one GPU each, for each N of RANKS. Prints a row per run: wall seconds of the whole command (mpirun, every
# rank's start, build, warm-up and the reference included), the speed-up against the one-GPU run where WORK
# holds it, the renders each rank did, and whether every row's error columns equal the one-GPU run's.
set -u
bin=$1
out=$2
shift 2
ranks=${*:-2}
width=${WIDTH:-900}
spps=${SPP_LIST:-64,256,1024}
mkdir -p "$out"
args=(--compare --scene cornell-box-lights --width "$width" --engines gpu --light-samplers area,projected
    --light-selections power,bvh --spp-list "$spps" --seeds 2 --rounds 3 --seed 40 --reference-cache off)
# The driver's pipeline cache, once, out of every timed command: a 1-spp render of each strategy compiles the
# pipelines the sweep's renders use (else the first command of a fresh machine pays their compilation: 3-4 s).
for sampler in area projected; do
    for selection in power bvh; do
        "$bin/ray-tracing-gpu" --headless --quiet --strategy scene --scene cornell-box-lights --width "$width" --spp 1 \
            --light-sampler "$sampler" --light-selection "$selection" >/dev/null
    done
done
for n in $ranks; do
    start=$(date +%s.%N)
    if [ "$n" = 1 ]; then
        "$bin/ray-tracing-gpu" "${args[@]}" --csv "$out/sweep-np1.csv" >"$out/sweep-np1.out" 2>"$out/sweep-np1.err"
    else
        mpirun -q -np "$n" "$bin/ray-tracing-gpu" "${args[@]}" --csv "$out/sweep-np$n.csv" >"$out/sweep-np$n.out" \
            2>"$out/sweep-np$n.err"
    fi
    status=$?
    end=$(date +%s.%N)
    echo "$n $(python3 -c "print($end - $start)") $status" >"$out/sweep-np$n.wall"
done
python3 - "$out" <<'PY'
import csv, glob, os, sys
out = sys.argv[1]
runs = {}
for wall in glob.glob(os.path.join(out, 'sweep-np*.wall')):
    n, seconds, status = open(wall).read().split()
    path = os.path.join(out, f'sweep-np{n}.csv')
    rows = list(csv.DictReader(open(path))) if os.path.exists(path) else []
    runs[int(n)] = (float(seconds), int(status), rows)
errors = ('mse', 'relmse', 'rmse', 'reference_relmse', 'trimmed_relmse', 'mape')
def keyed(rows):
    return {(r['strategy'], r['spp'], r['seed'], r['round']): r for r in rows}
one = runs.get(1)
print('| ranks (GPUs) | devices | table rows | renders | wall s | speed-up (wall) | renders per rank | errors as 1 GPU |')
print('|---|---|---|---|---|---|---|---|')
for n in sorted(runs):
    wall, status, rows = runs[n]
    if status != 0:
        print(f'| {n} | failed (status {status}) | | | | | | |')
        continue
    devices = ', '.join(sorted({r['device'] for r in rows}))
    table = len({(r['strategy'], r['spp'], r['seed']) for r in rows})
    per = {}
    for r in rows:
        per[r['rank']] = per.get(r['rank'], 0) + 1
    up = f'{one[0] / wall:.2f}x' if one and one[1] == 0 else ''
    same = ''
    if one and one[1] == 0:
        a, b = keyed(one[2]), keyed(rows)
        same = 'yes' if a.keys() == b.keys() and all(a[k][c] == b[k][c] for k in a for c in errors) else 'NO'
    print(f'| {n} | {devices} | {table} | {len(rows)} | {wall:.2f} | {up} | '
          f'{", ".join(f"{per[r]}" for r in sorted(per, key=int))} | {same} |')
PY
