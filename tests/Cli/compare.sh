#!/usr/bin/env bash
# Usage: compare.sh RAY_TRACING_GPU
# ray-tracing-gpu --compare as issue 10 runs it, shrunk for lavapipe: a CSV row per engine x strategy x spp, the
# plot, relMSE x spp about constant along each line (an unbiased estimator's error falls as 1/spp), the
# reference re-used from the cache on a second run, the equal-time figure, Ctrl-C keeping the rows written,
# and one error line with no file for bad input.
set -eu
app=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
common=(--compare --quiet --scene cornell-box-lights --width 48 --reference-spp 1024 --reference-cache "$work/cache")

"$app" "${common[@]}" --engines multi,gpu --estimators mixture,nee-mis --spp-list 4,16,64 --csv "$work/c.csv" \
    --plot "$work/c.png" >"$work/out1.txt" 2>"$work/err1.txt" || { cat "$work/err1.txt"; fail "ladder exited $?"; }
file "$work/c.png" | grep -q "PNG image data" || fail "no plot"
grep -q "rendering 2 x 512 spp" "$work/err1.txt" || fail "the first run did not render its reference in two halves"
# 48x48 pixels: the errors rest on few pixels, which the tool says (issue 41).
grep -q "warning: a 48x48 comparison: its errors rest on 2304 pixels" "$work/err1.txt" || fail "no warning for a tiny comparison"
python3 - "$work/c.csv" <<'PY' || fail "CSV rows"
import csv, sys
every = list(csv.DictReader(open(sys.argv[1])))
# --rounds' default 3: every row timed in three interleaved rounds, each the same image (the same seed's
# streams) on either engine, so the same relMSE.
assert len(every) == 2 * 2 * 3 * 3, len(every)
by_row = {}
for r in every:
    by_row.setdefault((r["engine"], r["label"], r["spp"]), []).append(r)
for key, rounds in by_row.items():
    assert sorted(int(r["round"]) for r in rounds) == [0, 1, 2], (key, rounds)
    assert len({r["relmse"] for r in rounds}) == 1, ("a round rendered another image", key, rounds)
rows = [r for r in every if r["round"] == "0"]
lines = {}
floors = {float(r["reference_relmse"]) for r in rows}
assert len(floors) == 1, floors
floor = floors.pop()
# The reference's own relMSE, from its two halves: positive, and below every render's (each includes it).
assert 0 < floor < min(float(r["relmse"]) for r in rows), (floor, rows)
for r in rows:
    assert float(r["wall_ms"]) > 0 and float(r["relmse"]) > 0 and float(r["mse"]) > 0, r
    # Rays per second by kind: the CPU engine always counts them, the GPU engine with --count-rays only; the
    # mixture traces no shadow rays.
    rates = [float(r[k + "_mrays_per_s"]) for k in ("camera", "extension", "shadow")]
    if r["engine"] == "gpu":
        assert rates == [-1, -1, -1], ("the GPU counted rays unasked", r)
    else:
        assert rates[0] > 0 and rates[1] > 0 and (rates[2] > 0) == (r["label"] == "nee-mis"), r
    assert abs(float(r["rmse"]) ** 2 - float(r["mse"])) < 1e-6 * float(r["mse"]) + 1e-12, r
    lines.setdefault((r["engine"], r["label"]), []).append(int(r["spp"]) * (float(r["relmse"]) - floor))
assert set(lines) == {("multi", "mixture"), ("multi", "nee-mis"), ("gpu", "mixture"), ("gpu", "nee-mis")}, lines
for key, products in lines.items():
    # relMSE x spp over a 16x range of spp, the reference's own relMSE taken out: constant for an unbiased
    # estimator, up to noise; a biased or broken line drifts by the factor of the range.
    assert max(products) / min(products) < 1.6, (key, products)
mixture = [p for (e, l), ps in lines.items() if l == "mixture" for p in ps]
nee = [p for (e, l), ps in lines.items() if l == "nee-mis" for p in ps]
assert max(nee) < min(mixture), "NEE + MIS is less noisy per sample than the mixture on this scene"
PY
grep -q "estimator mixture" "$work/out1.txt" && grep -q "estimator nee-mis" "$work/out1.txt" || fail "table"

