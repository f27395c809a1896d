#!/usr/bin/env bash
# Usage: bad_input.sh APP
# Every case must exit non-zero, print exactly one line on stderr that names the problem, not crash
# (no status above 128), and leave no output file behind.
set -u
app=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

expect_error() { # name, pattern the error line must contain, args...
    local name=$1 pattern=$2
    shift 2
    local out="$work/out.png"
    rm -f "$work"/out.*
    # Small defaults for the flags a case does not set itself (a repeated flag is an error of its own).
    local defaults=()
    [[ " $* " == *" --width "* ]] || defaults+=(--width 8)
    [[ " $* " == *" --spp "* ]] || defaults+=(--spp 1)
    [[ " $* " == *" --output "* ]] || defaults+=(--output "$out")
    # Under a time limit: a check that waits for the render (an unwritable output found only after it, a
    # huge request swapping) fails here instead of hanging the suite; `timeout` exits 124 with no error line.
    timeout 60 "$app" --headless --quiet "${defaults[@]}" "$@" >"$work/stdout" 2>"$work/stderr"
    local status=$?
    local lines
    lines=$(grep -c . "$work/stderr")
    if [ "$status" -eq 0 ] || [ "$status" -gt 128 ]; then
        echo "FAIL $name: exit status $status"; failures=$((failures + 1))
    elif [ "$lines" -ne 1 ]; then
        echo "FAIL $name: $lines lines on stderr:"; cat "$work/stderr"; failures=$((failures + 1))
    elif ! grep -qi -- "$pattern" "$work/stderr"; then
        echo "FAIL $name: '$(cat "$work/stderr")' does not mention '$pattern'"; failures=$((failures + 1))
    elif find "$work" -name 'out.*' | grep -q .; then
        echo "FAIL $name: an output file was written"; failures=$((failures + 1))
    else
        echo "ok   $name (status $status): $(cat "$work/stderr")"
    fi
}

# The window's flags, checked before any window opens: run without --headless and without a display, so that
# a check that came only after opening the window would fail with "cannot open a window" instead.
expect_window_error() { # name, pattern the error line must contain, args...
    local name=$1 pattern=$2
    shift 2
    env -u DISPLAY -u WAYLAND_DISPLAY timeout 60 "$app" --width 8 --spp 1 "$@" >"$work/stdout" 2>"$work/stderr"
    local status=$?
    if [ "$status" -ne 2 ]; then
        echo "FAIL $name: exit status $status (usage errors are 2): $(cat "$work/stderr")"; failures=$((failures + 1))
    elif [ "$(grep -c . "$work/stderr")" -ne 1 ] || ! grep -qi -- "$pattern" "$work/stderr"; then
        echo "FAIL $name: '$(cat "$work/stderr")' is not one line mentioning '$pattern'"; failures=$((failures + 1))
    else
        echo "ok   $name (status $status): $(cat "$work/stderr")"
    fi
}
expect_window_error "window size 0x0" "--window-size 0x0: the width must be from 160 to 16384" --window-size 0x0
expect_window_error "window size too large" "--window-size 100000x100000: the width must be from 160" \
    --window-size 100000x100000
expect_window_error "window size not a size" "--window-size must be WIDTHxHEIGHT.*got 'abc'" --window-size abc
expect_window_error "window size without x" "--window-size must be WIDTHxHEIGHT.*got '1280'" --window-size 1280
expect_window_error "window size height too small" "the height must be from 160" --window-size 800x100
# Values the windows' actions hold to a limit are refused naming it, before the window opens (issue 13).
expect_window_error "save to a .jpg name" "expected save=FILE.png" --actions "save=x.jpg"
expect_window_error "font size out of range" "font-size=an integer in \[10, 32\]" --actions "font-size=40"
if [[ $(basename "$app") == ray-tracing-gpu ]]; then
    expect_window_error "samples per frame above the cap" "not in range 0 to 256" --samples-per-frame 1000
    expect_window_error "samples action above the cap" "samples=an integer in \[0, 256\]" --actions "samples=1000"
fi

if [[ $(basename "$app") == ray-tracing-gpu ]]; then
    expect_error "unknown integrator" "--integrator" --integrator wave
    expect_error "wave size beyond its range" "--wave-paths" --wave-paths 100000000
