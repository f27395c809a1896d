#!/usr/bin/env bash
# Usage: scene_file.sh APP   (needs a display: CTest runs it under xvfb-run)
# A scene file in the window: loaded by the scene action as the panel's Load button does, rendered, rendered
# again by itself when the file changes on disk (here from red light to green), and --fresnel's choice
# applied from the panel's function; a script naming a file that does not exist is refused.
set -eu
app=$1
here=$(cd "$(dirname "$0")" && pwd)
. "$here/common.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

light_scene() { # FILE R G B: a camera facing a quad light that fills the view
    cat >"$1.tmp" <<JSON
{"format": "ray-tracing-scene", "version": 1,
 "camera": {"look_from": [0, 0, 5], "look_at": [0, 0, 0], "vfov": 40},
 "render": {"spp": 4, "depth": 4, "width": 32, "aspect": 1},
 "materials": [{"name": "light", "type": "diffuse_light", "radiance": [$2, $3, $4]},
               {"name": "glass", "type": "dielectric", "ior": 1.5}],
 "shapes": [{"type": "quad", "q": [-10, -10, 0], "u": [20, 0, 0], "v": [0, 20, 0], "material": "light"},
            {"type": "sphere", "center": [3, 3, 1], "radius": 0.2, "material": "glass"}]}
JSON
    mv "$1.tmp" "$1" # whole or not at all: the window must not read half a file
}
light_scene "$work/lamp.json" 1 0 0

# Once the first image is saved, the file becomes a green light: the window notices within half a second.
(
    for _ in $(seq 600); do [ -f "$work/first.png" ] && break; sleep 0.1; done
    sleep 1.1 # a new modification time on file systems with one-second stamps
    light_scene "$work/lamp.json" 0 1 0
) &
editor=$!

status=0
"$app" --validation --window-size 800x500 --scene rtow-final --width 32 --spp 4 --depth 4 --frames 2 \
    --actions "scene=$work/lamp.json;wait;save=$work/first.png;sleep=4;wait;save=$work/second.png;fresnel=exact;wait" \
    --state-json "$work/state.json" 2>"$work/app.err" || status=$?
wait $editor
check_run scene-file "$status" "$work/app.err"
grep -q "lamp.json changed on disk: reloading it" "$work/app.err" || { tail "$work/app.err"; echo "FAIL: no reload logged"; exit 1; }
# A script naming a file that is not there stops before the window opens.
if "$app" --actions "scene=$work/absent.json" --frames 1 2>"$work/absent.err"; then
    echo "FAIL: a missing scene file in --actions was accepted"; exit 1
fi
grep -q "absent.json" "$work/absent.err" || { cat "$work/absent.err"; echo "FAIL: the error does not name the file"; exit 1; }
python3 - "$work" <<'PY'
import json, sys
work = sys.argv[1]

def mean_rgb(pfm):
    with open(pfm, "rb") as f:
        assert f.readline().strip() == b"PF"
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        import struct
        data = struct.unpack(("<" if scale < 0 else ">") + "f" * (3 * w * h), f.read(12 * w * h))
    return [sum(data[c::3]) / (w * h) for c in range(3)]

first, second = mean_rgb(f"{work}/first.pfm"), mean_rgb(f"{work}/second.pfm")
print("first", first, "second", second)
# The camera sees only the light (radiance 1 in one channel) and a small glass sphere in front of it.
assert first[0] > 0.9 and first[1] < 0.05, f"first image is not the red light: {first}"
assert second[1] > 0.9 and second[0] < 0.05, f"second image is not the green light: {second}"
state = json.load(open(f"{work}/state.json"))
assert state["scene_reloads"] == 1, state["scene_reloads"]
assert state["panel"]["scene"].endswith("lamp.json"), state["panel"]["scene"]
assert state["panel"]["fresnel"] == "exact", state["panel"]
assert state["image"]["settings"]["fresnel"] == "exact", state["image"]
assert state["failed_renders"] == 0, state
PY
keep_pngs "$work"
echo "scene file ok"
