#!/usr/bin/env bash
# Rays per second by kind on the CPU engine (issue 42): each render of RENDERS_FILE once with --stats, then the
# table of tests/Bench/rays_table.py.
#   tests/Bench/cpu_rays.sh APP RENDERS_FILE OUT_DIR
# ENGINE (default multi: every core) for the engine.
set -eu
app=$1 renders=$2 out=$3
mkdir -p "$out"
grep -v '^\s*\(#\|$\)' "$renders" | while read -r name args; do
    # shellcheck disable=SC2086 # the render's flags split on spaces
    "$app" --headless --quiet --strategy scene --engine "${ENGINE:-multi}" $args --stats "$out/$name.json" >/dev/null
done
python3 "$(dirname "$0")/rays_table.py" --cpu "$out" "$renders"