fi
expect_error "unknown scene" "no-such-scene" --scene no-such-scene
expect_error "zero spp" "samples per pixel" --spp 0
expect_error "spp beyond 2^24" "samples per pixel" --spp 16777217
expect_error "aspect overflowing a float" "got 1e308" --aspect 1e308
expect_error "aspect not a number" "must be a number" --aspect 1.5x
expect_error "negative width" "width" --width -5
expect_error "unknown flag" "--frobnicate" --frobnicate
expect_error "an empty output name" "--output: names no file" --output ""
expect_error "an empty stats name" "--stats: names no file" --stats ""
expect_error "bad sampling" "sampling" --sampling halton
expect_error "bad pdf value" "--pdf" --pdf maybe
expect_error "bad estimator" "--estimator" --estimator path
expect_error "contradicting estimators" "contradicts" --estimator nee --pdf on
expect_error "bad light sampler" "--light-sampler" --light-sampler cosine
expect_error "bad light selection" "--light-selection" --light-selection bvh2
expect_error "bad roulette value" "--russian-roulette" --russian-roulette sometimes
expect_error "bad Fresnel model" "--fresnel" --fresnel fast
mkdir -p "$work/empty-assets"
RT_ASSET_DIR="$work/empty-assets" expect_error "missing texture" "earth.jpg" --scene rtnw-earth
expect_error "malformed OBJ" "malformed.obj" --scene mesh-in-one-weekend --mesh /usr/share/assimp/models/invalid/malformed.obj
expect_error "empty OBJ" "empty.obj" --scene mesh-in-one-weekend --mesh /usr/share/assimp/models/invalid/empty.obj
expect_error "missing OBJ" "nothere.obj" --scene mesh-in-one-weekend --mesh "$work/nothere.obj"
expect_error "output folder missing" "does not exist" --output "$work/no/such/folder/out.png"
expect_error "repeated flag" "--spp" --spp 2 --spp 3
expect_error "output extension" ".png" --output "$work/out.jpg"
expect_error "translation of two numbers" "--translate-scene" --translate-scene 1,2
expect_error "translation of four numbers" "--translate-scene" --translate-scene 1,2,3,4
expect_error "translation not a number" "--translate-scene" --translate-scene 1,x,3
expect_error "translation with a space" "--translate-scene" --translate-scene "1, 2,3"
expect_error "translation infinite" "--translate-scene" --translate-scene 0,inf,0
expect_error "translation not a number (nan)" "--translate-scene" --translate-scene nan,0,0
expect_error "translation overflows float" "--translate-scene" --translate-scene 1e39,0,0
expect_error "scale too large for float32" "world units across" --scale-scene 1e7
expect_error "zero scale" "--scale-scene" --scale-scene 0
expect_error "negative scale" "--scale-scene" --scale-scene -2
expect_error "infinite scale" "--scale-scene" --scale-scene inf
expect_error "scale not a number" "--scale-scene" --scale-scene nan
expect_error "scale malformed" "--scale-scene" --scale-scene 2x
expect_error "scale too small for float32" "world units across" --scale-scene 1e-6

# Every output path checked before the render, and all outputs written or none (issue 13). The renders are
# long (2^24 spp, the most a render takes), so a check made only after rendering times out; the PNG must not
# be left behind.
long=(--spp 16777216)
mkdir -p "$work/d.json"
expect_error "stats path is a folder" "is a folder" "${long[@]}" --stats "$work/d.json"
rmdir "$work/d.json"
expect_error "hdr in /proc" "/proc" "${long[@]}" --hdr /proc/out.pfm
expect_error "output in /proc" "/proc" "${long[@]}" --output /proc/out.png
expect_error "output folder is a file" "is not a folder" "${long[@]}" --output "$0/out.png"
# Only a regular file is replaced (issue 41): a link to a device had the device itself replaced by a PNG.
ln -s /dev/full "$work/full.png"
expect_error "output is a link to a device" "'/dev/full', a device" "${long[@]}" --output "$work/full.png"
[ -c /dev/full ] || { echo "FAIL: /dev/full is no longer a device"; failures=$((failures + 1)); }
ln -s "$work/nowhere/x.json" "$work/dangling.json"
expect_error "stats is a dangling link" "does not exist" --stats "$work/dangling.json"
[ "$(find "$work" -newer "$work/dangling.json" -type f | grep -vc 'std')" -eq 0 ] ||
    { echo "FAIL: a file beside the links: $(ls "$work")"; failures=$((failures + 1)); }
