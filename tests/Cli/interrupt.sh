#!/usr/bin/env bash
# Usage: interrupt.sh APP BOUND_SECONDS [SETTLE_SECONDS [SCENE]]
# Ctrl-C at any spp and size (issue 13): a render of 2^24 samples per pixel (the most), interrupted with SIGINT
# SETTLE_SECONDS after its acceleration structures are built (once the render loop runs), must exit within
# BOUND_SECONDS with the documented cancellation status 130, say so on stderr, and write no file (not the
# PNG, not the HDR, not the stats, no temporary).
set -u
app=$1
bound=$2
settle=${3:-1}
scene=${4:-many-lights} # 1000 lights, no roulette: slow paths, a row of a fixed-size batch runs for seconds
work=$(mktemp -d)
pid=
trap '[ -n "$pid" ] && kill -KILL "$pid" 2>/dev/null; rm -rf "$work"' EXIT

# The log lines and the progress line go to stderr, the summary to stdout: look in both.
started() { cat "$work/stdout" "$work/stderr" 2>/dev/null | grep -q "acceleration structures built"; }

# One tiny render of the same settings first: lavapipe compiles the specialised pipeline in it (Mesa's disk
# cache keeps it), so that no timed render below spends its settle time compiling, which cannot be interrupted.
"$app" --headless --quiet --strategy scene --scene "$scene" --width 2 --aspect 2 --spp 1 --russian-roulette off >/dev/null 2>&1 || true

# 2x1 pixels: 2^19 samples per pixel in one batch of a fixed path budget, seconds per row; 64x64: many rows;
# 200x200: one sample per pixel is seconds on lavapipe, so the GPU engine must cut a batch into bands of rows;
# 800x800: 24 ms a row there, so even the first band must be shorter than a pass of the interleaved rows.
for size in ${SIZES:-2 64 200 800}; do
    rm -f "$work"/*
    "$app" --headless --strategy scene --scene "$scene" --width "$size" --aspect "$((size == 2 ? 2 : 1))" --spp 16777216 --russian-roulette off --output "$work/out.png" --hdr "$work/out.pfm" \
        --stats "$work/out.json" >"$work/stdout" 2>"$work/stderr" &
    pid=$!
    # Wait (at most 120 s) for the scene to be built: a Ctrl-C before the render is the default action's.
    for _ in $(seq 1200); do
        started && break
        kill -0 "$pid" 2>/dev/null || break
        sleep 0.1
    done
    started || { echo "FAIL: never started:"; cat "$work/stdout" "$work/stderr"; exit 1; }
    sleep "$settle"
    kill -0 "$pid" 2>/dev/null || { echo "FAIL: exited before the interrupt:"; cat "$work/stderr"; exit 1; }
    # Timed with bash's own clock (EPOCHREALTIME, microseconds): no process started while the clock runs.
    start=${EPOCHREALTIME/[.,]/}
    kill -INT "$pid"
    # Poll rather than wait: an app that ignores the interrupt must fail the test, not hang it.
    deadline=$((start + 10000000))
    while kill -0 "$pid" 2>/dev/null && [ "${EPOCHREALTIME/[.,]/}" -lt "$deadline" ]; do
        sleep 0.01
    done
    end=${EPOCHREALTIME/[.,]/}
    if kill -0 "$pid" 2>/dev/null; then
        echo "FAIL width $size: still running 10 s after SIGINT"; exit 1
    fi
    wait "$pid"
    status=$?
    pid=
    elapsed=$(python3 -c "import sys; print(f'{(int(sys.argv[2]) - int(sys.argv[1])) * 1e-6:.3f}')" "$start" "$end")
    if [ "$status" -ne 130 ]; then
        echo "FAIL width $size: exit status $status, not 130"; cat "$work/stderr"; exit 1
    fi
    if ! python3 -c "import sys; sys.exit(float(sys.argv[1]) > float(sys.argv[2]))" "$elapsed" "$bound"; then
        echo "FAIL width $size: exited ${elapsed} s after SIGINT (bound ${bound} s)"; exit 1
    fi
    cat "$work/stdout" "$work/stderr" | grep -q "cancelled" ||
        { echo "FAIL width $size: no word of the cancel:"; cat "$work/stdout" "$work/stderr"; exit 1; }
    if [ -n "$(ls -A "$work" | grep -v '^std')" ]; then
        echo "FAIL width $size: files left behind: $(ls -A "$work")"; exit 1
    fi
    echo "ok   width $size: exit 130, ${elapsed} s after SIGINT, nothing written"
done
