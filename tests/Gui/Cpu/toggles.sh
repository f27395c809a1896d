#!/usr/bin/env bash
# Usage: toggles.sh APP   (needs a display: CTest runs it under xvfb-run)
# Every sampling toggle of the panel changes what is rendered, as the command line's flag does (issue 38): each
# action renders a row of the timings table with that setting and its own image (its relMSE against its reference
# differs from every other row's); stratified sampling takes the square spp below the one asked (10 -> 9) and says
# so in the table and on screen; sobol and random are different images of the same work.
set -eu
app=$1
here=$(cd "$(dirname "$0")" && pwd)
. "$here/common.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export RT_REFERENCE_CACHE="$work/cache"

status=0
"$app" --no-gpu --window-size 1000x640 --scene cornell-box-lights --width 48 --spp 16 --engine multi --seed 3 \
    --actions "wait;sampling=random;wait;sampling=stratified;spp=10;wait;frames=2;save=$work/stratified.png;sampling=accumulate;wait;light-sampler=area;wait;light-selection=power;wait;russian-roulette=off;wait;estimator=mixture;wait;wait-reference" \
    --frames 2 --state-json "$work/toggles.json" 2>"$work/toggles.err" || status=$?
check_run toggles "$status" "$work/toggles.err"
grep -q "saved .*stratified.png" "$work/toggles.err" || { echo "FAIL: no image saved during stratified"; exit 1; }
python3 - "$work/toggles.json" <<'PY'
import json, sys
rows = json.load(open(sys.argv[1]))["timings"]
keys = ("sampling", "spp", "light_sampler", "light_selection", "russian_roulette", "estimator")
expected = [
    ("sobol", 16, "projected", "bvh", "sqrt", "nee-mis"),
    ("random", 16, "projected", "bvh", "sqrt", "nee-mis"),
    ("stratified", 9, "projected", "bvh", "sqrt", "nee-mis"),  # the square below 10
    ("accumulate", 10, "projected", "bvh", "sqrt", "nee-mis"),
    ("accumulate", 10, "area", "bvh", "sqrt", "nee-mis"),
    ("accumulate", 10, "area", "power", "sqrt", "nee-mis"),
    ("accumulate", 10, "area", "power", "off", "nee-mis"),
    ("accumulate", 10, "area", "power", "off", "mixture"),
]
# A render between two actions of one step (sampling=stratified, then spp=10) may finish on a loaded machine
# before the second applies: its row is extra, the expected rows must appear in order.
everything = [tuple(r[k] for k in keys) for r in rows]
picked, at = [], 0
for want in expected:
    while at < len(everything) and everything[at] != want:
        at += 1
    assert at < len(everything), (want, "missing from", everything)
    picked.append(rows[at])
got = [tuple(r[k] for k in keys) for r in picked]
errors = [r["rel_mse"] for r in picked]
assert all(e is not None and e > 0 for e in errors), errors
assert len(set(errors)) == len(errors), ("two settings rendered the same image", errors)
print("toggles ok: " + ", ".join(f"{'/'.join(str(v) for v in g)} {e:.3g}" for g, e in zip(got, errors)))
PY
