#!/usr/bin/env bash
# Usage: camera.sh APP   (needs a display: CTest runs it under xvfb-run; xdotool types and drags)
# The CPU window's camera (issue 38), as the GPU window's: W held moves the view forward, a drag on the image turns
# it, the wheel over the image zooms, and camera=/fov= actions do the same; every move renders the new view
# (RenderRequest::camera), a timings row of its own, and camera=reset renders the scene's view again, the same
# image bit for bit.
set -eu
app=$1
here=$(cd "$(dirname "$0")" && pwd)
. "$here/common.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
common=(--no-gpu --window-size 1000x640 --scene cornell-box-lights --width 64 --spp 4 --engine multi)

# The actions.
status=0
"$app" "${common[@]}" --frames 2 --state-json "$work/actions.json" 2>"$work/actions.err" \
    --actions "wait;save=$work/scene.png;camera=forward:200;wait;save=$work/moved.png;camera=yaw:10;wait;camera=reset;wait;save=$work/reset.png;fov=30;wait" ||
    status=$?
check_run actions "$status" "$work/actions.err"
cmp -s "$work/scene.png" "$work/reset.png" || fail "camera=reset did not render the scene's view again"
cmp -s "$work/scene.png" "$work/moved.png" && fail "camera=forward rendered the scene's view"
python3 - "$work/actions.json" <<'PY'
import json, sys
state = json.load(open(sys.argv[1]))
rows = state["timings"]
assert [r["camera"] is None for r in rows] == [True, False, False, False], rows
assert rows[0]["renders"] == 2, "reset is the scene's view: the first row's work again"
assert rows[1]["camera"]["look_from"] == [0, 0, 200], rows[1]["camera"]
assert rows[2]["camera"]["look_from"] == [0, 0, 200] and rows[2]["camera"]["look_at"][0] != 0, rows[2]["camera"]
assert rows[3]["camera"]["vfov"] == 30 and state["panel"]["camera"] == rows[3]["camera"], (rows[3], state["panel"])
print("camera actions ok")
PY

# The keys, a drag and the wheel, as a person gives them (xdotool, package xdotool: build.sh installs it).
if ! command -v xdotool >/dev/null; then
    echo "camera input not tested: xdotool is missing (package xdotool)"
    exit 0
fi
status=0
"$app" "${common[@]}" --actions "wait;sleep=4;wait" --frames 2 --state-json "$work/input.json" \
    2>"$work/input.err" &
app_pid=$!
window=$(xdotool search --sync --onlyvisible --name "ray-tracing-cpu" | head -1)
sleep 1
xdotool windowfocus --sync "$window" 2>/dev/null || true
xdotool mousemove --window "$window" 700 200
xdotool keydown --window "$window" w; sleep 0.6; xdotool keyup --window "$window" w
xdotool mousedown 1; for _ in 1 2 3 4 5; do xdotool mousemove_relative -- 10 0; sleep 0.05; done; xdotool mouseup 1
xdotool click 4; sleep 0.1; xdotool click 4
wait "$app_pid" || status=$?
check_run input "$status" "$work/input.err"
python3 - "$work/input.json" <<'PY'
import json, sys
camera = json.load(open(sys.argv[1]))["panel"]["camera"]
assert camera is not None, "the input did not move the camera"
# The scene's camera: from the origin towards (0, 0, 800), 40 degrees.
assert camera["look_from"][2] > 1.0, ("W did not move forward", camera)
assert camera["look_at"][0] != 0.0, ("the drag did not turn", camera)
assert camera["vfov"] < 40.0, ("the wheel did not zoom in", camera)
print(f"camera input ok: {camera}")
PY
