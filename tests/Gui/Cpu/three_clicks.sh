#!/usr/bin/env bash
# Usage: three_clicks.sh APP   (needs a display: CTest runs it under xvfb-run)
# Single core, multi core, GPU: three renders of one scene and spp leave three timings side by side. Where
# a Vulkan ray-tracing device exists (lavapipe on CI) the GPU row is there and the validation layer reports
# nothing; without one (the loader pointed at no driver) the GPU has no row and the panel gives the reason.
set -eu
app=$1
here=$(cd "$(dirname "$0")" && pwd)
. "$here/common.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
clicks="engine=single;render;wait;engine=multi;render;wait;engine=gpu;render;wait"

run() { # name, VAR=value... for the environment
    local name=$1
    shift
    local status=0
    env "$@" "$app" --validation --window-size 1000x640 --scene rtrol-cornell-box --width 64 --spp 4 --depth 8 \
        --actions "$clicks" --frames 2 --screenshot "$work/$name.png" --state-json "$work/$name.json" \
        2>"$work/$name.err" || status=$?
    check_run "$name" "$status" "$work/$name.err"
}

run no-driver VK_ICD_FILENAMES=/nonexistent/icd.json VK_DRIVER_FILES=/nonexistent/icd.json
python3 "$here/window_checks.py" timings "$work/no-driver.json" no-gpu

run device
if python3 "$here/window_checks.py" gpu-ready "$work/device.json"; then
    python3 "$here/window_checks.py" timings "$work/device.json" gpu
else
    echo "no Vulkan ray-tracing device here: checking the unavailable case only"
    python3 "$here/window_checks.py" timings "$work/device.json" no-gpu
fi
python3 "$here/window_checks.py" settled "$work/device.json"
keep_pngs "$work"
echo "three clicks ok"
