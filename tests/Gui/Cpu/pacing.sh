#!/usr/bin/env bash
# Usage: pacing.sh APP   (needs a display: CTest runs it under xvfb-run)
# Issue 13 item 8: on 2 cores the window's own drawing (10 frames a second) competed with the render and
# multi core showed no gain over single core in the timings table. While a render runs the window now draws
# a frame every 0.5 s (FramePacer.h) and counts the frames; with nobody at the window none is for input.
set -eu
app=$1
here=$(cd "$(dirname "$0")" && pwd)
. "$here/common.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

status=0
"$app" --no-gpu --window-size 1000x640 --scene cornell-box-lights --width 128 --spp 128 --engine single \
    --actions "wait" --frames 2 --state-json "$work/pacing.json" 2>"$work/pacing.err" || status=$?
check_run pacing "$status" "$work/pacing.err"
python3 - "$work/pacing.json" <<'PY'
import json, sys
timing = json.load(open(sys.argv[1]))["timings"][0]
seconds, frames, on_input = timing["seconds"], timing["window_redraws"], timing["window_redraws_on_input"]
if seconds < 1.0:
    print(f"FAIL: the render took {seconds:.2f} s: too short to see the pacing"); sys.exit(1)
# One frame every 0.5 s, one when the render ends, one at its start; 10 frames a second before.
most = int(seconds / 0.5) + 3
if frames > most:
    print(f"FAIL: the window drew {frames} frames during a {seconds:.2f} s render (at most {most})"); sys.exit(1)
if on_input:
    print(f"FAIL: {on_input} frames counted as drawn for input with nobody at the window"); sys.exit(1)
print(f"pacing ok: {frames} frames during a {seconds:.2f} s render, none for input")
PY
