#!/usr/bin/env bash
# Usage: heatmap.sh APP
# --heatmap (issue 38): a headless render writes the per-pixel cost as a painted PNG (the map above its colour bar,
# at least 320 px wide) or as its values (PFM), with the figures in the stats JSON and the file named in the
# summary; a wrong extension, restir-di (not timed per pixel) and --compare are refused in one line, writing nothing.
set -eu
app=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
render=(--headless --scene rtrol-cornell-glass --width 48 --spp 4 --depth 8)

"$app" "${render[@]}" --heatmap "$work/cost.png" --stats "$work/s.json" --output "$work/image.png" >"$work/out.txt" 2>"$work/err.txt" ||
    { cat "$work/err.txt"; fail "--heatmap: status $?"; }
file "$work/cost.png" | grep -q "PNG image data, 320 x 114" || fail "the heatmap is not 320 x (48 + 66): $(file "$work/cost.png")"
file "$work/image.png" | grep -q "PNG image data, 48 x 48" || fail "the image beside the heatmap"
grep -q "wrote .*cost.png" "$work/out.txt" || fail "the summary does not name the heatmap"
python3 - "$work/s.json" <<'PY' || fail "the stats' heatmap"
import json, sys
h = json.load(open(sys.argv[1]))["heatmap"]
assert h["unit"] in ("microseconds per sample", "shader-clock ticks per sample"), h
assert h["width"] == 48 and h["height"] == 48, h
assert 0 < h["median"] <= h["p99"] <= h["max"] and h["mean"] > 0, h
PY

"$app" "${render[@]}" --quiet --heatmap "$work/cost.pfm" >/dev/null 2>"$work/err.txt" || { cat "$work/err.txt"; fail "--heatmap .pfm"; }
[ "$(head -c 2 "$work/cost.pfm")" = PF ] && [ "$(sed -n 2p "$work/cost.pfm")" = "48 48" ] || fail "the PFM's header"

refused() { # PATTERN ARGS...: one error line matching PATTERN, a failed status, no file written
    local pattern=$1; shift
    rm -f "$work"/x.*
    "$app" "$@" --output "$work/x.png" >/dev/null 2>"$work/err.txt" && fail "accepted: $*"
    [ "$(grep -c '^error:' "$work/err.txt")" = 1 ] || { cat "$work/err.txt"; fail "not one error line: $*"; }
    grep -q "^error: .*$pattern" "$work/err.txt" || { cat "$work/err.txt"; fail "the error does not say '$pattern'"; }
    [ -z "$(ls "$work"/x.* 2>/dev/null)" ] || fail "a refused run left $(ls "$work"/x.*)"
}
refused "must end in .png or .pfm or .exr" "${render[@]}" --heatmap "$work/x.jpg"
refused "restir-di" "${render[@]}" --estimator restir-di --heatmap "$work/x.pfm"
refused "--heatmap .*--headless" --compare --scene rtrol-cornell-glass --width 8 --spp-list 1 --heatmap "$work/x.png"
"$app" --help | grep -q -- "--heatmap" || fail "--help does not explain --heatmap"
echo "ok"
