#!/usr/bin/env bash
# Two builds of ray-tracing-cpu side by side on one core: each render of the list with build A, then build B,
# ROUNDS times (alternating, so that a drift of the machine hits both), then per render the fastest wall time
# of each, the ratio A/B, and whether the two linear images are the same bit for bit (a change of speed only).
#   tests/Bench/cpu_ab.sh A_BIN B_BIN RENDERS_FILE [ROUNDS (default 3)]
# CORES (default 0: taskset's list) and ENGINE (default single) for other runs: CORES=0,1 ENGINE=multi, both cores.
# RENDERS_FILE: one render per line, "NAME ARGS..." (ray-tracing-cpu flags after --headless); `#` comments.
# Example: tests/Bench/cpu_ab.sh old/ray-tracing-cpu build/bin/ray-tracing-cpu tests/Bench/renders/cpu-catalogue.txt
set -eu
a=$1 b=$2 renders=$3 rounds=${4:-3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "| render | A s | B s | A / B | images |"
echo "|---|---:|---:|---:|---|"
grep -v '^\s*\(#\|$\)' "$renders" | while read -r name args; do
    best_a=inf best_b=inf
    for ((round = 1; round <= rounds; ++round)); do
        for which in a b; do
            bin=$a
            [ "$which" = b ] && bin=$b
            start=$EPOCHREALTIME
            # shellcheck disable=SC2086
            taskset -c "${CORES:-0}" "$bin" --headless --strategy scene --engine "${ENGINE:-single}" --quiet $args --hdr "$out/$which.pfm" >/dev/null
            seconds=$(python3 -c "print(f'{$EPOCHREALTIME - $start:.3f}')")
            if [ "$which" = a ]; then
                best_a=$(python3 -c "print(min(float('$best_a'), $seconds))")
            else
                best_b=$(python3 -c "print(min(float('$best_b'), $seconds))")
            fi
        done
    done
    same=$(cmp -s "$out/a.pfm" "$out/b.pfm" && echo "same" || echo "DIFFERENT")
    echo "| $name | $best_a | $best_b | $(python3 -c "print(f'{$best_a / $best_b:.3f}')") | $same |"
done
