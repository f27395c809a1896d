#!/usr/bin/env bash
# Usage: scene_files.sh APP SOURCE_DIR
# Scene files as a user runs them (issue 12): the documented example renders; a catalogue scene exported and
# read back renders the same image bit for bit; docs/SCENES.md shows the example file as it is; glTF files
# (Debian's assimp-testmodels: a textured box as .gltf + .bin + .png and as .glb, a square seen by the file's
# camera) render to an image that is not one colour, with one warning line.
set -u
app=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

run() { # name, args...: must succeed
    local name=$1
    shift
    if ! timeout 300 "$app" --headless --quiet "$@" >"$work/stdout" 2>"$work/stderr"; then
        fail "$name: exit status $?: $(cat "$work/stderr")"
        return 1
    fi
    echo "ok   $name"
}

# The example of docs/SCENES.md, as written there.
example="$src/Assets/scenes/example.json"
awk '/^```json$/ { inside = 1; next } /^```$/ && inside { exit } inside' "$src/docs/SCENES.md" >"$work/doc-example.json"
cmp -s "$work/doc-example.json" "$example" || fail "docs/SCENES.md's example differs from Assets/scenes/example.json"
run "example renders" --scene "$example" --width 48 --spp 2 --output "$work/example.png" &&
    { [ -s "$work/example.png" ] || fail "example: no PNG"; }

# Export and read back: the same image, bit for bit (PNG and linear PFM). rtrol-cornell-glass has a sampling
# target; rtnw-final has media, motion, an image and Perlin textures, instances.
for scene in rtrol-cornell-glass rtnw-final; do
    run "$scene exported" --scene "$scene" --export-scene "$work/$scene.json" || continue
    [ -s "$work/$scene.json" ] || { fail "$scene: nothing exported"; continue; }
    common=(--width 32 --spp 2 --seed 3)
    run "$scene rendered" --scene "$scene" "${common[@]}" --output "$work/a.png" --hdr "$work/a.pfm" &&
        run "$scene re-read and rendered" --scene "$work/$scene.json" "${common[@]}" --output "$work/b.png" \
            --hdr "$work/b.pfm" &&
        { cmp -s "$work/a.pfm" "$work/b.pfm" && cmp -s "$work/a.png" "$work/b.png" ||
            fail "$scene: the re-read scene renders a different image"; }
    # Exported twice: the same bytes but the description, which names the scene's source.
    run "$scene re-exported" --scene "$work/$scene.json" --export-scene "$work/again.json" &&
        { grep -v '"description"' "$work/again.json" | cmp -s - <(grep -v '"description"' "$work/$scene.json") ||
            fail "$scene: exporting the re-read scene gives a different file"; }
done

# glTF 2.0: tiny renders (the GPU app runs on lavapipe here). Each image must not be one colour (the standard
# deviation of its grey levels, ImageMagick's, 0 to 1, above 0.01), and the model must be in view: at depth 1 a
# camera ray sees only emitters and the background, so the unlit model is a black silhouette on the sky that
# must cover 5 % to 95 % of the image (a camera looking away, or at the model from inside, fails; a sky alone
# gives about 0.016 of deviation, which is why the first check is not enough on its own).
# pfm_stat spread|sky FILE.pfm: the standard deviation of the sRGB-encoded grey levels (0 to 1, as ImageMagick
# gives it for the PNG), or the fraction of pixels brighter than 2 % grey (the sky around a black silhouette).
# Python's standard library only: the NVIDIA host of tests/Bench/device_run.sh has no ImageMagick.
pfm_stat() {
    python3 - "$@" <<'PY'
import struct, sys
what, path = sys.argv[1], sys.argv[2]
with open(path, "rb") as f:
    assert f.readline().strip() == b"PF"
    w, h = map(int, f.readline().split())
    scale = float(f.readline())
    data = struct.unpack(("<" if scale < 0 else ">") + "f" * (3 * w * h), f.read(12 * w * h))
def srgb(x):
    x = min(max(x, 0.0), 1.0)
    return 12.92 * x if x <= 0.0031308 else 1.055 * x ** (1 / 2.4) - 0.055
grey = [0.2126 * srgb(data[3 * i]) + 0.7152 * srgb(data[3 * i + 1]) + 0.0722 * srgb(data[3 * i + 2]) for i in range(w * h)]
mean = sum(grey) / len(grey)
if what == "spread":
    print((sum((g - mean) ** 2 for g in grey) / len(grey)) ** 0.5)
else:
    print(sum(g > 0.02 for g in grey) / len(grey))
PY
}
models=${RT_GLTF_MODELS:-/usr/share/assimp/models/glTF2} # the device run carries its own copy
for model in BoxTextured-glTF/BoxTextured.gltf BoxTextured-glTF-Binary/BoxTextured.glb cameras/Cameras.gltf; do
    file="$models/$model"
    if [ ! -f "$file" ]; then
        echo "skip $model: assimp-testmodels is not installed"
        continue
    fi
    name=$(basename "$model")
    run "glTF $model renders" --scene "$file" --width 24 --spp 4 --depth 4 --output "$work/$name.png" \
        --hdr "$work/$name.pfm" || continue
    [ -s "$work/$name.png" ] || { fail "$model: no PNG"; continue; }
    spread=$(pfm_stat spread "$work/$name.pfm")
    python3 -c "import sys; sys.exit(float(sys.argv[1]) <= 0.01)" "$spread" ||
        fail "$model: the image is (nearly) one colour (grey-level deviation $spread)"
    warnings=$(grep -c '^warning:' "$work/stderr")
    [ "$warnings" -eq 1 ] && grep -q "nothing in the file emits: lit by a gradient sky" "$work/stderr" ||
        fail "$model: expected one warning line saying the sky was added, got: $(cat "$work/stderr")"
    run "glTF $model silhouette" --scene "$file" --width 24 --spp 1 --depth 1 --output "$work/$name-1.png" \
        --hdr "$work/$name-1.pfm" || continue
    sky=$(pfm_stat sky "$work/$name-1.pfm")
    python3 -c "import sys; sys.exit(not 0.05 <= float(sys.argv[1]) <= 0.95)" "$sky" ||
        fail "$model: the model covers $(python3 -c "import sys; print(round(100 * (1 - float(sys.argv[1]))))" "$sky") % of the image"
done

exit $failures
