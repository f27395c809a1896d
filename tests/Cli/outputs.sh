#!/usr/bin/env bash
# Usage: outputs.sh APP
# A small headless render writes the PNG, the PFM and a stats JSON with the fields the issue names;
# --help explains every flag; --list-scenes lists the catalogue.
set -eu
app=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$app" --headless --quiet --scene rtrol-cornell-box --width 24 --spp 2 --depth 8 --seed 3 \
    --output "$work/a.png" --hdr "$work/a.pfm" --stats "$work/a.json" >/dev/null
file "$work/a.png" | grep -q "PNG image data, 24 x 24"
# Logs on stderr, the one-line summary alone on stdout (a script reads it).
"$app" --headless --scene rtrol-cornell-box --width 8 --spp 1 --depth 2 >"$work/out.txt" 2>"$work/err.txt"
[ "$(wc -l <"$work/out.txt")" -eq 1 ] || { echo "stdout is not the summary alone:"; cat "$work/out.txt"; exit 1; }
grep -q "^info: settings" "$work/err.txt" || { echo "no log line on stderr"; exit 1; }
head -c 2 "$work/a.pfm" | grep -q "PF"
# A setting the estimator does not use is named as ignored (issue 41), as --count is for a scene without one.
"$app" --headless --scene rtrol-cornell-box --width 8 --spp 1 --depth 2 --estimator bsdf --light-sampler area \
    >/dev/null 2>"$work/err.txt"
grep -q "warning: --light-sampler is ignored: estimator bsdf samples no light" "$work/err.txt" ||
    { cat "$work/err.txt"; echo "--light-sampler with the bsdf estimator not named as ignored"; exit 1; }
for key in scene engine settings true_spp wall_seconds build_seconds mpaths_per_second nan_samples inf_samples; do
    grep -q "\"$key\"" "$work/a.json" || { echo "stats.json lacks $key"; exit 1; }
done
python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert d['true_spp']==2 and d['nan_samples']==0" "$work/a.json"
# The same render as OpenEXR: float is the PFM's values bit for bit, half within half's precision (read back by
# OpenImageIO where Debian's python3-openimageio is installed, else only the file's magic number).
for type in float half; do
    "$app" --headless --quiet --scene rtrol-cornell-box --width 24 --spp 2 --depth 8 --seed 3 \
        --hdr "$work/a-$type.exr" --hdr-type "$type" >/dev/null
    head -c 4 "$work/a-$type.exr" | od -An -tx1 | grep -q "76 2f 31 01" || { echo "--hdr .exr wrote no OpenEXR"; exit 1; }
done
if /usr/bin/python3 -c "import OpenImageIO, numpy" 2>/dev/null; then
    /usr/bin/python3 - "$work" <<'PY' || { echo "the EXRs do not hold the PFM's image"; exit 1; }
import sys, numpy as np, OpenImageIO as oiio
work = sys.argv[1]
def pfm(path):
    data = open(path, "rb").read()
    parts = data.split(b"\n", 3)
    w, h = map(int, parts[1].split())
    return np.frombuffer(parts[3], dtype="<f4").reshape(h, w, 3)[::-1]
reference = pfm(f"{work}/a.pfm")
exact = oiio.ImageInput.open(f"{work}/a-float.exr").read_image("float")
half = oiio.ImageInput.open(f"{work}/a-half.exr").read_image("float")
assert np.array_equal(exact, reference), "float EXR differs from the PFM"
assert np.allclose(half, reference, rtol=2.0 ** -11, atol=2.0 ** -24), "half EXR beyond half's precision"
PY
fi
"$app" --headless --quiet --scene rtrol-cornell-box --width 8 --spp 1 --hdr "$work/bad.png" >/dev/null 2>"$work/bad.txt" &&
    { echo "--hdr .png was accepted"; exit 1; }
grep -q "must end in .pfm or .exr" "$work/bad.txt" || { cat "$work/bad.txt"; exit 1; }
# A file or link at a temporary's name is another's: the render takes a name of its own beside it and leaves it be (a
# link planted at the fixed "b.png.pending" of before had the PNG written through it into its target).
echo victim >"$work/victim.txt"
ln -s "$work/victim.txt" "$work/b.png.pending"
"$app" --headless --quiet --scene rtrol-cornell-box --width 8 --spp 1 --output "$work/b.png" --hdr "$work/b.exr" \
    >/dev/null
[ "$(cat "$work/victim.txt")" = victim ] || { echo "the render wrote through a link at b.png.pending"; exit 1; }
[ -f "$work/b.png" ] && [ ! -L "$work/b.png" ] && [ -L "$work/b.png.pending" ] ||
    { ls -l "$work"; echo "b.png is not the render's own file, or the link was replaced"; exit 1; }
! ls "$work" | grep -q -- '\.~[pw]' || { ls "$work"; echo "a temporary was left behind"; exit 1; }

help=$("$app" --help)
for flag in --headless --scene --spp --depth --width --aspect --sampling --pdf --unidirectional-light --seed \
    --output --hdr --hdr-type --stats --list-scenes; do
    grep -q -- "$flag" <<<"$help" || { echo "--help does not explain $flag"; exit 1; }
done
[ "$("$app" --list-scenes | wc -l)" -ge 22 ]
"$app" --list-scenes | grep -q "^cornell-box-lights "
echo "outputs ok"
