#!/usr/bin/env bash
# Usage: scene_files.sh APP SOURCE_DIR
# Scene files as a user runs them (issue 12): the documented example renders; a catalogue scene exported and
# read back renders the same image bit for bit; docs/SCENES.md shows the example file as it is.
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

exit $failures
