#!/usr/bin/env bash
# Variants of the shaders side by side in one run, one build of the app: each render of the list with every
# variant (ray-tracing-gpu --shader-dir), ROUNDS times, alternating, then per render the fastest GPU time
# (`gpu_seconds` of --stats) of each variant, its ratio to the first one and the relMSE of its image against the
# first one's (round-off where a variant changes only the speed; a variant that breaks the image shows here, not
# as a gain). A variant is a folder of SPIR-V in
# the layout of build/bin/shaders: build it with the GLSL changed (cmake --build build --target rt_shaders),
# copy build/bin/shaders away, restore the GLSL. What the probes of docs/notebook/PERFORMANCE.md §8.7 did by hand.
#   tests/Bench/shader_variants.sh APP_BIN_DIR OUT_DIR RENDERS_FILE VARIANT_DIR...
# RENDERS_FILE: one render per line, "NAME ARGS..." (ray-tracing-gpu flags after --headless); `#` comments.
# ROUNDS (default 3).
set -eu
bin=$1 out=$2 renders=$3
shift 3
[ $# -ge 1 ] || { echo "shader_variants.sh: no variant folder given" >&2; exit 2; }
rounds=${ROUNDS:-3}
mkdir -p "$out"
printf '%24s' render
for v in "$@"; do printf '  %14s' "$(basename "$v")"; done
echo
grep -v '^\s*\(#\|$\)' "$renders" | while read -r name args; do
    for ((r = 1; r <= rounds; ++r)); do
        i=0
        for v in "$@"; do
            # shellcheck disable=SC2086 # the render's flags split on spaces
            "$bin/ray-tracing-gpu" --headless --quiet --strategy scene $args --shader-dir "$v" --stats "$out/$name-$i-$r.json" \
                --hdr "$out/$name-$i.pfm" </dev/null >/dev/null
            i=$((i + 1))
        done
    done
    python3 - "$out" "$name" "$rounds" "$#" <<'PY'
import json, sys
out, name, rounds, count = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
best = [min(json.load(open(f"{out}/{name}-{i}-{r}.json"))["gpu_seconds"] * 1e3 for r in range(1, rounds + 1))
        for i in range(count)]
print(f"{name:>24}" + "".join(f"  {t:8.1f} {best[0] / t:4.2f}x" for t in best), end="")
PY
    for ((i = 1; i < $#; ++i)); do
        printf '  relMSE(%d) %s' "$i" "$(python3 "$(dirname "$0")/pfm_relmse.py" "$out/$name-$i.pfm" "$out/$name-0.pfm")"
    done
    echo
done