# The same reference again: from the cache.
"$app" "${common[@]}" --engines gpu --spp-list 4 >/dev/null 2>"$work/err2.txt"
grep -q "from the cache" "$work/err2.txt" || { cat "$work/err2.txt"; fail "the reference was not re-used"; }

# --metric flip: the table by mean HDR-FLIP, the CSV with every metric (FLIP on round 0), each falling with spp.
"$app" "${common[@]}" --engines gpu --estimators mixture,nee-mis --spp-list 4,64 --rounds 2 --metric flip \
    --csv "$work/f.csv" --plot "$work/f.png" >"$work/outf.txt" 2>&1 || { cat "$work/outf.txt"; fail "--metric flip"; }
file "$work/f.png" | grep -q "PNG image data" || fail "no FLIP plot"
grep -q "FLIP against 1024 spp" "$work/outf.txt" || { cat "$work/outf.txt"; fail "the FLIP table"; }
python3 - "$work/f.csv" <<'PY' || fail "FLIP CSV rows"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 2 * 2 * 2, len(rows)
by = {}
for r in rows:
    flip, trimmed, rel, mape = (float(r[k]) for k in ("flip", "trimmed_relmse", "relmse", "mape"))
    if r["round"] == "1":
        assert flip < 0, ("FLIP is measured on round 0 only", r)
        continue
    assert 0 < flip < 1 and 0 < trimmed <= rel and mape > 0, r
    by.setdefault(r["label"], {})[int(r["spp"])] = (flip, trimmed, mape)
for label, s in by.items():
    assert all(s[64][i] < s[4][i] for i in range(3)), ("every metric falls with spp", label, s)
PY
# The ladder's --output: every engine x strategy at every spp over its error image, drawn from images kept in a
# temporary folder that is gone afterwards (TMPDIR), or in --images, whose index names each engine's device.
mkdir "$work/tmp"
TMPDIR="$work/tmp" "$app" "${common[@]}" --engines multi,gpu --spp-list 4,16 --rounds 1 --output "$work/ladder.png" \
    >"$work/outl.txt" 2>&1 || { cat "$work/outl.txt"; fail "the ladder's --output"; }
grep -q "wrote $work/ladder.png" "$work/outl.txt" || fail "the ladder's figure not reported"
[ -z "$(ls -A "$work/tmp")" ] || fail "the ladder's images left in TMPDIR: $(ls "$work/tmp")"
"$app" "${common[@]}" --engines multi,gpu --estimators mixture,nee-mis --spp-list 4,16 --rounds 1 \
    --output "$work/ladder2.png" --images "$work/ladder-images" >"$work/outl2.txt" 2>&1 ||
    { cat "$work/outl2.txt"; fail "the ladder's --output with --images"; }
python3 - "$work/ladder.png" "$work/ladder2.png" "$work/ladder-images/images.json" <<'PY' || fail "the ladder's figure"
import json, struct, sys
def size(path):
    head = open(path, "rb").read(24)
    assert head[:8] == b"\x89PNG\r\n\x1a\n", path
    return struct.unpack(">II", head[16:24])
# Two rows (image, error) per engine x strategy, a column per spp and the reference's: 2 x 2 rows against 3
# columns, then 2 x 4 rows against 3 columns.
(w1, h1), (w2, h2) = size(sys.argv[1]), size(sys.argv[2])
assert h1 > w1 and abs(w2 - w1) <= 2 and h2 > 1.8 * h1, (w1, h1, w2, h2)
index = json.load(open(sys.argv[3]))
assert set(index["devices"]) == {"multi", "gpu"} and "thread" in index["devices"]["multi"], index["devices"]
assert index["epsilon"] == 0.01 and len(index["images"]) == 2 * 2 * 2, index
PY

"$app" "${common[@]}" --engines gpu --estimators mixture,nee-mis --equal-time 100 --rounds 1 --metric mape \
    --output "$work/mape.png" \
    >"$work/outm.txt" 2>&1 || { cat "$work/outm.txt"; fail "--metric mape"; }
grep -q "1/(MAPE^2 s)" "$work/outm.txt" || { cat "$work/outm.txt"; fail "the MAPE efficiency column"; }

