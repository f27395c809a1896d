#!/usr/bin/env bash
# The light-sampling efficiency table: for each scene, one long NEE + MIS render as the reference, then every
# strategy's spp ladder on one engine against it (ray-tracing-gpu --compare --reference), and a table of
# efficiency 1 / (relMSE x time) per strategy (tests/Bench/efficiency_table.py). Used for docs/notebook/PERFORMANCE.md.
#   tests/Bench/efficiency.sh BIN_DIR OUT_DIR ENGINE WIDTH REFERENCE_SPP SPP_LIST SCENE...
# e.g. on the lent GPU: efficiency.sh .devcarry/bin "$OUT" gpu 600 20000 64,256,1024 cornell-box-lights
set -eu
bin=$1 out=$2 engine=$3 width=$4 referenceSpp=$5 sppList=$6
shift 6
mkdir -p "$out"
# estimator, light sampler, light selection, Russian roulette[, pixel sampling (default random)];
# STRATEGIES="nee-mis projected bvh on sobol;..." picks others
strategies=(
    "mixture solid-angle power on"
    "mixture solid-angle power off"
    "nee projected power on"
    "nee-mis area uniform on"
    "nee-mis solid-angle power on"
    "nee-mis projected uniform on"
    "nee-mis projected power on"
    "nee-mis projected power off"
    "nee-mis projected bvh on"
)
if [ -n "${STRATEGIES:-}" ]; then IFS=';' read -r -a strategies <<<"$STRATEGIES"; fi
for scene in "$@"; do
    reference="$out/$scene-reference.pfm"
    if [ "$engine" = gpu ]; then app="$bin/ray-tracing-gpu"; else app="$bin/ray-tracing-cpu --engine $engine"; fi
    $app --headless --quiet --strategy scene --scene "$scene" --width "$width" --estimator nee-mis --spp "$referenceSpp" \
        --seed 7777 --hdr "$reference" --stats "$out/$scene-reference.json" >/dev/null
    for s in "${strategies[@]}"; do
        set -- $s
        sampling=${5:-random}
        name="$scene-$1-$2-$3-rr$4"
        [ "$sampling" = random ] || name="$name-$sampling"
        "$bin/ray-tracing-gpu" --compare --quiet --scene "$scene" --width "$width" --engines "$engine" \
            --estimator "$1" --light-sampler "$2" --light-selection "$3" --russian-roulette "$4" --sampling "$sampling" \
            --spp-list "$sppList" --reference "$reference" --table "$out/$name.json" >/dev/null
        echo "$name done" >&2
    done
done
