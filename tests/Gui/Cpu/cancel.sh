#!/usr/bin/env bash
# Usage: cancel.sh APP   (needs a display: CTest runs it under xvfb-run)
# Issue 13 item 8: after a finished render, a cancelled one left the progress bar reading "done", and Save
# wrote what looked like nothing. Now the bar says "cancelled" with the samples on screen, and Save writes the
# partial image as it is, saying so; the cancelled render leaves no timing.
set -eu
app=$1
here=$(cd "$(dirname "$0")" && pwd)
. "$here/common.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

status=0
"$app" --no-gpu --window-size 1000x640 --scene rtrol-cornell-box --width 96 --spp 8 \
    --actions "wait;spp=100000;running;frames=2;cancel;wait;save=$work/partial.png" --frames 2 \
    --screenshot "$work/cancel.png" --state-json "$work/cancel.json" 2>"$work/cancel.err" || status=$?
check_run cancel "$status" "$work/cancel.err"
python3 - "$work/cancel.json" "$work/partial.png" <<'PY'
import json, subprocess, sys
state = json.load(open(sys.argv[1]))
def fail(message):
    print("FAIL:", message); sys.exit(1)
progress, message, image = state["progress"], state["message"], state["image"]
if not progress.startswith("cancelled: "):
    fail(f"the progress bar reads '{progress}' after Cancel")
if image["complete"] or not (0 < image["samples"] < 100000):
    fail(f"the image on screen should be the cancelled render's partial image: {image}")
if f"{image['samples']} of 100000 spp on screen" not in progress:
    fail(f"the progress bar '{progress}' does not say how many samples are on screen ({image['samples']})")
if f"a partial image, {image['samples']} of 100000 spp (the render was cancelled)" not in message:
    fail(f"Save did not say what it wrote: '{message}'")
if len(state["timings"]) != 1 or state["timings"][0]["spp"] != 8:
    fail(f"a cancelled render is no timing: {state['timings']}")
mean = float(subprocess.run(["convert", sys.argv[2], "-format", "%[fx:mean]", "info:"], check=True,
                            capture_output=True, text=True).stdout)
if mean < 0.05:
    fail(f"the saved partial image is black (mean {mean:.4f})")
print(f"cancel ok: '{progress}', saved {image['samples']} spp (mean {mean:.3f})")
PY
[ -s "$work/partial.pfm" ] || { echo "FAIL: no PFM beside the partial PNG"; exit 1; }
keep_pngs "$work"