"$app" "${common[@]}" --engines gpu --estimators mixture,nee-mis --equal-time 300 --output "$work/grid.png" \
    --csv "$work/e.csv" --images "$work/images/new" >"$work/out3.txt" 2>&1 || { cat "$work/out3.txt"; fail "equal time"; }
file "$work/grid.png" | grep -q "PNG image data" || fail "no equal-time figure"
[ "$(wc -l <"$work/e.csv")" -eq 7 ] || fail "equal-time CSV rows (2 strategies x 3 rounds)"
# --images: the reference and each render as PFMs, indexed with the relMSE the CSV printed, which the files
# themselves give again (Common/Image/Metrics.h's formula, recomputed here).
python3 - "$work/images/new" "$work/e.csv" <<'PY' || fail "--images"
import csv, json, struct, sys
from pathlib import Path
folder = Path(sys.argv[1])
index = json.loads((folder / "images.json").read_text())
def pfm(name):
    data = (folder / name).read_bytes().split(b"\n", 3)
    assert data[0] == b"PF", name
    w, h = map(int, data[1].split())
    assert (w, h) == (index["width"], index["height"]), (name, w, h)
    return struct.unpack(f"<{w * h * 3}f", data[3])
reference = pfm(index["reference"]["path"])
assert index["scene"] == "cornell-box-lights" and index["reference"]["spp"] == 1024, index
rows = {r["label"]: float(r["relmse"]) for r in csv.DictReader(open(sys.argv[2]))}
assert [i["label"] for i in index["images"]] == ["mixture", "nee-mis"], index
for image in index["images"]:
    values = pfm(image["path"])
    relmse = sum((v - r) ** 2 / (r * r + 0.01) for v, r in zip(values, reference)) / len(values)
    assert abs(relmse - image["relmse"]) <= 1e-4 * image["relmse"], (image, relmse)
    assert abs(rows[image["label"]] - image["relmse"]) <= 1e-6 * image["relmse"], (image, rows)
    assert image["spp"] > 0 and image["ms"] > 0 and image["seed"] == 0, image
    assert image["path"] == f"gpu-{image['label']}-{image['spp']}spp-seed0.pfm", image
PY

# --seeds: every row rendered with seeds 0, 1, 2 (a CSV row each), the table's relMSE their mean inside its
# 95 % interval, which is the Student-t interval of the CSV's three values (t = 4.3027 at 2 degrees of freedom).
"$app" "${common[@]}" --engines multi --estimators nee-mis --spp-list 4,8 --seeds 3 --rounds 1 --csv "$work/s.csv" \
    --table "$work/s.json" >"$work/out4.txt" 2>&1 || { cat "$work/out4.txt"; fail "--seeds"; }
python3 - "$work/s.csv" "$work/s.json" <<'PY' || fail "--seeds figures"
import csv, json, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
table = json.load(open(sys.argv[2]))
assert len(rows) == 2 * 3, len(rows)
for spp in (4, 8):
    seeds = [r for r in rows if int(r["spp"]) == spp]
    assert sorted(int(r["seed"]) for r in seeds) == [0, 1, 2], seeds
    values = [float(r["relmse"]) for r in seeds]
    mean = sum(values) / 3
    sd = math.sqrt(sum((v - mean) ** 2 for v in values) / 2)
    row = next(r for r in table["rows"] if r["spp"] == spp)["multi"]
    # The CSV holds 9 significant digits: its mean is the table's within 1e-8.
    assert row["seeds"] == 3 and abs(row["relmse"] - mean) <= 1e-8 * mean, (row, mean)
    lo, hi = row["relmse_ci95"]
    half = 4.3027 * sd / math.sqrt(3)
    assert abs(lo - (mean - half)) <= 1e-4 * half and abs(hi - (mean + half)) <= 1e-4 * half, (lo, hi, mean, half)
    assert len(set(values)) == 3, "the seeds rendered the same image"
PY

# Ctrl-C in the middle of a ladder: status 130, the rows finished before kept whole, no plot.
"$app" "${common[@]}" --engines multi --spp-list 1,1,1,1,1,1,1,1,100000 --csv "$work/i.csv" --plot "$work/i.png" \
    >/dev/null 2>&1 &
