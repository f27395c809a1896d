#!/usr/bin/env bash
# How much of a scene's error its glass makes: the scene as the catalogue has it, and a copy whose dielectrics
# are white Lambertian (albedo 0.73, the Cornell box's white), each through ray-tracing-gpu --compare with the
# same flags. Light through glass reaches a diffuse surface only along BSDF-sampled paths (a caustic: a shadow
# ray cannot refract), so that error is the same whatever NEE's light selection or sampler does, and it bounds
# the ratio of two such strategies' efficiencies (docs/notebook/PERFORMANCE.md §4.6).
#   tests/Bench/without_glass.sh APP_BIN_DIR OUT_DIR SCENE [--compare flags...]
# e.g. tests/Bench/without_glass.sh build/bin /tmp/glass many-lights --width 600 --engines gpu \
#          --reference-spp 4096 --estimators nee-mis --light-selections uniform,power,bvh --spp-list 64,256
# Writes OUT_DIR/SCENE.json and SCENE-without-glass.json (the scene files) and .csv (--compare's rows) of each.
set -euo pipefail
bin=$1 out=$2 scene=$3
shift 3
mkdir -p "$out"
"$bin/ray-tracing-gpu" --scene "$scene" --export-scene "$out/$scene.json" >/dev/null
python3 - "$out/$scene.json" "$out/$scene-without-glass.json" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
white = len(scene["textures"])
scene["textures"].append({"type": "solid", "color": [0.73, 0.73, 0.73]})
glass = [i for i, m in enumerate(scene["materials"]) if m["type"] == "dielectric"]
if not glass:
    sys.exit(f"without_glass.sh: {sys.argv[1]} has no dielectric")
for i in glass:
    scene["materials"][i] = {"type": "lambertian", "albedo_texture": white}
json.dump(scene, open(sys.argv[2], "w"))
print(f"{len(glass)} dielectric material(s) made white Lambertian")
PY
for file in "$scene" "$scene-without-glass"; do
    "$bin/ray-tracing-gpu" --compare --quiet --scene "$out/$file.json" --csv "$out/$file.csv" "$@"
done
