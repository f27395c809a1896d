#!/usr/bin/env bash
# Every catalogue scene x estimator x pixel sampling, and NEE's samplers, selections and options, rendered by one ray-tracing-cpu into a folder of PFMs,
# or two such folders compared byte for byte: the check that a change of the CPU engine's code leaves its
# images as they were (issue 34: "the same images bit for bit on the CPU").
#   tests/Bench/cpu_images.sh render BIN OUT_DIR [WIDTH (default 64)] [SPP (default 8)]
#   tests/Bench/cpu_images.sh compare DIR_A DIR_B
# `compare` prints one line per image that differs, with its relMSE (tests/Bench/pfm_relmse.py), and a count;
# it exits 1 when an image is missing on either side.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
mode=${1:?usage: cpu_images.sh render BIN OUT_DIR [WIDTH] [SPP] | compare DIR_A DIR_B}
case "$mode" in
render)
    bin=$2 out=$3 width=${4:-64} spp=${5:-8}
    mkdir -p "$out"
    scenes=$("$bin" --list-scenes | awk 'NF && $1 !~ /:$/ {print $1}')
    n=0
    for scene in $scenes; do
        variants=()
        for estimator in bsdf mixture nee nee-mis; do
            for sampling in random stratified sobol; do
                variants+=("$estimator-$sampling:--estimator $estimator --sampling $sampling")
            done
        done
        # NEE's samplers and selections, the emitters' sides and the general (unspecialised) path loop.
        for sampler in area solid-angle; do
            variants+=("nee-mis-$sampler:--estimator nee-mis --sampling sobol --light-sampler $sampler")
        done
        for selection in uniform power; do
            variants+=("nee-mis-$selection:--estimator nee-mis --sampling random --light-selection $selection")
        done
        variants+=("nee-mis-two-sided:--estimator nee-mis --unidirectional-light off"
            "nee-mis-general:--estimator nee-mis --specialize off" "mixture-general:--estimator mixture --specialize off"
            "bsdf-no-roulette:--estimator bsdf --russian-roulette off")
        for variant in "${variants[@]}"; do
            # shellcheck disable=SC2086
            "$bin" --headless --quiet --strategy scene --engine multi --scene "$scene" --width "$width" --spp "$spp" ${variant#*:} \
                --hdr "$out/$scene-${variant%%:*}.pfm" >/dev/null
            n=$((n + 1))
        done
    done
    echo "$n images in $out"
    ;;
compare)
    a=$2 b=$3
    same=0 different=0 missing=0
    for fa in "$a"/*.pfm; do
        name=$(basename "$fa")
        fb="$b/$name"
        if [ ! -f "$fb" ]; then
            echo "missing in $b: $name"
            missing=$((missing + 1))
        elif cmp -s "$fa" "$fb"; then
            same=$((same + 1))
        else
            echo "different: $name relMSE $(python3 "$here/pfm_relmse.py" "$fb" "$fa" 2>/dev/null || echo '?')"
            different=$((different + 1))
        fi
    done
    echo "$same the same bit for bit, $different different, $missing missing"
    [ "$missing" -eq 0 ]
    ;;
*)
    echo "usage: cpu_images.sh render BIN OUT_DIR [WIDTH] [SPP] | compare DIR_A DIR_B" >&2
    exit 2
    ;;
esac