pid=$!
for _ in $(seq 600); do [ "$(cat "$work/i.csv" 2>/dev/null | wc -l)" -ge 9 ] && break; sleep 0.1; done
sleep 0.5
kill -INT $pid
status=0
wait $pid || status=$?
[ $status -eq 130 ] || fail "Ctrl-C status $status"
[ "$(wc -l <"$work/i.csv")" -eq 9 ] || fail "Ctrl-C kept $(wc -l <"$work/i.csv") lines"
[ ! -e "$work/i.png" ] || fail "a plot after Ctrl-C"

# Bad input: one error line, non-zero status, no file.
bad() {
    local out status=0
    out=$("$app" "$@" 2>&1) || status=$?
    [ $status -ne 0 ] || fail "accepted: $*"
    [ "$(grep -c '^error:' <<<"$out")" -eq 1 ] || fail "not one error line for: $* -> $out"
}
bad --compare --scene cornell-box-lights --csv "$work/x.txt"
bad --compare --scene cornell-box-lights --plot "$work/x.png"
bad --compare --scene cornell-box-lights --estimators mixture,bogus --csv "$work/x.csv"
bad --compare --scene cornell-box-lights --light-selections nearest
bad --compare --scene cornell-box-lights --equal-time 100
bad --compare --scene cornell-box-lights --equal-time -5 --output "$work/x.png"
bad --compare --scene cornell-box-lights --equal-time 100 --spp-list 4,16 --output "$work/x.png"
# One render's outputs, which a comparison would ignore: refused, each by its own error.
for flag in "--stats $work/x.json" "--hdr $work/x.pfm"; do
    # shellcheck disable=SC2086 # the flag and its file
    bad --compare --scene cornell-box-lights --spp-list 4 $flag
    # shellcheck disable=SC2086
    "$app" --compare --scene cornell-box-lights --spp-list 4 $flag 2>&1 | grep -q "^error: ${flag%% *} " ||
        fail "$flag with --compare: not its own error"
done
"$app" --compare --scene cornell-box-lights --equal-time 100 --spp-list 4,16 --output "$work/x.png" 2>&1 |
    grep -q "^error: .*excludes" || fail "--equal-time with --spp-list: not the exclusion's error"
bad --compare --scene cornell-box-lights --seeds 0
bad --compare --scene cornell-box-lights --seeds 101
bad --compare --scene cornell-box-lights --rounds 0
bad --compare --scene cornell-box-lights --equal-time nan --output "$work/x.png"
bad --compare --scene cornell-box-lights --spp-list 4 --output "$work/x.jpg" # the ladder's figure is a PNG
bad --compare --scene cornell-box-lights --engines multi,multi
bad --compare --scene cornell-box-lights --spp-list 16777216 # a reference of 4 x 16777216 spp
python3 -c '
import struct, sys
values = [0.5] * (16 * 16 * 3)
values[100] = float("nan")
sys.stdout.buffer.write(b"PF\n16 16\n-1.0\n" + struct.pack("<%df" % len(values), *values))' >"$work/nan.pfm"
bad --compare --scene cornell-box-lights --width 16 --spp-list 4 --reference "$work/nan.pfm"
# A pipe as the reference: refused, not waited on (opening a pipe blocks until a writer comes).
mkfifo "$work/x-pipe.pfm"
out=$(timeout 20 "$app" --compare --scene cornell-box-lights --width 16 --spp-list 4 --reference "$work/x-pipe.pfm" 2>&1) &&
    fail "a pipe as the reference was accepted"
grep -q "not a regular file" <<<"$out" || fail "a pipe as the reference: $out"
rm "$work/x-pipe.pfm"
bad --scene cornell-box-lights --headless --csv "$work/x.csv"
touch "$work/x-file"
bad --compare --scene cornell-box-lights --equal-time 100 --images "$work/x-file"
ln -s "$work/images" "$work/x-link"
bad --compare --scene cornell-box-lights --equal-time 100 --images "$work/x-link"
rm "$work/x-file" "$work/x-link"
[ -z "$(ls "$work" | grep '^x')" ] || fail "a file left behind: $(ls "$work")"
echo "compare ok"
