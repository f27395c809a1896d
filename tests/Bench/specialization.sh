#!/usr/bin/env bash
# The GPU engine's specialised pipelines against its general one (issue 11). Every scene at its own settings
# but WIDTH and SPP, rendered with --specialize off (the general pipeline), strategy (the render's estimator,
# light sampler, light selection and sampling only) and on (the strategy and the scene's features: the
# default), one after the other in each of ROUNDS rounds (the fastest of each kept), in one run. Prints one
# markdown row per scene: the GPU seconds (the device's timestamps, gpu_seconds) of the general and the
# specialised pipeline, their ratio, the relMSE of the specialised image against the general one (both at SPP
# with the same seed: 0 or round-off where the driver compiles the arithmetic differently; a fold that changed
# the estimator would show far above it), then the strategy-only seconds and what the features add on top of
# them (strategy s / specialised s).
#   tests/Bench/specialization.sh BIN_DIR OUT_DIR WIDTH SPP [SCENE...]   (default: every catalogue scene)
# ROUNDS (default 2). Each pipeline compiles once per process (mesa keeps lavapipe's on disk), so the first
# round of a scene may include a compilation on lavapipe, which compiles at the first launch; the fastest
# round leaves it out.
set -eu
bin=$1 out=$2 width=$3 spp=$4
shift 4
rounds=${ROUNDS:-2}
modes=(off strategy on)
mkdir -p "$out"
scenes=("$@")
if [ ${#scenes[@]} -eq 0 ]; then mapfile -t scenes < <("$bin/ray-tracing-gpu" --list-scenes | awk '{print $1}'); fi

gpuSeconds() { python3 -c "import json, sys; print(json.load(open(sys.argv[1]))['gpu_seconds'])" "$1"; }

echo "| scene | general s | specialised s | speed-up | relMSE between them | strategy-only s | features' own speed-up |"
echo "|---|---:|---:|---:|---:|---:|---:|"
for scene in "${scenes[@]}"; do
    declare -A best=()
    for ((r = 0; r < rounds; ++r)); do
        for mode in "${modes[@]}"; do
            "$bin/ray-tracing-gpu" --headless --quiet --strategy scene --scene "$scene" --width "$width" --spp "$spp" \
                --specialize "$mode" --hdr "$out/$scene-$mode.pfm" --stats "$out/$scene-$mode.json" >/dev/null
            s=$(gpuSeconds "$out/$scene-$mode.json")
            best[$mode]=$(python3 -c "import sys; print(min(float(sys.argv[1]), float(sys.argv[2])))" "$s" "${best[$mode]:-inf}")
        done
    done
    rel=$(python3 "$(dirname "$0")/pfm_relmse.py" "$out/$scene-on.pfm" "$out/$scene-off.pfm")
    python3 -c "
import sys
off, strategy, on, rel = map(float, sys.argv[2:6])
print(f'| {sys.argv[1]} | {off:.3f} | {on:.3f} | {off / on:.2f}x | {rel:.2e} | {strategy:.3f} | {strategy / on:.2f}x |')
" "$scene" "${best[off]}" "${best[strategy]}" "${best[on]}" "$rel"
    unset best
done
