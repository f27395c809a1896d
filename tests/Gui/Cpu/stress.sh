#!/usr/bin/env bash
# Usage: stress.sh APP   (needs a display: CTest runs it under xvfb-run)
# What a restless person does: shrinks the window to nothing and back, switches scenes twenty times in a row
# (on the CPU and on the GPU), changes the depth in the middle of renders, resizes while rendering. The app
# must exit 0 with nothing from the validation layer (leaks are reported when the device is destroyed), and
# the image on screen must be the one the panel describes: the same pixels as a headless render of the
# panel's final settings.
set -eu
app=$1
here=$(cd "$(dirname "$0")" && pwd)
. "$here/common.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

scenes=$("$app" --list-scenes | awk '$1 != "furnace" {print $1}' | head -20)
[ "$(wc -l <<<"$scenes")" -eq 20 ] || { echo "FAIL: fewer than 20 scenes listed"; exit 1; }
switch_all() { for s in $scenes; do printf 'scene=%s;' "$s"; done; }
switch_waiting() { for s in $(head -8 <<<"$scenes"); do printf 'scene=%s;wait;' "$s"; done; }

actions="resize=0x0;frames=3;resize=900x600;frames=2;"
actions+="$(switch_all)wait;"                              # twenty in a row on multi core
actions+="engine=gpu;$(switch_all)wait;$(switch_waiting)"   # and on the GPU, eight of them rendered
actions+="scene=rtrol-cornell-box;spp=24;width=80;render;running;depth=7;wait;"   # GPU, depth mid-render
actions+="engine=multi;spp=200;render;running;depth=5;resize=0x0;frames=2;resize=1040x680;wait;"
actions+="engine=single;sampling=accumulation;spp=30;width=72;render;running;depth=6;wait;save=$work/final.png"

status=0
"$app" --validation --scene rtrol-cornell-box --width 48 --spp 2 --actions "$actions" --frames 2 \
    --screenshot "$work/stress.png" --state-json "$work/stress.json" 2>"$work/stress.err" || status=$?
check_run stress "$status" "$work/stress.err"
python3 "$here/window_checks.py" settled "$work/stress.json"
[ "$(identify -format '%w %h' "$work/stress.png")" = "1040 680" ] || { echo "FAIL: screenshot is not 1040x680"; exit 1; }
# A dozen timings overflow the table's pane: it must have scrolled to the latest one.
python3 -c "import json,sys; s=json.load(open(sys.argv[1])); assert len(s['timings']) > 3, 'too few timings'; \
assert s['layout']['latest_timing_visible'], 'the latest timing is scrolled out of view'" "$work/stress.json" ||
    { echo "FAIL: timings table"; exit 1; }

# Single and multi core give the same image bit for bit, so the window's image must equal a headless render.
read -r -a flags <<<"$(python3 "$here/window_checks.py" headless-args "$work/stress.json")"
"$app" --headless --quiet "${flags[@]}" --hdr "$work/headless.pfm" >/dev/null
cmp -s "$work/final.pfm" "$work/headless.pfm" || { echo "FAIL: the window's image differs from a headless render of ${flags[*]}"; exit 1; }
keep_pngs "$work"
echo "stress ok: the window's image equals the headless render of ${flags[*]}"
