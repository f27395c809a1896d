#!/usr/bin/env bash
# Usage: window_vs_headless.sh APP [ROUNDS] [SCENE] [WIDTH] [SPP]   (needs a display or xvfb-run)
# Issue 38: the CPU window's render is no slower than a headless render of the same settings beyond 5 %. Each
# round renders once headless (--stats' render_seconds) and once in the window (--state-json's timing: the same
# tracing time, RenderStats::renderSeconds), for single and multi core, interleaved, the window with its GPU
# engine starting beside it as a user's would (lavapipe here). Prints each pair and the median ratio window /
# headless per engine. Nothing else may run meanwhile.
set -eu
app=$1
rounds=${2:-5}
scene=${3:-cornell-box-lights}
width=${4:-200}
spp=${5:-64}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export RT_REFERENCE_CACHE=off
display=()
[ -n "${DISPLAY:-}" ] || display=(xvfb-run -a -s "-screen 0 1280x800x24")
settings=(--scene "$scene" --width "$width" --spp "$spp" --seed 1)
echo "# $(date -u +%F) $(nproc) cores, $scene ${width} px, $spp spp, $rounds rounds: render seconds, headless and window"
for round in $(seq 1 "$rounds"); do
    for engine in single multi; do
        "$app" --headless --strategy scene "${settings[@]}" --engine "$engine" --output "$work/h.png" --stats "$work/h.json" >/dev/null 2>&1
        "${display[@]}" "$app" --strategy scene "${settings[@]}" --engine "$engine" --actions wait --frames 1 ${WINDOW_FLAGS:-} \
            --state-json "$work/w.json" 2>/dev/null
        python3 - "$work/h.json" "$work/w.json" "$engine" "$round" >>"$work/pairs.txt" <<'PY'
import json, sys
headless = json.load(open(sys.argv[1]))["render_seconds"]
window = json.load(open(sys.argv[2]))["timings"][0]
assert window["engine"] == sys.argv[3] and window["renders"] == 1, window
print(sys.argv[3], sys.argv[4], headless, window["seconds"], window["window_redraws"], window["window_redraws_on_input"])
PY
    done
done
python3 - "$work/pairs.txt" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
for engine in ("single", "multi"):
    pairs = [(float(h), float(w), int(r)) for e, _, h, w, r, _ in rows if e == engine]
    for h, w, r in pairs:
        print(f"{engine:6s} headless {h:7.3f} s  window {w:7.3f} s  ratio {w / h:5.3f}  ({r} frames drawn)")
    ratios = [w / h for h, w, _ in pairs]
    print(f"{engine}: median window / headless {statistics.median(ratios):.3f} "
          f"(min {min(ratios):.3f}, max {max(ratios):.3f}, {len(ratios)} rounds)")
PY
