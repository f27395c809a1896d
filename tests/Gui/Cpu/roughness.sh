#!/usr/bin/env bash
# Usage: roughness.sh APP   (needs a display: CTest runs it under xvfb-run)
# The roughness slider's function in the window (roughness-scale=X, as the slider calls it) renders the image
# the command line's --roughness-scale X renders, sample for sample; the panel reports the factor.
set -eu
app=$1
here=$(cd "$(dirname "$0")" && pwd)
. "$here/common.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
common=(--scene veach-mis --width 48 --spp 4 --depth 8 --seed 3)

status=0
"$app" --window-size 800x500 "${common[@]}" --frames 2 \
    --actions "wait;save=$work/own.png;roughness-scale=6;wait;save=$work/window.png" \
    --state-json "$work/state.json" 2>"$work/app.err" || status=$?
check_run roughness "$status" "$work/app.err"
"$app" --headless --quiet "${common[@]}" --roughness-scale 6 --hdr "$work/headless.pfm"
python3 - "$work" <<'PY'
import json, struct, sys
work = sys.argv[1]

def pfm(path):
    with open(path, "rb") as f:
        assert f.readline().strip() == b"PF"
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        return struct.unpack(("<" if scale < 0 else ">") + "f" * (3 * w * h), f.read(12 * w * h))

own, window, headless = (pfm(f"{work}/{name}.pfm") for name in ("own", "window", "headless"))
largest = max(abs(a - b) for a, b in zip(window, headless))
assert largest <= 1e-5, f"the window's image at roughness x6 is not --roughness-scale 6's (largest difference {largest})"
changed = sum(abs(a - b) for a, b in zip(own, window)) / sum(abs(a) for a in own)
assert changed > 0.05, f"roughness x6 changed the image by {changed:.3f} of its radiance only"
state = json.load(open(f"{work}/state.json"))
assert state["panel"]["roughness_scale"] == 6, state["panel"]
assert state["failed_renders"] == 0, state
PY
keep_pngs "$work"
echo "roughness ok"
