#!/usr/bin/env bash
# The GPU engine's specialised pipelines against its general one (issue 11): every scene at its own settings
# but WIDTH and SPP, rendered with --specialize off and on alternately (ROUNDS times, the fastest of each
# kept), in one run. Prints one markdown row per scene: the GPU seconds of each, their ratio, and the relMSE of
# the specialised image against the general one (both at SPP with the same seed: noise-level, not zero, where
# the driver compiles the arithmetic differently; a fold that changed the estimator would show far above it).
#   tests/Bench/specialization.sh BIN_DIR OUT_DIR WIDTH SPP [SCENE...]   (default: every catalogue scene)
set -eu
bin=$1 out=$2 width=$3 spp=$4
shift 4
rounds=${ROUNDS:-2}
mkdir -p "$out"
scenes=("$@")
if [ ${#scenes[@]} -eq 0 ]; then mapfile -t scenes < <("$bin/ray-tracing-gpu" --list-scenes | awk '{print $1}'); fi
echo "| scene | general s | specialised s | speed-up | relMSE between them |"
echo "|---|---:|---:|---:|---:|"
for scene in "${scenes[@]}"; do
    for mode in off on; do
        best=
        for ((r = 0; r < rounds; ++r)); do
            "$bin/ray-tracing-gpu" --headless --quiet --scene "$scene" --width "$width" --spp "$spp" \
                --specialize "$mode" --hdr "$out/$scene-$mode.pfm" --stats "$out/$scene-$mode.json" >/dev/null
            s=$(python3 -c "import json; print(json.load(open('$out/$scene-$mode.json'))['gpu_seconds'])")
            best=$(python3 -c "print(min(float('$s'), float('${best:-inf}')))")
        done
        eval "t_$mode=$best"
    done
    rel=$(python3 "$(dirname "$0")/pfm_relmse.py" "$out/$scene-on.pfm" "$out/$scene-off.pfm")
    python3 -c "print(f'| $scene | {$t_off:.3f} | {$t_on:.3f} | {$t_off / $t_on:.2f}x | {float(\"$rel\"):.2e} |')"
done