rm -f "$work/full.png" "$work/dangling.json"
# A disk that takes 4 KB of each file (RLIMIT_FSIZE, SIGXFSZ ignored: write() fails with EFBIG, as ENOSPC does
# on a full disk): the PNG was cut at 4 KB and reported as written with status 0. Not for the GPU app: the limit
# also binds lavapipe's device memory (memfd), which then faults; the files are written by the same code.
if [[ "$(basename "$app")" != *gpu* ]]; then
    (
        ulimit -f 4
        trap '' XFSZ
        expect_error "a disk that takes 4 KB" "File too large" --width 96 --spp 4 --stats "$work/out.json"
        exit "$failures"
    ) || failures=$((failures + 1))
fi

# Huge requests are refused with the figures before anything is built (issue 13); counts must be positive.
expect_error "negative count" "--count" --scene many-lights --count -3
expect_error "zero count" "--count" --scene white-spheres --count 0
expect_error "count beyond memory" "available" --scene many-lights --count 2000000000
expect_error "image beyond memory" "available" --width 65536

# Scene files (issue 12): the bad-file tour, one line each with the file and where in it.
scene_file() { # name, JSON text: writes $work/NAME.json
    printf '%s\n' "$2" >"$work/$1.json"
}
base='"materials": [{"name": "m", "type": "lambertian", "albedo": [0.5, 0.5, 0.5]}]'
scene_file syntax "{ $base,, }"
scene_file unknown-key "{ $base, \"shapes\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, \"material\": \"m\", \"colour\": 1}] }"
scene_file wrong-type "{ $base, \"shapes\": [{\"type\": \"sphere\", \"center\": \"origin\", \"radius\": 1, \"material\": \"m\"}] }"
scene_file negative-radius "{ $base, \"shapes\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": -1, \"material\": \"m\"}] }"
scene_file zero-quad "{ $base, \"shapes\": [{\"type\": \"quad\", \"q\": [0, 0, 0], \"u\": [1, 0, 0], \"v\": [2, 0, 0], \"material\": \"m\"}] }"
scene_file missing-mesh "{ $base, \"meshes\": [{\"obj\": \"gone.obj\"}], \"shapes\": [{\"type\": \"mesh\", \"mesh\": 0, \"material\": 0}] }"
scene_file missing-texture "{ \"textures\": [{\"type\": \"image\", \"path\": \"gone.png\"}] }"
expect_error "scene file: syntax error" "syntax.json:1:" --scene "$work/syntax.json"
expect_error "scene file: unknown key" "/shapes/0: unknown key 'colour'" --scene "$work/unknown-key.json"
expect_error "scene file: wrong type" "/shapes/0/center: expected an array of 3 numbers" --scene "$work/wrong-type.json"
expect_error "scene file: negative radius" "/shapes/0/radius" --scene "$work/negative-radius.json"
expect_error "scene file: zero-area quad" "zero area" --scene "$work/zero-quad.json"
expect_error "scene file: missing mesh" "/meshes/0/obj: mesh 'gone.obj' not found" --scene "$work/missing-mesh.json"
expect_error "scene file: missing texture" "/textures/0/path: texture 'gone.png' not found" --scene "$work/missing-texture.json"
expect_error "scene file: none there" "not found" --scene "$work/nothere.json"
# glTF files (issue 12): tinygltf's refusal on one line, a missing buffer file, accessors out of range.
gltf_file() { # name, JSON text after the asset: writes $work/NAME.gltf
    printf '{"asset": {"version": "2.0"}, %s}\n' "$2" >"$work/$1.gltf"
}
# One triangle, its three vertices (36 bytes) in a data URI or in a file; ACCESSOR is spliced in.
triangle() { # buffer uri, accessor count, POSITION accessor index
    printf '"scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": %s}}]}], "buffers": [{"uri": "%s", "byteLength": 36}], "bufferViews": [{"buffer": 0, "byteLength": 36}], "accessors": [{"bufferView": 0, "componentType": 5126, "count": %s, "type": "VEC3"}]' \
        "$3" "$1" "$2"
}
vertices="data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"
printf '{"asset": {"version": "2.0"},, }\n' >"$work/malformed.gltf"
gltf_file good "$(triangle "$vertices" 3 0)"
gltf_file missing-bin "$(triangle gone.bin 3 0)"
gltf_file overrun "$(triangle "$vertices" 4 0)"
gltf_file no-accessor "$(triangle "$vertices" 3 7)"
expect_error "glTF: malformed JSON" "malformed.gltf: not a valid glTF 2.0 JSON file" --scene "$work/malformed.gltf"
expect_error "glTF: missing buffer file" "missing-bin.gltf: buffer file '.*gone.bin' not found" --scene "$work/missing-bin.gltf"
expect_error "glTF: accessor overrunning its data" "overrun.gltf: /accessors/0: 4 elements of 12 bytes" --scene "$work/overrun.gltf"
expect_error "glTF: accessor index out of range" "POSITION: accessor 7 does not exist" --scene "$work/no-accessor.gltf"
# Issue 41: a required extension the importer does not read refuses the file (glTF 2.0 section 3.12); a buffer
# outside the scene's folder, a buffer that is a folder, and nesting past 512 levels are refused; a folder or a
# device given as the scene says so; control characters of the input reach the terminal escaped.
gltf_file required "\"extensionsRequired\": [\"EXT_unknown_thing\"], $(triangle "$vertices" 3 0)"
mkdir -p "$work/inner"
gltf_file inner/outside "$(triangle ../../../../../../../../etc/passwd 3 0)"
gltf_file dot "$(triangle . 3 0)"
python3 -c 'import sys; sys.stdout.write("{\"asset\": {\"version\": \"2.0\"}, \"extras\": " + "[" * 30000 + "]" * 30000 + "}")' \
    >"$work/deep.gltf"
