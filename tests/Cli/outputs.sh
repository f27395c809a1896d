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
for key in scene engine settings true_spp wall_seconds build_seconds mpaths_per_second nan_samples inf_samples; do
    grep -q "\"$key\"" "$work/a.json" || { echo "stats.json lacks $key"; exit 1; }
done
python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert d['true_spp']==2 and d['nan_samples']==0" "$work/a.json"

help=$("$app" --help)
for flag in --headless --scene --spp --depth --width --aspect --sampling --pdf --unidirectional-light --seed \
    --output --hdr --stats --list-scenes; do
    grep -q -- "$flag" <<<"$help" || { echo "--help does not explain $flag"; exit 1; }
done
[ "$("$app" --list-scenes | wc -l)" -ge 22 ]
"$app" --list-scenes | grep -q "^cornell-box-lights "
echo "outputs ok"
