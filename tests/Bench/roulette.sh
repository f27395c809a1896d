#!/usr/bin/env bash
# Russian roulette's two rules side by side, per scene, at equal time on one engine: pbrt-v4's (survival m, the
# throughput's largest component; --russian-roulette on) and Blender Cycles' (sqrt(m); sqrt), every other setting
# the scene's own. roulette_table.py OUT_DIR then prints each rule's efficiency 1/(relMSE s) and their ratio.
#   tests/Bench/roulette.sh BIN_DIR OUT_DIR ENGINE WIDTH EQUAL_MS SEEDS REFERENCE_SPP SCENE...
# e.g. roulette.sh build/bin docs/results/cpu-roulette multi 128 1000 3 8192 rtrol-cornell-box cornell-box-lights
# The renders' images go to IMAGES (default OUT_DIR) and are deleted after each scene; the CSVs keep every figure.
set -eu
bin=$1 out=$2 engine=$3 width=$4 equalMs=$5 seeds=$6 referenceSpp=$7
shift 7
images=${IMAGES:-$out}
mkdir -p "$out" "$images"
if [ "$engine" = gpu ]; then app="$bin/ray-tracing-gpu"; else app="$bin/ray-tracing-cpu"; fi
for scene in "$@"; do
    $app --compare --scene "$scene" --engines "$engine" --width "$width" --equal-time "$equalMs" --rounds 1 \
        --seeds "$seeds" --reference-spp "$referenceSpp" --roulettes on,sqrt \
        --csv "$out/$scene.csv" --images "$images/$scene-images" >"$out/$scene.txt" 2>"$out/$scene.log"
    rm -rf "$images/$scene-images"
    echo "$scene done" >&2
done
