#!/usr/bin/env bash
# Usage: screenshot.sh APP   (needs a display: CTest runs it under xvfb-run)
# The window opens on the command line's render; --frames/--screenshot saves what it shows: a PNG of the
# window's size, not blank, whose image pane shows that render (saved through Save image to compare) and
# differs from the panel. Then the light theme and a larger font, same checks.
set -eu
app=$1
here=$(cd "$(dirname "$0")" && pwd)
. "$here/common.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$app" --no-gpu --window-size 1100x700 --scene rtrol-cornell-box --width 120 --spp 8 \
    --actions "wait;save=$work/render.png" --frames 3 --screenshot "$work/dark.png" --state-json "$work/dark.json"
python3 "$here/window_checks.py" screenshot "$work/dark.png" "$work/dark.json" "$work/render.png" 1100 700
python3 "$here/window_checks.py" settled "$work/dark.json"
[ -s "$work/render.pfm" ] || { echo "FAIL: Save image wrote no PFM beside the PNG"; exit 1; }

"$app" --no-gpu --window-size 900x640 --scene rtrol-cornell-glass --width 90 --aspect 1.5 --spp 6 \
    --sampling accumulate --actions "theme=light;font-size=20;wait;save=$work/light-render.png" --frames 3 \
    --screenshot "$work/light.png" --state-json "$work/light.json"
python3 "$here/window_checks.py" screenshot "$work/light.png" "$work/light.json" "$work/light-render.png" 900 640
python3 "$here/window_checks.py" settled "$work/light.json"
# No --window-size (issue 13 item 7): the window fits the panel, the image at one pixel per pixel and the
# timings (PaneLayout.h), at least 1024x720, cut to the screen (Xvfb's is 1280x800): a small image is
# magnified beside the panel; a 600x600 one needs 1016x862: 1024 wide (the least), cut to 800 high.
for case in "120 1024 720" "600 1024 800"; do
    read -r width w h <<<"$case"
    "$app" --no-gpu --scene rtrol-cornell-box --width "$width" --spp 2 --actions "wait;save=$work/default-$width.png" \
        --frames 2 --screenshot "$work/default-$width-shot.png" --state-json "$work/default-$width.json"
    python3 "$here/window_checks.py" screenshot "$work/default-$width-shot.png" "$work/default-$width.json" \
        "$work/default-$width.png" "$w" "$h"
done
keep_pngs "$work"
echo "screenshot ok"
