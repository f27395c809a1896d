#!/usr/bin/env bash
# Runs on the lent NVIDIA machine (the workplace's `device` tool), from the repository root, with the build
# carried in .devcarry/ (bin/: the binaries, shaders and assets; lib/: the shared libraries ldd lists beyond
# glibc; layers/: the Khronos validation layer) and Debian's Vulkan loader in .gl/, both made here by
# tests/Bench/device_carry.sh (figures in docs/notebook/PERFORMANCE.md).
#   tests/Bench/device_run.sh tests    the GPU test suite (but its heavy part), the apps' smoke tests and --heatmap's
#   tests/Bench/device_run.sh samplers the light samplers at equal time on the light scenes (issue 37)
#   tests/Bench/device_run.sh roulette Russian roulette's rules (pbrt-v4's, Cycles' sqrt) at equal time on every
#                                      catalogue scene (roulette.sh): ENGINE gpu (WIDTH 400, MS 500, SEEDS 3,
#                                      REF_SPP 8192) or multi (the host's every core; WIDTH 128, MS 1000)
#   tests/Bench/device_run.sh equal-error  issue 42: cornell-box-lights' time to the thesis' mixture-1000 error
#                                      (equal_error.sh; its STRATEGIES, SPP_LIST, SEEDS, ROUNDS, REF_SPP)
#   tests/Bench/device_run.sh pilot        --strategy auto's headless pilot on SCENES at SPPS, 600 px, for SEEDS:
#                                      its table and its host clock
#   tests/Bench/device_run.sh pilot-sizes  the GPU's time by image size, spp and integrator (pilot_sizes.sh)
#   tests/Bench/device_run.sh auto     --strategy auto against a full --compare at equal time (auto_strategy.sh)
#                                      (SCENES split by '|': lanes side by side, one GPU each)
#   tests/Bench/device_run.sh heavy    the heavy part: CPU/GPU agreement of every scene at 128 px, 64 spp (FILTER:
#                                      a gtest filter within it)
#   tests/Bench/device_run.sh table    thesis Table 5.4 redone: cornell-box-lights 600x600, depth 50, mixture
#   tests/Bench/device_run.sh estimators  the same scene on the GPU with each estimator against one reference
#   tests/Bench/device_run.sh specialization  issue 11: every scene with the general, strategy-only and
#                                      strategy + features pipelines (600 px, 256 spp; SPEC_WIDTH, SPEC_SPP,
#                                      ROUNDS), then the figure: cornell-box-lights 600x600, 1000 spp, mixture
#   tests/Bench/device_run.sh restir   issue 36: restir-di against nee-mis at equal time (tests/Bench/restir.sh)
#   tests/Bench/device_run.sh ab [RENDERS_FILE]  the baseline build (.devcarry/baseline, BASELINE_BIN of
#                                      device_carry.sh) against this one, render by render (gpu_ab.sh)
#   tests/Bench/device_run.sh bars     issue 9's efficiency bars in one run: cornell-box-lights (mixture
#                                      against nee-mis) and many-lights (light selections), by --compare
#                                      (INTEGRATOR: the GPU integrator, default the app's)
#   tests/Bench/device_run.sh rays [RENDERS_FILE]  issue 42: every catalogue scene (600 px, 256 spp; or the
#                                      renders of RENDERS_FILE) without and with
#                                      --count-rays: what counting costs, the images alike, rays per second by kind
#   tests/Bench/device_run.sh cpu-rays [RENDERS_FILE]  issue 42: the host's CPU engine on every core, rays per
#                                      second by kind (default: the renders of `rays`)
#   tests/Bench/device_run.sh integrators [RENDERS_FILE]  the megakernel against the wavefront, render by
#                                      render (default tests/Bench/renders/integrators.txt)
#   tests/Bench/device_run.sh veach     issue 35: Veach's MIS scene, bsdf / nee / nee-mis each for BUDGET_MS
#                                      (1000) on the GPU, SEEDS (4) seeds, against one nee-mis reference of
#                                      REF_SPP (262144); relMSE per plate x light region (veach_regions.py)
#   tests/Bench/device_run.sh scaling [RANKS]  issue 40: cornell-box-lights WIDTH (1200) px at SPP (65536) spp on
#                                      one GPU and split over mpirun's ranks, one GPU each (RANKS, default "2 4",
#                                      "1" the single process only), tests/Bench/scaling.sh
#   tests/Bench/device_run.sh compare-scaling [RANKS]  issue 40: a --compare sweep of 24 rows on one GPU and over
#                                      mpirun's ranks (RANKS, default "1 2"), tests/Bench/compare_scaling.sh
#   tests/Bench/device_run.sh thesis   issue 39: the thesis' figures and Table 5.4, its values beside ours
#                                      (tests/Bench/thesis_figures.sh; its images packed by pfm_pack.py)
#   tests/Bench/device_run.sh mpi      tests/Cli/mpi.sh and mpi_compare.sh on this driver: split renders, errors,
#                                      Ctrl-C, a killed rank; a distributed --compare
#   tests/Bench/device_run.sh window-frames  issue 38: the GPU window's frames (1 to 64 samples each, one submission
#                                      per frame) against headless renders, on the device's clock (rt_gpu_bench;
#                                      ROUNDS repetitions, interleaved)
#   tests/Bench/device_run.sh variants RENDERS_FILE  the shader variants carried in .devcarry/variants/ (VARIANTS
#                                      of device_carry.sh) against the build's own shaders, render by render
#                                      (shader_variants.sh)
set -u
mode=${1:-tests}
out=${OUT:-/tmp/out}
mkdir -p "$out"
for f in .gl/*.deb; do dpkg -x "$f" /; done
# Open MPI: the host's (docs/SCALING.md), else Debian's carried in .mpi/ (MPI_DEBS=1 of device_carry.sh).
if ! command -v mpirun >/dev/null; then for f in .mpi/*.deb; do [ -e "$f" ] && dpkg -x "$f" /; done; fi
ldconfig
export LD_LIBRARY_PATH=$PWD/.devcarry/lib
for f in .devcarry/layers/*.xz; do [ -e "$f" ] && xz -dc "$f" >"${f%.xz}"; done
export VK_LAYER_PATH=$PWD/.devcarry/layers
if ! ls /usr/share/vulkan/icd.d/nvidia_icd.json /etc/vulkan/icd.d/nvidia_icd.json >/dev/null 2>&1; then
    export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
fi
# The tests find the app at the path it had when they were built.
mkdir -p /work/main/build && ln -sfn "$PWD/.devcarry/bin" /work/main/build/bin
bin=/work/main/build/bin
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader
echo "CPU: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2)"

case "$mode" in
tests)
    "$bin/ray-tracing-gpu" --headless --strategy scene --validation --scene rtrol-cornell-glass --width 200 --spp 16 \
        --output "$out/glass.png" --stats "$out/glass.json"
    "$bin/rt_gpu_tests" --gtest_brief=1 --gtest_filter='-Heavy/*' 2>&1 | tail -40
    bash tests/Cli/bad_input.sh "$bin/ray-tracing-gpu" | grep -v "^ok"
    bash tests/Cli/heatmap.sh "$bin/ray-tracing-gpu"
    "$bin/ray-tracing-gpu" --headless --quiet --strategy scene --scene rtrol-cornell-glass --width 400 --spp 64 --heatmap "$out/glass-cost.png" \
        --stats "$out/glass-cost.json" --output "$out/glass-cost-image.png"
    RT_GLTF_MODELS=$PWD/.devcarry/gltf bash tests/Cli/scene_files.sh "$bin/ray-tracing-gpu" . | grep -v "^ok"
    ;;
window-frames)
    "$bin/rt_gpu_bench" --benchmark_enable_random_interleaving=true --benchmark_repetitions="${ROUNDS:-5}" \
        --benchmark_report_aggregates_only=true --benchmark_out="$out/window-frames.json" --benchmark_out_format=json 2>&1 |
        tail -60
    ;;
heavy)
    "$bin/rt_gpu_tests" --gtest_brief=1 --gtest_filter="${FILTER:-Heavy/*}" 2>&1 | tail -40
    ;;
table)
    # The thesis' estimator (book 3's mixture) with the random samples of the table's first runs.
    "$bin/ray-tracing-gpu" --compare --quiet --scene cornell-box-lights --width 600 --depth 50 \
        --estimator mixture --sampling random --spp-list 10,50,100,250,500,1000,2000,5000 --engines multi,gpu \
        --reference-spp 20000 --table "$out/table.json"
    ;;
estimators)
    # One reference for every estimator (nee-mis, the least noisy, at 50,000 spp), then each estimator's
    # ladder against it: relMSE against GPU time.
    "$bin/ray-tracing-gpu" --headless --quiet --strategy scene --scene cornell-box-lights --width 600 --depth 50 \
        --estimator nee-mis --spp 50000 --seed 7777 --hdr "$out/reference.pfm" --stats "$out/reference.json"
    for e in mixture nee nee-mis; do
        "$bin/ray-tracing-gpu" --compare --quiet --scene cornell-box-lights --width 600 --depth 50 \
            --estimator "$e" --spp-list 25,50,100,250,500,1000 --engines gpu --reference "$out/reference.pfm" \
            --table "$out/estimator-$e.json"
    done
    ;;
specialization)
    # Images stay on the machine (about 13 MB a scene); the tables and the stats come back.
    work=/tmp/specialization
    mkdir -p "$work" "$out/specialization"
    ROUNDS=${ROUNDS:-2} bash tests/Bench/specialization.sh "$bin" "$work" "${SPEC_WIDTH:-600}" "${SPEC_SPP:-256}" |
        tee "$out/specialization.md"
    cp "$work"/*.json "$out/specialization/"
    ROUNDS=3 bash tests/Bench/specialization_figure.sh "$bin" "$work/figure" | tee "$out/figure.txt"
    cp "$work"/figure/*.json "$out/specialization/"
    ;;
rays)
    # Issue 42: every catalogue scene at 600 px, 256 spp without and with --count-rays (the same build), the
    # images compared (NEE's the same bits; restir-di's within a driver's rounding, notebook §43), then the rays
    # per second by kind.
    renders=/tmp/rays-renders.txt
    grep -v '^\s*\(#\|$\)' "${2:-tests/Bench/renders/catalogue-256.txt}" | sed 's/^\([^ ]*\) \(.*\)$/\1 \2 || \2 --count-rays/' \
        >"$renders"
    ROUNDS=${ROUNDS:-2} bash tests/Bench/gpu_ab.sh "$bin" "$bin" /tmp/rays "$renders" | tee "$out/rays-ab.txt"
    python3 tests/Bench/rays_table.py /tmp/rays "$renders" | tee "$out/rays.md"
    (cd /tmp/rays && tar -czf "$out/rays-stats.tar.gz" ./*.json)
    ;;
cpu-rays)
    # Issue 42: the host's CPU engine (every core) on the renders of `rays`: its rays per second by kind.
    bash tests/Bench/cpu_rays.sh "$bin/ray-tracing-cpu" "${2:-tests/Bench/renders/catalogue-256.txt}" /tmp/cpurays |
        tee "$out/cpu-rays.md"
    (cd /tmp/cpurays && tar -czf "$out/cpu-rays-stats.tar.gz" ./*.json)
    ;;
integrators)
    ROUNDS=${ROUNDS:-2} bash tests/Bench/gpu_ab.sh "$bin" "$bin" /tmp/ab "${2:-tests/Bench/renders/integrators.txt}" |
        tee "$out/integrators.txt"
    (cd /tmp/ab && tar -czf "$out/integrators-stats.tar.gz" ./*.json)
    ;;
bars)
    integrator=${INTEGRATOR:+--integrator $INTEGRATOR}
    # shellcheck disable=SC2086 # $integrator is empty or two words
    "$bin/ray-tracing-gpu" --compare --quiet $integrator --scene cornell-box-lights --width 600 --engines gpu \
        --reference-spp 16384 --estimators mixture,nee-mis --roulettes off,on --samplings random,sobol \
        --spp-list 256,1024 --csv "$out/cbl.csv" --table "$out/cbl.json"
    # shellcheck disable=SC2086
    "$bin/ray-tracing-gpu" --compare --quiet $integrator --scene many-lights --width 600 --engines gpu --reference-spp 4096 \
        --estimators nee-mis --light-selections uniform,power,bvh --samplings random,sobol --spp-list 64,256 \
        --csv "$out/ml.csv" --table "$out/ml.json"
    ;;
veach)
    # Seed 1's comparison renders the reference (nee-mis, REF_SPP in two halves whose difference gives its
    # own relMSE); the other seeds measure against that file.
    budget=${BUDGET_MS:-1000}
    rm -rf /tmp/veach && mkdir -p /tmp/veach && "$bin/ray-tracing-gpu" --scene veach-mis --export-scene /tmp/veach/veach-mis.json
    folders=()
    for seed in $(seq 1 "${SEEDS:-4}"); do
        if [ "$seed" = 1 ]; then
            reference=(--estimator nee-mis --reference-spp "${REF_SPP:-262144}" --reference-cache off)
        else
            reference=(--reference /tmp/veach/seed-1/reference.pfm)
        fi
        "$bin/ray-tracing-gpu" --compare --quiet --scene veach-mis --engines gpu --estimators bsdf,nee,nee-mis \
            --equal-time "$budget" "${reference[@]}" --seed "$seed" --images "/tmp/veach/seed-$seed"
        folders+=("/tmp/veach/seed-$seed")
    done
    python3 tests/Bench/veach_regions.py --scene /tmp/veach/veach-mis.json --budget-ms "$budget" \
        --json "$out/regions.json" --markdown "$out/regions.md" "${folders[@]}"
    # Seed 1's images come back for the figures (the tool brings back 8 files).
    mkdir -p "$out/seed-1" && cp /tmp/veach/seed-1/*.pfm /tmp/veach/seed-1/images.json "$out/seed-1/"
    ;;
variants)
    set -o pipefail
    ls -d .devcarry/variants/*/ >/dev/null || { echo "no shader variants carried (VARIANTS of device_carry.sh)"; exit 2; }
    ROUNDS=${ROUNDS:-3} bash tests/Bench/shader_variants.sh "$bin" /tmp/variants "${2:?variants needs a RENDERS_FILE}" \
        "$bin/shaders" .devcarry/variants/* | tee "$out/variants.txt"
    ;;
samplers)
    # Issue 37's light samplers at equal time on the light scenes: solid-angle, projected (the bilinear warp for
    # polygons, the horizon-clipped cap for spheres) and projected-exact (Peters 2021 for polygons), nee-mis,
    # SEEDS (4) seeds of MS (1000) ms each against a REF_SPP (65536) reference; tables, CSVs and figures in one
    # archive (the device tool brings back few files).
    rm -rf /tmp/samplers && mkdir -p /tmp/samplers
    for scene in ${SCENES:-rect-light-closeup sphere-light-closeup triangle-lights cornell-box-lights}; do
        "$bin/ray-tracing-gpu" --compare --quiet --scene "$scene" --width "${WIDTH:-600}" --engines gpu \
            --estimators nee-mis --light-samplers solid-angle,projected,projected-exact --equal-time "${MS:-1000}" \
            --seeds "${SEEDS:-4}" --rounds 1 --reference-spp "${REF_SPP:-65536}" --reference-cache off \
            --output "/tmp/samplers/$scene-grid.png" --csv "/tmp/samplers/$scene.csv" | tee "/tmp/samplers/$scene.txt"
    done
    cat /tmp/samplers/*.txt >"$out/samplers.txt"
    (cd /tmp/samplers && tar -czf "$out/samplers.tar.gz" ./*)
    ;;
equal-error)
    rm -rf /tmp/equal-error && bash tests/Bench/equal_error.sh "$bin" /tmp/equal-error
    tail -n 8 /tmp/equal-error/*.txt
    (cd /tmp/equal-error && tar -czf "$out/equal-error.tar.gz" ./*)
    ;;
roulette)
    engine=${ENGINE:-gpu}
    if [ "$engine" = gpu ]; then width=${WIDTH:-400} ms=${MS:-500}; else width=${WIDTH:-128} ms=${MS:-1000}; fi
    rm -rf "/tmp/roulette-$engine" && mkdir -p "/tmp/roulette-$engine"
    scenes=${SCENES:-$("$bin/ray-tracing-gpu" --list-scenes | awk '{print $1}')}
    for scene in $scenes; do
        IMAGES=/tmp/roulette-images bash tests/Bench/roulette.sh "$bin" "/tmp/roulette-$engine" "$engine" "$width" "$ms" \
            "${SEEDS:-3}" "${REF_SPP:-8192}" "$scene"
        (cd "/tmp/roulette-$engine" && tar -czf "$out/roulette-$engine.tar.gz" ./*)
    done
    ;;
pilot)
    # Issue 37: --strategy auto's headless pilot (its table, time model and frames) on SCENES at 600 px, at each
    # of SPPS, for each of SEEDS (default 0; the first render of the lease compiles the candidates' pipelines), with
    # PILOT_BUDGET (default 0.05): the table, then the pilot's host clock (the probe's extra per render, the
    # preparation and its compiling, the search, its renders, their tracing, its frames' stages and its scoring)
    # beside the GPU's.
    for scene in ${SCENES:-cornell-box-lights}; do
        for spp in ${SPPS:-1460}; do
            for seed in ${SEEDS:-0}; do
                stats="$out/pilot-$scene-$spp-$seed.json"
                "$bin/ray-tracing-gpu" --headless --strategy auto --strategy-cache off --scene "$scene" --width 600 \
                    --spp "$spp" --seed "$seed" --pilot-budget "${PILOT_BUDGET:-0.05}" --stats "$stats" 2>&1 |
                    grep -v "^\[" | tail -20
                python3 -c "import json,sys; c=json.load(open(sys.argv[1]))['strategy_choice']; print({k: c[k] for k in ('render_cost', 'half_overhead_ms', 'pilot_frame_configuration', 'pilot_width', 'pilot_spp', 'budget_seconds', 'pilot_ms', 'too_short', 'budget_spent', 'probe_host_extra_ms', 'probe_ms', 'candidates_cost_scale', 'prepare_seconds', 'search_seconds', 'search_render_host_seconds', 'search_tracing_host_seconds', 'search_scoring_seconds', 'prepare_compile_seconds', 'search_stage_seconds', 'pilot_wall_seconds', 'probe_seconds')})" "$stats"
            done
        done
    done
    ;;
pilot-sizes)
    # Issue 37's GPU pilot: render time on the GPU's clock by image size, spp and integrator (pilot_sizes.sh; SCENE).
    bash tests/Bench/pilot_sizes.sh "$bin" "$out" "${SCENE:-cornell-box-lights}"
    ;;
auto)
    # Issue 37's --strategy auto: a headless pilot on cornell-box-lights at 600 px, 1024 spp, twice (the driver's
    # shader cache cold, then warm: the pilot's wall time includes its pipelines' compilation; HEADLESS_RUNS= skips
    # them), then
    # auto_strategy.sh at equal time (MS, default 500) on SCENES at WIDTH (600), SEEDS (2) seeds, REF_SPP (8192).
    # SCENES split by '|' run as lanes side by side, lane k on the host's GPU k (--device k), each its scenes in turn:
    # one build's table of many scenes in fewer device-minutes (each render has its GPU to itself; the host's cores
    # are shared, its pilots' clock too).
    # The archive is written again after each scene: what a run past the device's time limit leaves under $OUT
    # still comes back (the tool brings back few files, so one archive).
    rm -rf /tmp/auto /tmp/auto-lanes /tmp/auto-lanes.tar.gz && mkdir -p /tmp/auto
    for run in ${HEADLESS_RUNS-cold warm}; do
        "$bin/ray-tracing-gpu" --headless --quiet --strategy auto --scene cornell-box-lights --width 600 --spp 1024 \
            --stats "/tmp/auto/headless-$run.json" | tee "/tmp/auto/headless-$run.txt"
    done
    IFS='|' read -r -a lanes <<<"${SCENES:-rect-light-closeup sphere-light-closeup triangle-lights cornell-box-lights}"
    for k in "${!lanes[@]}"; do
        laneBin=$bin
        if [ "${#lanes[@]}" -gt 1 ]; then
            laneBin=/tmp/auto-lanes/$k && mkdir -p "$laneBin"
            printf '#!/bin/sh\nexec %q --device %d "$@"\n' "$(realpath "$bin/ray-tracing-gpu")" "$k" \
                >"$laneBin/ray-tracing-gpu"
            chmod +x "$laneBin/ray-tracing-gpu"
        fi
        (
            # The device the lane's renders use, as the app reports it (the stats name only its model).
            "$laneBin/ray-tracing-gpu" --list-devices >"/tmp/auto/lane-$k-devices.txt" 2>&1
            for scene in ${lanes[$k]}; do
                IMAGES=/tmp/auto-images-$k bash tests/Bench/auto_strategy.sh "$laneBin" /tmp/auto gpu "${WIDTH:-600}" \
                    "${MS:-500}" "${SEEDS:-2}" "${REF_SPP:-8192}" "$scene"
                # tar exits 1 on a file the other lane is writing (the archive is still whole), 2 on a fatal error.
                (
                    flock 9
                    cd /tmp/auto && tar -czf /tmp/auto-lanes.tar.gz ./*
                    [ $? -le 1 ] && cp /tmp/auto-lanes.tar.gz "$out/auto.tar.gz.part" &&
                        mv "$out/auto.tar.gz.part" "$out/auto.tar.gz"
                ) 9>/tmp/auto-lanes.lock
            done
        ) &
    done
    wait
    python3 tests/Bench/auto_strategy_table.py /tmp/auto | tee "$out/auto.md"
    ;;
restir)
    # Issue 36: restir-di against nee-mis with the light BVH at equal time on the GPU (tests/Bench/restir.sh): WIDTH
    # (400) px, MS (1000) ms a render, SEEDS (4) seeds, against a nee-mis reference of REF_SPP (4096) spp, on SCENES.
    # The archive is written again after each scene (a run past the time limit still brings back what it did).
    rm -rf /tmp/restir && mkdir -p /tmp/restir
    for scene in ${SCENES:-lamp-room many-lights:10000 cornell-box-lights}; do
        bash tests/Bench/restir.sh "$bin" /tmp/restir gpu "${WIDTH:-400}" "${MS:-1000}" "${SEEDS:-4}" \
            "${REF_SPP:-4096}" "$scene"
        cat /tmp/restir/*.txt >"$out/restir.txt"
        (cd /tmp/restir && tar -czf "$out/restir.tar.gz" ./*)
    done
    ;;
scaling)
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_mca_base_component_show_load_errors=0
    bash tests/Bench/scaling.sh "$bin" /tmp/scaling ${2:-2 4} | tee "$out/scaling.txt"
    cp /tmp/scaling/*.json /tmp/scaling/*.wall "$out/"
    ;;
compare-scaling)
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_mca_base_component_show_load_errors=0
    rm -rf /tmp/compare-scaling
    bash tests/Bench/compare_scaling.sh "$bin" /tmp/compare-scaling ${2:-1 2} | tee "$out/compare-scaling.txt"
    cp /tmp/compare-scaling/sweep-* "$out/"
    ;;
thesis)
    # The thesis' figures (tests/Bench/thesis_figures.sh). This machine has no matplotlib: the runs' JSON come
    # back in thesis.tar and the images packed as float16 (pfm_pack.py); drawn here by
    #   pfm_pack.py unpack DIR/images images-*.npz && thesis_figures.py DIR
    rm -rf /tmp/thesis
    bash tests/Bench/thesis_figures.sh /tmp/thesis "$bin"
    cat /tmp/thesis/cpu-gpu.txt /tmp/thesis/gpu.txt
    tar -C /tmp/thesis -cf "$out/thesis.tar" --exclude='*.pfm' .
    python3 tests/Bench/pfm_pack.py pack /tmp/thesis/images "$out/images"
    ;;
mpi)
    # The MPI suite of the default tests on this driver (tests/Cli/mpi.sh), ranks on the host's GPUs.
    export OMPI_MCA_mca_base_component_show_load_errors=0
    bash tests/Cli/mpi.sh "$bin/ray-tracing-gpu" gpu && bash tests/Cli/mpi_compare.sh "$bin/ray-tracing-gpu" gpu
    ;;
ab)
    ROUNDS=${ROUNDS:-3} bash tests/Bench/gpu_ab.sh .devcarry/baseline "$bin" /tmp/ab ${2:-} | tee "$out/ab.txt"
    # One archive of every render's stats: the device tool brings back a limited number of files.
    (cd /tmp/ab && tar -czf "$out/ab-stats.tar.gz" ./*.json)
    ;;
esac
