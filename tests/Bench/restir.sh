#!/usr/bin/env bash
# Issue 36's efficiency check: restir-di against nee-mis with the light BVH, at equal time, on one engine, every row
# the mean of SEEDS independent renders (restir-di's pixels and iterations are correlated). Per scene: nee-mis
# (projected, bvh) and restir-di (its defaults: 32 candidates from projected x bvh, 5 neighbours, temporal cap 20),
# then restir-di with temporal cap 1, with 32 and with 8 candidates, against one reference (nee-mis, REFERENCE_SPP,
# cached on disk).
#   tests/Bench/restir.sh BIN_DIR OUT_DIR ENGINE WIDTH EQUAL_MS SEEDS REFERENCE_SPP SCENE[:COUNT]...
# e.g. tests/Bench/restir.sh build/bin docs/results/cpu-restir multi 128 3000 4 2048 lamp-room many-lights:10000
# FLAGS: more flags for every render and its reference, e.g. FLAGS="--depth 2": direct light at the first vertex alone,
# the part of the image restir-di's resampling serves (notebook §58).
set -eu
bin=$1 out=$2 engine=$3 width=$4 equalMs=$5 seeds=$6 referenceSpp=$7
shift 7
mkdir -p "$out"
if [ "$engine" = gpu ]; then app="$bin/ray-tracing-gpu"; else app="$bin/ray-tracing-cpu"; fi
for entry in "$@"; do
    scene=${entry%%:*}
    name=$scene
    count=()
    if [ "$entry" != "$scene" ]; then
        count=(--count "${entry#*:}")
        name="$scene-${entry#*:}"
    fi
    common=(--compare --scene "$scene" "${count[@]}" --engines "$engine" --width "$width" --equal-time "$equalMs"
        --rounds 1 --seeds "$seeds" --reference-spp "$referenceSpp" --light-sampler projected --light-selection bvh)
    read -r -a extra <<<"${FLAGS:-}"
    common+=("${extra[@]}")
    $app "${common[@]}" --estimators nee-mis,restir-di --csv "$out/$name.csv" --output "$out/$name.png" \
        >"$out/$name.txt" 2>"$out/$name.log"
    for variant in "c1 --restir-temporal-cap 1" "c1-m8 --restir-temporal-cap 1 --restir-candidates 8"; do
        tag=${variant%% *}
        read -r -a flags <<<"${variant#* }"
        $app "${common[@]}" --estimators restir-di "${flags[@]}" --csv "$out/$name-$tag.csv" \
            --output "$out/$name-$tag.png" >"$out/$name-$tag.txt" 2>"$out/$name-$tag.log"
    done
done
