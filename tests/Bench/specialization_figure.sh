#!/usr/bin/env bash
# Issue 11's figure: cornell-box-lights at 600x600, 1000 spp, book 3's mixture (its target on the H100: <= 470
# ms), with the general pipeline (--specialize off), the strategy-only one and the strategy + features one
# (on), one after the other in each of ROUNDS rounds, in one run. Prints every render's GPU seconds, the
# fastest of each, the relMSE of the specialised image against the general one, and where the fastest
# specialised render's time went (stats' stage_seconds: upload, BLAS/TLAS builds, pipeline compilation,
# clear, trace, readback, resolve).
#   tests/Bench/specialization_figure.sh BIN_DIR OUT_DIR [SCENE WIDTH SPP ESTIMATOR]
# ROUNDS (default 3).
set -eu
bin=$1 out=$2 scene=${3:-cornell-box-lights} width=${4:-600} spp=${5:-1000} estimator=${6:-mixture}
rounds=${ROUNDS:-3}
mkdir -p "$out"
echo "$scene ${width}x${width}, $spp spp, --estimator $estimator, $rounds rounds"
for ((r = 1; r <= rounds; ++r)); do
    for mode in off strategy on; do
        "$bin/ray-tracing-gpu" --headless --quiet --strategy scene --scene "$scene" --width "$width" --spp "$spp" \
            --estimator "$estimator" --specialize "$mode" --hdr "$out/figure-$mode.pfm" \
            --stats "$out/figure-$mode-$r.json" >/dev/null
    done
done
python3 - "$out" "$rounds" <<'PY'
import json, sys
out, rounds = sys.argv[1], int(sys.argv[2])
best = {}
for mode in ("off", "strategy", "on"):
    runs = [json.load(open(f"{out}/figure-{mode}-{r}.json")) for r in range(1, rounds + 1)]
    times = [j["gpu_seconds"] * 1e3 for j in runs]
    best[mode] = min(range(rounds), key=lambda i: times[i])
    name = {"off": "general", "strategy": "strategy only", "on": "specialised"}[mode]
    print(f"{name:>14}: " + ", ".join(f"{t:.1f}" for t in times) + f" ms GPU; fastest {min(times):.1f} ms")
    best[mode] = (min(times), runs[best[mode]])
print(f"speed-up: {best['off'][0] / best['on'][0]:.2f}x (strategy only {best['off'][0] / best['strategy'][0]:.2f}x)")
stages = best["on"][1].get("stage_seconds", {})
print("stages of the fastest specialised render (ms): " +
      ", ".join(f"{k} {v * 1e3:.2f}" for k, v in sorted(stages.items())))
print(best["on"][1].get("frame_configuration", ""))
print(f"wall {best['on'][1]['wall_seconds'] * 1e3:.1f} ms, render (host) {best['on'][1]['render_seconds'] * 1e3:.1f} ms")
PY
echo "relMSE specialised vs general: $(python3 "$(dirname "$0")/pfm_relmse.py" "$out/figure-on.pfm" "$out/figure-off.pfm")"
