#!/usr/bin/env bash
# Issue 37's GPU pilot: a render's time on the GPU's clock against its size and spp, warm (--compare times every
# row in interleaved rounds after an untimed render of each), for two light samplers x two selections and both
# integrators: whether small renders' time per path predicts the render's. Run by device_run.sh pilot-sizes.
#   pilot_sizes.sh BIN OUT [SCENE]
set -eu
bin=$1 out=$2 scene=${3:-cornell-box-lights}
mkdir -p "$out"
for integrator in megakernel wavefront; do
    for w in 600 256 64; do
        "$bin/ray-tracing-gpu" --compare --engines gpu --scene "$scene" --width "$w" --spp-list 1,2,4,16,64 \
            --light-samplers projected,solid-angle --light-selections bvh,uniform --rounds 3 --reference-spp 256 \
            --reference-cache off --integrator "$integrator" --csv "$out/$scene-$integrator-$w.csv" >/dev/null 2>"$out/$scene-$integrator-$w.log" || echo "failed: $w $integrator"
    done
done
python3 - "$out" "$scene" <<'PY'
import csv, sys, glob, os, statistics
out, scene = sys.argv[1], sys.argv[2]
for f in sorted(glob.glob(f"{out}/{scene}-*.csv")):
    rows = list(csv.DictReader(open(f)))
    by = {}
    for r in rows:
        by.setdefault((r['strategy'], int(r['spp'])), []).append(float(r['gpu_ms'] or r['wall_ms']))
    print(os.path.basename(f))
    for (s, spp), ms in sorted(by.items()):
        print(f"  {s:45} {spp:4d} spp  {statistics.median(ms):9.3f} ms")
PY
