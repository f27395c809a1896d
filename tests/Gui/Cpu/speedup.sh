#!/usr/bin/env bash
# Usage: speedup.sh APP [REPEATS] [-- RENDER FLAGS...]   (needs a display: run it under xvfb-run -a)
# A measurement, not a test (CTest does not run it): the single -> multi core speed-up of one render, headless
# and in the window's timings table, REPEATS times each, interleaved so that other load on the machine
# falls on both alike. Prints each pair of render times and the median speed-ups.
# Default render: cornell-box-lights, 200x200, 64 spp (about 4 s on one core of the 2-core CI machine), in a
# 1280x800 window (WINDOW_SIZE=WxH for another).
set -eu
app=$1
repeats=${2:-3}
shift $(($# >= 2 ? 2 : 1))
[ "${1:-}" = "--" ] && shift
render=("$@")
[ ${#render[@]} -gt 0 ] || render=(--scene cornell-box-lights --width 200 --spp 64)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

seconds() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['render_seconds'])" "$1"; }

headless=()
window=()
for i in $(seq "$repeats"); do
    "$app" --headless --quiet --strategy scene "${render[@]}" --engine single --stats "$work/s.json" >/dev/null 2>&1
    "$app" --headless --quiet --strategy scene "${render[@]}" --engine multi --stats "$work/m.json" >/dev/null 2>&1
    s=$(seconds "$work/s.json")
    m=$(seconds "$work/m.json")
    headless+=("$(python3 -c "print($s / $m)")")
    echo "headless  run $i: single $s s, multi $m s"

    # The launch render is single core; then multi; the window exits once both are in the table.
    "$app" --no-gpu --window-size "${WINDOW_SIZE:-1280x800}" "${render[@]}" --engine single --actions "wait;engine=multi;render;wait" --frames 1 \
        --state-json "$work/w.json" 2>/dev/null
    read -r s m marks < <(python3 - "$work/w.json" <<'EOF'
import json, sys
rows = json.load(open(sys.argv[1]))["timings"]
t = {r["engine"]: r for r in rows}
marks = ",".join(f'{e}:{t[e].get("window_redraws_on_input", 0)}' for e in ("single", "multi"))
print(t["single"]["seconds"], t["multi"]["seconds"], marks)
EOF
)
    window+=("$(python3 -c "print($s / $m)")")
    echo "window    run $i: single $s s, multi $m s (redraws on input: $marks)"
done
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR % 2 ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2)}'; }
printf 'median speed-up single -> multi: headless %.2fx, window %.2fx (%s runs each; load average %s)\n' \
    "$(median "${headless[@]}")" "$(median "${window[@]}")" "$repeats" "$(cut -d' ' -f1-3 /proc/loadavg)"
