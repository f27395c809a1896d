#!/usr/bin/env bash
# Two builds of ray-tracing-gpu side by side in one run: each render of the list with build A, then build B,
# for ROUNDS rounds (alternating, so that a drift of the machine hits both), then per render the fastest GPU
# time (`gpu_seconds` of --stats) of each, their ratio A/B, the same of the host's clock (`render_seconds`: the
# batches' submissions and waits), and the relMSE between the two images (round-off when B changes only the speed).
#   tests/Bench/gpu_ab.sh A_BIN_DIR B_BIN_DIR OUT_DIR [RENDERS_FILE]
# RENDERS_FILE: one render per line, "NAME ARGS..." (ray-tracing-gpu flags after --headless), or
# "NAME A_ARGS || B_ARGS" where the builds name a setting differently (an old build without --estimator, say);
# `#` comments.
# Without it, issue 11's figure and issue 9's defaults (below). ROUNDS (default 3).
set -eu
a=$1 b=$2 out=$3 renders=${4:-}
rounds=${ROUNDS:-3}
mkdir -p "$out"
if [ -z "$renders" ]; then
    renders=$out/renders.txt
    cat >"$renders" <<'EOF'
cbl-mixture --scene cornell-box-lights --width 600 --spp 1000 --estimator mixture
cbl-defaults --scene cornell-box-lights --width 600 --spp 1000
glass-mixture --scene rtrol-cornell-glass --width 600 --spp 1000
many-lights-bvh --scene many-lights --width 600 --spp 256
many-lights-uniform --scene many-lights --width 600 --spp 256 --light-selection uniform
EOF
fi
grep -v '^\s*\(#\|$\)' "$renders" | while read -r name args; do
    args_a=${args%%||*}
    args_b=${args#*||}
    for ((r = 1; r <= rounds; ++r)); do
        for side in a b; do
            dir=$a flags=$args_a
            [ "$side" = b ] && dir=$b flags=$args_b
            # shellcheck disable=SC2086 # the render's flags split on spaces
            "$dir/ray-tracing-gpu" --headless --quiet --strategy scene $flags --hdr "$out/$name-$side.pfm" \
                --stats "$out/$name-$side-$r.json" >/dev/null
        done
    done
    python3 - "$out" "$name" "$rounds" <<'PY'
import json, sys
out, name, rounds = sys.argv[1], sys.argv[2], int(sys.argv[3])
stats = {s: [json.load(open(f"{out}/{name}-{s}-{r}.json")) for r in range(1, rounds + 1)] for s in "ab"}
best = {s: min(j["gpu_seconds"] for j in stats[s]) * 1e3 for s in "ab"}
wall = {s: min(j["render_seconds"] for j in stats[s]) * 1e3 for s in "ab"}
print(f"{name:>22}: A {best['a']:9.1f} ms  B {best['b']:9.1f} ms  A/B {best['a'] / best['b']:.2f}x"
      f"  wall: A {wall['a']:9.1f} ms  B {wall['b']:9.1f} ms  A/B {wall['a'] / wall['b']:.2f}x", end="")
PY
    echo "  relMSE $(python3 "$(dirname "$0")/pfm_relmse.py" "$out/$name-b.pfm" "$out/$name-a.pfm")"
done
