#!/usr/bin/env bash
# Usage: relmse.sh APP   (needs a display: CTest runs it under xvfb-run)
# The timings table's error beside time (issue 38): after a render the window renders a reference of the same work
# at 4x its spp while it is idle (two halves, as --compare does), stores it in --compare's reference cache, and
# each row shows relMSE and 1 / (relMSE x s). Checked here: the values equal --compare's on the same render (the
# same image and reference, whether --compare finds the window's reference in the cache or renders its own), the
# efficiency is 1 / (relMSE x the row's time), nee-mis has the lower relMSE than mixture on cornell-box-lights at
# equal spp, and a second window finds its references in the cache.
set -eu
app=$1
here=$(cd "$(dirname "$0")" && pwd)
. "$here/common.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export RT_REFERENCE_CACHE="$work/cache"
fail() { echo "FAIL: $*"; exit 1; }
settings=(--scene cornell-box-lights --width 48 --spp 16 --seed 7)

window() { # name
    local status=0
    "$app" --no-gpu --window-size 1000x640 "${settings[@]}" --estimator nee-mis --engine multi \
        --actions "wait;wait-reference;estimator=mixture;render;wait;wait-reference" --frames 2 \
        --screenshot "$work/$1.png" --state-json "$work/$1.json" 2>"$work/$1.err" || status=$?
    check_run "$1" "$status" "$work/$1.err"
}

window first
[ "$(ls "$work/cache"/*.pfm | wc -l)" -eq 2 ] || fail "the window did not store its two references in the cache"
# --compare on the same renders, each estimator's its own comparison (a comparison measures its strategies against
# the reference of its base settings): from the window's references in the cache, then rendering its own.
for estimator in nee-mis mixture; do
    compare=(--compare "${settings[@]}" --estimator "$estimator" --spp-list 16 --engines multi --rounds 1)
    "$app" "${compare[@]}" --csv "$work/cached-$estimator.csv" >/dev/null 2>"$work/cached.err" ||
        { cat "$work/cached.err"; fail "--compare exited $?"; }
    grep -q "from the cache" "$work/cached.err" || fail "--compare did not find the window's $estimator reference"
    "$app" "${compare[@]}" --reference-cache off --csv "$work/own-$estimator.csv" >/dev/null 2>"$work/own.err" ||
        { cat "$work/own.err"; fail "--compare exited $?"; }
done
window second
python3 - "$work" <<'PY'
import csv, json, sys
work = sys.argv[1]
def rows(name):
    timings = json.load(open(f"{work}/{name}.json"))["timings"]
    assert len(timings) == 2, timings
    return {t["estimator"]: t for t in timings}
first, second = rows("first"), rows("second")
for estimator, t in first.items():
    ref = t["reference"]
    assert ref and ref["state"] == "ready" and ref["spp"] == 64 and ref["engine"] == "multi", ref
    assert not ref["from_cache"] and ref["seconds"] > 0 and 0 < ref["own_rel_mse"] < t["rel_mse"], t
    assert abs(t["efficiency"] * t["rel_mse"] * t["seconds"] - 1) < 1e-9, t
    again = second[estimator]
    assert again["reference"]["from_cache"] and again["rel_mse"] == t["rel_mse"], (again, t)
    for name in ("cached", "own"):
        row = list(csv.DictReader(open(f"{work}/{name}-{estimator}.csv")))
        assert len(row) == 1, row
        theirs = float(row[0]["relmse"])
        assert abs(theirs / t["rel_mse"] - 1) < 0.05, (name, estimator, theirs, t["rel_mse"])
        assert abs(float(row[0]["reference_relmse"]) / ref["own_rel_mse"] - 1) < 0.05, (name, row, ref)
    print(f"{estimator}: relMSE {t['rel_mse']:.4g} (--compare {theirs:.4g}), 1/(relMSE s) {t['efficiency']:.4g}")
assert first["nee-mis"]["rel_mse"] < first["mixture"]["rel_mse"], "nee-mis is no better than mixture at equal spp"
PY
keep_pngs "$work"
