#!/usr/bin/env bash
# Usage: scaling.sh BIN WORK [RANKS...]
# Issue 40's reference on one host: cornell-box-lights WIDTH x WIDTH (1200) at SPP (65536) spp with the scene's
# defaults, rendered by one process on one GPU (RANKS "1") and split over mpirun's N ranks, one GPU each, for each
# N of RANKS. Prints a row per render (render seconds: the slowest rank's; wall: the whole command, mpirun and
# every rank's start, build and pipeline compile included) and, where the one-GPU row is in OUT, the speed-up
# of each split render and its image's relMSE against it (float sums: < 1e-6 expected). Each render's stats and
# image (about 17 MB) stay in WORK, so that calls on the same machine add rows to one table.
set -u
bin=$1
out=$2
shift 2
images=$out
ranks=${*:-2 4}
width=${WIDTH:-1200}
spp=${SPP:-65536}
mkdir -p "$out"
args=(--headless --quiet --strategy scene --scene cornell-box-lights --width "$width" --spp "$spp" --seed 40)
# The driver's pipeline cache, once, out of every timed command: one sample per pixel of the same image runs the
# same integrator (the wavefront, from 2^20 camera paths) and so compiles the same pipelines.
"$bin/ray-tracing-gpu" --headless --quiet --strategy scene --scene cornell-box-lights --width "$width" --spp 1 >/dev/null
for n in $ranks; do
    start=$(date +%s.%N)
    if [ "$n" = 1 ]; then
        "$bin/ray-tracing-gpu" "${args[@]}" --hdr "$images/np1.pfm" --stats "$out/scaling-np1.json"
    else
        mpirun -q -np "$n" "$bin/ray-tracing-gpu" "${args[@]}" --hdr "$images/np$n.pfm" --stats "$out/scaling-np$n.json"
    fi
    status=$?
    end=$(date +%s.%N)
    echo "$n $(python3 -c "print($end - $start)") $status" >"$out/scaling-np$n.wall"
done
python3 - "$out" "$images" <<'PY'
import glob, json, os, sys
import numpy as np
out, images = sys.argv[1], sys.argv[2]
def pfm(p):
    with open(p, 'rb') as f:
        f.readline(); w, h = map(int, f.readline().split()); scale = float(f.readline())
        return np.frombuffer(f.read(), '<f4' if scale < 0 else '>f4').reshape(h, w, 3).astype(np.float64)
rows = {}
for wall in glob.glob(os.path.join(out, 'scaling-np*.wall')):
    n, seconds, status = open(wall).read().split()
    stats = os.path.join(out, f'scaling-np{n}.json')
    s = json.load(open(stats)) if os.path.exists(stats) else None
    rows[int(n)] = (float(seconds), int(status), s)
one = rows.get(1)
reference = pfm(os.path.join(images, 'np1.pfm')) if one and os.path.exists(os.path.join(images, 'np1.pfm')) else None
print('| ranks (GPUs) | devices | render s | wall s | speed-up (render) | speed-up (wall) | relMSE vs 1 GPU |')
print('|---|---|---|---|---|---|---|')
for n in sorted(rows):
    wall, status, s = rows[n]
    if s is None:
        print(f'| {n} | failed (status {status}) | | | | | |')
        continue
    devices = ', '.join(r['device'] for r in s['ranks']) if 'ranks' in s else s['device']
    render = s['render_seconds']
    up = f"{one[2]['render_seconds'] / render:.2f}x" if one and one[2] else ''
    upwall = f'{one[0] / wall:.2f}x' if one and one[2] else ''
    rel = ''
    image = os.path.join(images, f'np{n}.pfm')
    if reference is not None and os.path.exists(image):
        b = pfm(image)
        rel = f'{np.mean((b - reference) ** 2 / (reference ** 2 + 1e-2)):.2g}'
    print(f'| {n} | {devices} | {render:.2f} | {wall:.2f} | {up} | {upwall} | {rel} |')
PY
