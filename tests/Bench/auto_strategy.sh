#!/usr/bin/env bash
# Issue 37's check of --strategy auto, per scene, at equal time on one engine:
#  1. a full --compare over every candidate of auto's defaults (estimators x light samplers x light selections; no
#     selections where the scene has one light, no projected-exact where its lights are spheres, no mixture where it
#     has a microfacet material; the scene's pixel sampling, and Sobol beside it where that is random) with the auto row beside them, its time including its
#     pilot's;
#  2. the best strategy of 1 measured again, and the scene's own strategy and auto with RECHECK_SEEDS fresh seeds
#     (default 12, from seed RECHECK_FIRST_SEED, default 100, below 1000: a render sharing a seed with its
#     reference's halves, seed + 1000 and + 2000, would be correlated with it), against 1's reference: the best of many noisy rows is biased up (the winner's curse), a
#     new measurement is not. Every row against the one reference file: --compare renders its reference with the
#     request's strategy, and a reference's own noise is part of every relMSE (rtrol-cornell-box on an H200 at 8192
#     spp: the scene's mixture's reference had 5x the noise of nee-mis's, half the rows' relMSE at 1 s), so rows
#     measured against two references do not compare. With RECHECK_ONLY=1, a scene whose full comparison's CSV and
#     reference (IMAGES/SCENE-reference.pfm) exist is only rechecked.
# auto_strategy_table.py OUT_DIR then prints auto's efficiency against the best's and the scene's own. Each
# comparison's --table JSON is kept beside its CSV (SCENE.json, SCENE-auto-SEED.json): the auto row's pilots' tables.
#   tests/Bench/auto_strategy.sh BIN_DIR OUT_DIR ENGINE WIDTH EQUAL_MS SEEDS REFERENCE_SPP SCENE...
# e.g. on the CPU: auto_strategy.sh build/bin docs/results/cpu-auto-strategy multi 128 1000 2 8192 cornell-box-lights
# The renders' images go to IMAGES (default OUT_DIR) and are deleted after each scene but the reference.
set -eu
bin=$1 out=$2 engine=$3 width=$4 equalMs=$5 seeds=$6 referenceSpp=$7
shift 7
images=${IMAGES:-$out}
recheckSeeds=${RECHECK_SEEDS:-12}
mkdir -p "$out" "$images"
here=$(cd "$(dirname "$0")" && pwd)
if [ "$engine" = gpu ]; then app="$bin/ray-tracing-gpu"; else app="$bin/ray-tracing-cpu"; fi
for scene in "$@"; do
    # auto's candidates (Compare/AutoStrategy.h autoCandidates): no light selection for one light, no
    # projected-exact for sphere lights, no mixture where the scene has a microfacet material; Sobol beside random
    # pixel samples where the scene's are random (the books' scenes: of the light scenes, rtrol-cornell-box).
    estimators=nee-mis,mixture samplings=
    [ "$scene" = rtrol-cornell-box ] && samplings=random,sobol
    case "$scene" in
    rect-light-closeup | rtrol-cornell-box) samplers=projected,solid-angle,area,projected-exact selections=bvh ;;
    sphere-light-closeup) samplers=projected,solid-angle,area selections=bvh ;;
    veach-mis) samplers=projected,solid-angle,area selections=bvh,power,uniform estimators=nee-mis ;;
    glossy-cornell) samplers=projected,solid-angle,area,projected-exact selections=bvh,power,uniform estimators=nee-mis ;;
    *) samplers=projected,solid-angle,area,projected-exact selections=bvh,power,uniform ;;
    esac
    common=(--scene "$scene" --engines "$engine" --width "$width" --equal-time "$equalMs" --rounds 1)
    # The scene's own strategy, as the stats record it.
    $app --headless --quiet --strategy scene --scene "$scene" --width 8 --spp 1 --depth 1 --stats "$out/$scene-defaults.json" >/dev/null
    reference="$images/$scene-reference.pfm"
    if [ "${RECHECK_ONLY:-0}" != 1 ] || [ ! -f "$out/$scene.csv" ] || [ ! -f "$reference" ]; then
        $app --compare "${common[@]}" --seeds "$seeds" --reference-spp "$referenceSpp" --strategy auto \
            --estimators "$estimators" --light-samplers "$samplers" --light-selections "$selections" \
            ${samplings:+--samplings "$samplings"} --csv "$out/$scene.csv" --images "$images/$scene-images" --table "$out/$scene.json" \
            >"$out/$scene.txt" 2>"$out/$scene.log"
        mv "$images/$scene-images/reference.pfm" "$reference"
    fi
    read -r estimator sampler selection sampling roulette < <(/usr/bin/python3 "$here/auto_strategy_table.py" --best "$out/$scene.csv")
    # The rechecks seed by seed, the best's and then the own's and auto's (one --compare, whose rows take turns):
    # a row's seeds rendered as one block met whatever the machine's speed was then (±10 % between blocks on the CI
    # kind's 2 cores), and that drift read as the rows' difference.
    rm -f "$out/$scene-recheck-best".{csv,txt} "$out/$scene-recheck".{csv,txt}
    for ((k = 0; k < recheckSeeds; ++k)); do
        seed=$((${RECHECK_FIRST_SEED:-100} + k))
        $app --compare "${common[@]}" --seeds 1 --seed "$seed" --reference "$reference" --estimator "$estimator" \
            --light-sampler "$sampler" --light-selection "$selection" --sampling "$sampling" \
            --russian-roulette "${roulette#rr-}" --csv "$images/$scene-best-$seed.csv" \
            --images "$images/$scene-recheck-images" >>"$out/$scene-recheck-best.txt" 2>/dev/null
        $app --compare "${common[@]}" --seeds 1 --seed "$seed" --reference "$reference" --strategy auto \
            --csv "$images/$scene-auto-$seed.csv" --images "$images/$scene-recheck-images" \
            --table "$out/$scene-auto-$seed.json" >>"$out/$scene-recheck.txt" 2>/dev/null
        for kind in best:recheck-best auto:recheck; do
            part="$images/$scene-${kind%%:*}-$seed.csv" whole="$out/$scene-${kind#*:}.csv"
            if [ -f "$whole" ]; then tail -n +2 "$part" >>"$whole"; else cp "$part" "$whole"; fi
            rm -f "$part"
        done
        rm -rf "$images/$scene-recheck-images"
    done
    rm -rf "$images/$scene-images" "$images/$scene-recheck-images" # the CSVs keep every figure
    echo "$scene done" >&2
done
