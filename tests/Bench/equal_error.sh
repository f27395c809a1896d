#!/usr/bin/env bash
# Issue 42's time to equal error on the GPU: cornell-box-lights at 600x600, the thesis' estimator (book 3's mixture,
# no roulette, random samples) at 1000 spp against a reference of REF_SPP (32768) spp, and the renders that should
# reach its relMSE sooner (STRATEGIES: --compare's strategy lists, ";" between runs) on a ladder of spp (SPP_LIST),
# SEEDS (2) seeds and ROUNDS (3) rounds each, all against that one reference. equal_error_table.py OUT_DIR then
# interpolates each strategy's time to the mixture's error.
#   tests/Bench/equal_error.sh BIN_DIR OUT_DIR
set -eu
bin=$1 out=$2
scene=${SCENE:-cornell-box-lights} width=${WIDTH:-600}
strategies=${STRATEGIES:-"--estimators nee-mis --roulettes on,sqrt --light-samplers projected,area"}
mkdir -p "$out"
images=${IMAGES:-/tmp/equal-error-images}
rm -rf "$images"
common=(--scene "$scene" --engines gpu --width "$width" --seeds "${SEEDS:-2}" --rounds "${ROUNDS:-3}")
"$bin/ray-tracing-gpu" --compare "${common[@]}" --reference-spp "${REF_SPP:-32768}" --spp-list 1000 \
    --estimators mixture --roulettes off --samplings random --csv "$out/mixture-1000.csv" --images "$images/mixture" \
    >"$out/mixture-1000.txt" 2>&1
IFS=';' read -r -a runs <<<"$strategies"
for i in "${!runs[@]}"; do
    # shellcheck disable=SC2086 # the strategy's flags split on spaces
    "$bin/ray-tracing-gpu" --compare "${common[@]}" --reference "$images/mixture/reference.pfm" \
        --spp-list "${SPP_LIST:-96,128,160,192,256}" ${runs[$i]} --csv "$out/run-$i.csv" --images "$images/run-$i" \
        >"$out/run-$i.txt" 2>&1
    rm -rf "$images/run-$i"
done
