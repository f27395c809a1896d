#!/usr/bin/env bash
# The CPU engine's specialised path loops against its general one (issue 11): every scene at its own settings
# but WIDTH and SPP, rendered with --specialize off and on alternately (ROUNDS times, the fastest of each
# kept), on one core (taskset -c 0 when there is taskset), in one run. Prints one markdown row per scene: the
# render seconds of each, their ratio, the loop the specialised render ran, and whether the two images are the
# same bit for bit (they must be: every instance of the loop draws the same random numbers).
#   tests/Bench/cpu_specialization.sh BIN_DIR OUT_DIR WIDTH SPP [SCENE...]   (default: every catalogue scene)
set -eu
bin=$1 out=$2 width=$3 spp=$4
shift 4
rounds=${ROUNDS:-3}
mkdir -p "$out"
pin=()
if command -v taskset >/dev/null; then pin=(taskset -c 0); fi
scenes=("$@")
if [ ${#scenes[@]} -eq 0 ]; then mapfile -t scenes < <("$bin/ray-tracing-cpu" --list-scenes | awk '{print $1}'); fi
echo "| scene | general s | specialised s | speed-up | specialised loop | same image |"
echo "|---|---:|---:|---:|---|---|"
for scene in "${scenes[@]}"; do
    declare -A best=()
    for ((r = 0; r < rounds; ++r)); do
        for mode in off on; do
            "${pin[@]}" "$bin/ray-tracing-cpu" --headless --strategy scene --engine single --scene "$scene" --width "$width" \
                --spp "$spp" --specialize "$mode" --hdr "$out/$scene-$mode.pfm" --stats "$out/$scene-$mode.json" \
                2>"$out/$scene-$mode.log" >/dev/null
            s=$(python3 -c "import json; print(json.load(open('$out/$scene-$mode.json'))['render_seconds'])")
            best[$mode]=$(python3 -c "print(min(float('$s'), float('${best[$mode]:-inf}')))")
        done
    done
    loop=$(python3 -c "import json, re; c = json.load(open('$out/$scene-on.json'))['frame_configuration']; print(re.sub(r'^path loop: (.*) \(scene:.*', r'\1', c))")
    same=$(cmp -s "$out/$scene-on.pfm" "$out/$scene-off.pfm" && echo yes || echo NO)
    python3 -c "print(f'| $scene | {${best[off]}:.3f} | {${best[on]}:.3f} | {${best[off]} / ${best[on]}:.2f}x | $loop | $same |')"
    unset best
done