expect_error "glTF: a required extension not read" "requires EXT_unknown_thing, which this importer does not read" \
    --scene "$work/required.gltf"
expect_error "glTF: a buffer outside the scene's folder" "/etc/passwd' lies outside the scene's folder" \
    --scene "$work/inner/outside.gltf"
expect_error "glTF: a buffer that is a folder" "is not a regular file" --scene "$work/dot.gltf"
expect_error "glTF: nested 30,000 deep" "nested deeper than 512 levels" --scene "$work/deep.gltf"
expect_error "a folder as the scene" "it is a folder, not a scene file" --scene "$work/inner"
expect_error "a device as the scene" "it is not a regular file" --scene /dev/null
expect_error "control characters escaped" "unknown scene 'a\\\\x1b\[2Jb'" --scene "$(printf 'a\033[2Jb')"
expect_error "C1 controls escaped" "unknown scene 'a\\\\xc2\\\\x9b2Jb'" --scene "$(printf 'a\302\2332Jb')"
expect_error "extra arguments in the order given" "'-w 32'" -w 32
printf 'glTF\002\000\000\000' >"$work/cut.glb"
expect_error "glTF: a cut .glb" "cut.glb: not a valid glTF 2.0 binary file" --scene "$work/cut.glb"
# The cases above are broken only where they say: unbroken, the triangle renders.
if ! timeout 60 "$app" --headless --quiet --width 8 --spp 1 --scene "$work/good.gltf" --output "$work/good.png" \
    >/dev/null 2>"$work/stderr"; then
    echo "FAIL glTF: the unbroken triangle does not render: $(cat "$work/stderr")"; failures=$((failures + 1))
fi
rm -f "$work/good.png"
expect_error "export to a non-JSON name" "--export-scene" --export-scene "$work/out.txt"
expect_error "export into a missing folder" "does not exist" --export-scene "$work/no/such/out.json"
# CLI::Range lets NaN through: a number flag refuses it by name.
expect_error "roughness scale NaN" "--roughness-scale" --scene veach-mis --roughness-scale nan
expect_error "pilot budget NaN" "--pilot-budget" --pilot-budget nan
expect_error "pilot time NaN" "--pilot-max-seconds" --pilot-max-seconds nan
# Two outputs naming one file: refused before the render (the second would replace the first, and a failure of
# either removed the file both name: a user's x.exr, given as --hdr and --heatmap, was deleted).
echo keep >"$work/keep.exr"
expect_error "hdr and heatmap one file" "--hdr and --heatmap name the same file" --hdr "$work/keep.exr" \
    --heatmap "$work/keep.exr"
echo keep >"$work/shared.png"
ln -s "$work/shared.png" "$work/alias.json"
expect_error "output and a link to it" "--output and --stats name the same file" --output "$work/shared.png" \
    --stats "$work/alias.json"
grep -q keep "$work/keep.exr" && grep -q keep "$work/shared.png" ||
    { echo "FAIL a refused render touched the user's file"; failures=$((failures + 1)); }
# --compare's flags without --compare.
expect_error "table without compare" "--table requires --compare" --table "$work/t.json"
expect_error "zero reference spp" "--reference-spp" --compare --engines single --spp-list 1 --reference-spp 0
expect_error "empty engine list" "--engines: names no engine" --compare --engines "" --spp-list 1
# A mesh that is a folder is named as one, not "not found".
expect_error "mesh is a folder" "is not a regular file" --scene mesh-in-one-weekend --mesh "$work"

exit $failures
