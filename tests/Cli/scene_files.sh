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
models=/usr/share/assimp/models/glTF2
for model in BoxTextured-glTF/BoxTextured.gltf BoxTextured-glTF-Binary/BoxTextured.glb cameras/Cameras.gltf; do
    file="$models/$model"
    if [ ! -f "$file" ]; then
        echo "skip $model: assimp-testmodels is not installed"
        continue
    fi
    name=$(basename "$model")
    run "glTF $model renders" --scene "$file" --width 24 --spp 4 --depth 4 --output "$work/$name.png" || continue
    [ -s "$work/$name.png" ] || { fail "$model: no PNG"; continue; }
    spread=$(convert "$work/$name.png" -colorspace Gray -format '%[fx:standard_deviation]' info:)
    python3 -c "import sys; sys.exit(float(sys.argv[1]) <= 0.01)" "$spread" ||
        fail "$model: the image is (nearly) one colour (grey-level deviation $spread)"
    warnings=$(grep -c '^warning:' "$work/stderr")
    [ "$warnings" -eq 1 ] && grep -q "nothing in the file emits: lit by a gradient sky" "$work/stderr" ||
        fail "$model: expected one warning line saying the sky was added, got: $(cat "$work/stderr")"
    run "glTF $model silhouette" --scene "$file" --width 24 --spp 1 --depth 1 --output "$work/$name-1.png" || continue
    sky=$(convert "$work/$name-1.png" -colorspace Gray -threshold 2% -format '%[fx:mean]' info:)
    python3 -c "import sys; sys.exit(not 0.05 <= float(sys.argv[1]) <= 0.95)" "$sky" ||
        fail "$model: the model covers $(python3 -c "import sys; print(round(100 * (1 - float(sys.argv[1]))))" "$sky") % of the image"
done

exit $failures
