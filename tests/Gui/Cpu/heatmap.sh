#!/usr/bin/env bash
# Usage: heatmap.sh APP   (needs a display: CTest runs it under xvfb-run)
# The CPU window's cost heatmap (issue 38): --heatmap on shows each pixel's cost per sample in place of the image,
# on the CPU engines (microseconds) and the GPU (shader-clock ticks, where a ray-tracing device exists); restir-di
# is not timed per pixel and the window says why; heatmap=off shows the image again. The state JSON reports what
# the screen holds (RT_GUI_KEEP keeps the screenshots for a person to look at).
set -eu
app=$1
here=$(cd "$(dirname "$0")" && pwd)
. "$here/common.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

run() { # name actions
    local status=0
    "$app" --validation --window-size 1000x640 --scene rtrol-cornell-glass --width 64 --spp 8 --depth 50 --heatmap on \
        --actions "$2" --frames 2 --screenshot "$work/$1.png" --state-json "$work/$1.json" 2>"$work/$1.err" || status=$?
    check_run "$1" "$status" "$work/$1.err"
}

run cpu "wait"
python3 - "$work/cpu.json" <<'PY'
import json, sys
state = json.load(open(sys.argv[1]))
heatmap = state["image"]["heatmap"]
assert state["panel"]["heatmap"] is True, state["panel"]
assert heatmap and heatmap["unit"] == "microseconds per sample" and heatmap["width"] == 64, heatmap
assert 0 < heatmap["median"] <= heatmap["p99"], heatmap
print(f"cpu heatmap ok: median {heatmap['median']:.3f} us per sample")
PY

run gpu "wait;engine=gpu;render;wait;heatmap=off"
python3 - "$work/gpu.json" <<'PY'
import json, sys
state = json.load(open(sys.argv[1]))
if state["gpu"]["state"] != "ready":
    print(f"no GPU here ({state['gpu']['detail']}): the GPU's heatmap not checked")
    sys.exit(0)
assert state["panel"]["heatmap"] is False, state["panel"]
heatmap = state["image"]["heatmap"]
# The image on screen was timed (the switch only changes what is shown); its map is the GPU's.
assert state["image"]["engine"] == "gpu" and heatmap["unit"] == "shader-clock ticks per sample", state["image"]
print(f"gpu heatmap ok: median {heatmap['median']:.0f} ticks per sample")
PY

run restir "wait;estimator=restir-di;render;wait"
python3 - "$work/restir.json" <<'PY'
import json, sys
image = json.load(open(sys.argv[1]))["image"]
assert image["heatmap"] is None and "restir-di" in image["heatmap_unavailable"], image
print("restir-di: no heatmap, and the window says why")
PY
keep_pngs "$work"
echo "heatmap ok"
