#!/usr/bin/env bash
# Issue 42's comparison with Blender Cycles: efficiency 1/(relMSE x seconds) of this project's CPU engine and of
# Cycles on the same scene, at the same size, samples and threads, both against one Cycles reference.
#   tests/Bench/cycles/cycles_compare.sh APP OUT_DIR
# APP: ray-tracing-cpu. SCENE (rtrol-cornell-box), WIDTH (300), SPP (64), REF_SPP (16384), THREADS (2), ROUNDS (3:
# each render timed ROUNDS times, Cycles and ours alternating, the fastest kept), STRATEGIES (our renders, ";"
# between their flags; default nee-mis with Sobol samples by the default (projected) and the area light sampler,
# and book 3's mixture with random samples, the scene's defaults for the books' scenes; a strategy's flags may name
# --strategy auto, whose pilot's wall time counts as the render's and whose choices are listed). The reference is kept in
# OUT_DIR and reused by a later run of the same scene, width and REF_SPP (16,384 spp of 300 px: about 20 minutes
# on two cores). Needs Debian's blender (apt-get install blender; 3.4.1 in bookworm). Prints a Markdown table.
set -eu
app=$1 out=$2
scene=${SCENE:-rtrol-cornell-box} width=${WIDTH:-300} spp=${SPP:-64} ref_spp=${REF_SPP:-16384}
threads=${THREADS:-2} rounds=${ROUNDS:-3}
strategies=${STRATEGIES:-"--estimator nee-mis --sampling sobol;--estimator nee-mis --sampling sobol --light-sampler area;--estimator mixture --sampling random"}
here=$(dirname "$0")
command -v blender >/dev/null || { echo "error: no blender (apt-get install blender)" >&2; exit 2; }
mkdir -p "$out"
rm -f "$out"/ours-*-choices.txt
"$app" --scene "$scene" --export-scene "$out/$scene.json" 2>/dev/null
cycles() { # SPP OUT.pfm: prints the render's seconds
    blender -b --factory-startup -noaudio -P "$here/cycles_render.py" -- "$out/$scene.json" "$2" "$1" "$width" \
        "$threads" 2>&1 | python3 -c 'import json, sys
for line in sys.stdin:
    if line.startswith("{\"render_seconds\""):
        print(json.loads(line)["render_seconds"]); sys.exit(0)
    if line.startswith("error:"):
        sys.exit(line.strip())
sys.exit("error: Cycles printed no time")'
}
reference=$out/cycles-$scene-$width-$ref_spp.pfm
if [ ! -e "$reference" ]; then
    echo "rendering the Cycles reference: $ref_spp spp of $width px" >&2
    cycles "$ref_spp" "$reference.part.pfm" >/dev/null
    mv "$reference.part.pfm" "$reference"
fi
relmse() { python3 "$here/../pfm_relmse.py" "$1" "$reference"; }
best() { python3 -c "import sys; print(min(float(x) for x in sys.argv[1:]))" "$@"; }

cycles_times=()
declare -A our_times
IFS=';' read -r -a ours <<<"$strategies"
for ((r = 1; r <= rounds; ++r)); do
    cycles_times+=("$(cycles "$spp" "$out/cycles.pfm")")
    for i in "${!ours[@]}"; do
        # The scene's strategy unless the flags name one (--strategy auto: add --strategy-cache off, or every round
        # after the first takes the first's choice without a pilot).
        strategy=(--strategy scene)
        [[ " ${ours[$i]} " == *" --strategy "* ]] && strategy=()
        # shellcheck disable=SC2086 # the strategy's flags split on spaces
        "$app" --headless --quiet "${strategy[@]}" --engine multi --scene "$scene" --width "$width" --spp "$spp" ${ours[$i]} \
            --hdr "$out/ours-$i.pfm" --stats "$out/ours-$i.json" >/dev/null 2>&1
        # A pilot's time (its wall clock, preparation included) is the render's too.
        our_times[$i]="${our_times[$i]:-} $(python3 -c "import json, sys
j = json.load(open(sys.argv[1]))
c = j.get('strategy_choice')
if c:
    print(c['chosen'], file=open(sys.argv[2], 'a'))
print(j['render_seconds'] + (c['pilot_wall_seconds'] if c else 0.0))" "$out/ours-$i.json" "$out/ours-$i-choices.txt")"
    done
done
cycles_s=$(best "${cycles_times[@]}")
cycles_rel=$(relmse "$out/cycles.pfm")
echo "$scene, $width px, $spp spp, $threads threads; relMSE against Cycles at $ref_spp spp; the fastest of $rounds rounds"
echo
echo "| renderer | seconds | relMSE | 1/(relMSE s) | efficiency / Cycles' |"
echo "|---|---:|---:|---:|---:|"
python3 - "$cycles_s" "$cycles_rel" <<'PY'
import sys
s, rel = float(sys.argv[1]), float(sys.argv[2])
print(f"| Blender Cycles {__import__('subprocess').run(['blender', '--version'], capture_output=True, text=True).stdout.split(chr(10))[0].split()[-1]} | {s:.3f} | {rel:.5f} | {1 / (rel * s):.1f} | 1.00 |")
PY
for i in "${!ours[@]}"; do
    # shellcheck disable=SC2086
    s=$(best ${our_times[$i]})
    rel=$(relmse "$out/ours-$i.pfm")
    label=${ours[$i]}
    # --strategy auto: the choice of each round (the relMSE is the last round's image, the time the fastest round's).
    [ -e "$out/ours-$i-choices.txt" ] && label="$label (chose: $(sort "$out/ours-$i-choices.txt" | uniq -c |
        awk '{n = $1; $1 = ""; printf "%s%s x%d", sep, substr($0, 2), n; sep = "; "}'))"
    python3 - "$label" "$s" "$rel" "$cycles_s" "$cycles_rel" <<'PY'
import sys
label, s, rel, cs, crel = sys.argv[1].strip(), *map(float, sys.argv[2:])
print(f"| ray-tracing-cpu {label} | {s:.3f} | {rel:.5f} | {1 / (rel * s):.1f} | {(crel * cs) / (rel * s):.2f} |")
PY
done
