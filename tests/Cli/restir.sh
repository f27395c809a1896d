#!/usr/bin/env bash
# Usage: restir.sh APP cpu|gpu
# --estimator restir-di as a user runs it (issue 36), on either app: a render names its combination in the summary
# line and the stats (with the reservoirs' memory). CPU: --compare ranks it beside nee-mis over 4 seeds by default.
# GPU: an image whose restir buffers exceed one storage buffer of the device is refused in one line, nothing written
# (rendered where they fit).
set -eu
app=$1
kind=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

if [ "$kind" = gpu ]; then
    # 2048 x 2048: 256 MiB of surfaces, past lavapipe's 128 MiB binding range, within an NVIDIA GPU's 4 GiB.
    set +e
    "$app" --headless --quiet --scene cornell-box-lights --width 2048 --aspect 1 --spp 1 --depth 2 \
        --estimator restir-di --restir-candidates 1 --restir-spatial 0 --output "$work/big.png" >"$work/out" 2>"$work/err"
    status=$?
    set -e
    if [ "$status" -ne 0 ]; then
        [ "$(grep -c . "$work/err")" -eq 1 ] || { echo "expected one error line:"; cat "$work/err"; exit 1; }
        grep -q "restir-di" "$work/err" && grep -q "maxStorageBufferRange" "$work/err" || { cat "$work/err"; exit 1; }
        [ ! -e "$work/big.png" ] || { echo "an image was written"; exit 1; }
    else
        [ -s "$work/big.png" ] || { echo "status 0 without the image"; exit 1; }
    fi
fi

line=$("$app" --headless --quiet --scene lamp-room --count 64 --width 24 --spp 3 --estimator restir-di \
    --restir-biased on --restir-candidates 4 --output "$work/a.png" --stats "$work/a.json")
echo "$line" | grep -q "restir-di-biased" || { echo "summary without the combination: $line"; exit 1; }
/usr/bin/python3 - "$work/a.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
r = d["restir"]
assert r["combination"] == "biased", r
assert r["reservoirs_bytes_per_pixel"] <= 64, r
assert r["reservoirs_bytes"] == r["reservoirs_bytes_per_pixel"] * d["width"] * d["height"], r
assert d["settings"]["restir_candidates"] == 4 and d["settings"]["restir_biased"] is True, d["settings"]
assert d["true_spp"] == 3 and d["nan_samples"] == 0, d
PY
[ "$kind" = cpu ] || exit 0

"$app" --headless --quiet --scene cornell-box-lights --width 16 --depth 4 --compare --engines multi \
    --estimators nee-mis,restir-di --spp-list 2,4 --reference-spp 64 --reference-cache off --rounds 1 \
    --csv "$work/c.csv" >"$work/table"
/usr/bin/python3 - "$work/c.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
# Without --seeds, every row of a comparison with restir-di is rendered with 4 seeds (its pixels are correlated).
for label in ("nee-mis", "restir-di"):
    mine = [r for r in rows if r["strategy"].split()[0] == label]
    assert sorted((int(r["spp"]), int(r["seed"])) for r in mine) == [(s, k) for s in (2, 4) for k in range(4)], mine
for r in rows:
    assert float(r["relmse"]) > 0, r
PY
