#!/usr/bin/env bash
# Set up, build, and run the main job or the tests, on Debian 12 (bookworm).
#
#   ./build.sh          install what is missing, configure and build (Release) into build/
#   ./build.sh run      ... installing and building only the two apps and their shaders (tests off), then the
#                       main job: render cornell-box-lights at 600x600 to out/, print the time, and the CPU/GPU
#                       timing table. About 8 minutes on a bare 2-core machine, installs included.
#   ./build.sh test     ... then the test suite (everything but the label "heavy")
#   ./build.sh heavy    ... then the heavy suites only
#   ./build.sh fuzz     installs clang and libFuzzer, then fuzzes every reader of outside input for FUZZ_SECONDS
#                       (default 600) each in a build of its own, build-fuzz/ (tests/Fuzz/run.sh; label fuzz)
#
# Environment: BUILD_DIR (default build), BUILD_TYPE (default Release), JOBS (default: number of cores),
# RT_SKIP_APT=1 to never call apt-get.
set -euo pipefail
cd "$(dirname "$0")"

mode=${1:-build}
BUILD_DIR=${BUILD_DIR:-build}
BUILD_TYPE=${BUILD_TYPE:-Release}
JOBS=${JOBS:-$(nproc)}

# Every dependency comes from Debian's packages. mesa-vulkan-drivers (lavapipe, the CPU Vulkan device with
# ray tracing) must be 25.x, from bookworm-backports: bookworm's own 22.x has no ray tracing. `run` installs
# what the two apps need; the tests' and benchmarks' own packages come with `build`, `test` and `heavy`.
app_packages=(
    cmake g++ make pkg-config file python3 python3-matplotlib
    libglm-dev libspdlog-dev libstb-dev libtinyobjloader-dev libtbb-dev libcli11-dev nlohmann-json3-dev zlib1g-dev
    libvulkan-dev glslc spirv-tools libglfw3-dev libimgui-dev fonts-dejavu-core xplanet-images assimp-testmodels libtinygltf-dev
    libopenexr-dev libopenmpi-dev openmpi-bin
)
test_packages=(
    libgtest-dev libbenchmark-dev vulkan-tools vulkan-validationlayers xvfb xauth x11-utils xdotool imagemagick hyperfine
    python3-openimageio
)
backports_packages=(mesa-vulkan-drivers)
fuzz_packages=(clang libclang-rt-14-dev)

as_root() {
    if [ "$(id -u)" -eq 0 ]; then "$@"; elif command -v sudo >/dev/null; then sudo "$@"; else
        echo "build.sh: need root (or sudo) to run: $*" >&2; exit 1
    fi
}

missing_packages() {
    local p
    for p in "$@"; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
    done
}

lavapipe_is_new_enough() {
    local v
    v=$(dpkg-query -W -f='${Version}' mesa-vulkan-drivers 2>/dev/null || true)
    [ -n "$v" ] && dpkg --compare-versions "$v" ge 25
}

# install_dependencies PACKAGE...: those missing, and lavapipe from backports where it is older than 25.
install_dependencies() {
    [ "${RT_SKIP_APT:-0}" = 1 ] && return
    local missing
    missing=$(missing_packages "$@")
    if [ -z "$missing" ] && lavapipe_is_new_enough; then
        return
    fi
    echo "== installing Debian packages: ${missing//$'\n'/ } ${backports_packages[*]}"
    if ! grep -rqs "bookworm-backports" /etc/apt/sources.list /etc/apt/sources.list.d/; then
        echo "deb http://deb.debian.org/debian bookworm-backports main" |
            as_root tee /etc/apt/sources.list.d/bookworm-backports.list >/dev/null
    fi
    as_root env DEBIAN_FRONTEND=noninteractive apt-get update -qq
    # shellcheck disable=SC2086
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $missing >/dev/null
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
        -t bookworm-backports "${backports_packages[@]}" >/dev/null
}

# build [TARGET...]: configure, then build the targets named (with what they need, and without the tests'
# targets), or everything.
build() {
    local tests=ON
    [ $# -gt 0 ] && tests=OFF
    echo "== configuring ($BUILD_TYPE) and building${*:+ $*} in $BUILD_DIR with $JOBS jobs"
    cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE="$BUILD_TYPE" -DRT_BUILD_TESTS=$tests -DRT_BUILD_BENCHMARKS=$tests \
        >/dev/null
    local targets=()
    local t known
    # Read whole before grep: `grep -q` would close the pipe early, and under pipefail the build's broken
    # pipe would read as "no such target" (and build everything).
    known=$(cmake --build "$BUILD_DIR" --target help)
    for t in "$@"; do
        # A target the configuration left out (the GPU app without Vulkan) is skipped, not an error.
        if grep -q "^\.\.\. $t\$" <<<"$known"; then
            targets+=(--target "$t")
        fi
    done
    cmake --build "$BUILD_DIR" -j "$JOBS" "${targets[@]}"
}

main_job() {
    mkdir -p out
    # 512 spp at 600x600 takes about a minute on a 2-core machine of the CI kind (docs/notebook/PERFORMANCE.md).
    echo "== main job: cornell-box-lights, 600x600, 512 spp, depth 50, multi-core CPU, the strategy a pilot chooses"
    "$BUILD_DIR/bin/ray-tracing-cpu" --headless --scene cornell-box-lights --width 600 --spp 512 --depth 50 \
        --engine multi --output out/cornell-box-lights.png --hdr out/cornell-box-lights.pfm \
        --stats out/cornell-box-lights.json
    if [ -x "$BUILD_DIR/bin/ray-tracing-gpu" ]; then
        echo "== CPU vs GPU (Vulkan ray tracing; lavapipe where there is no GPU): cornell-box-lights, 200x200"
        "$BUILD_DIR/bin/ray-tracing-gpu" --compare --scene cornell-box-lights --width 200 --spp-list 4,16 \
            --depth 50 --reference-spp 64 --table out/compare.json
    fi
}

run_tests() {
    local labels=("$@")
    ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$JOBS" "${labels[@]}"
}

case "$mode" in
run) install_dependencies "${app_packages[@]}" && build ray-tracing-cpu ray-tracing-gpu && main_job ;;
build | test | heavy) install_dependencies "${app_packages[@]}" "${test_packages[@]}" && build ;;&
test) run_tests -LE heavy ;;
heavy) run_tests -L heavy ;;
fuzz) install_dependencies "${app_packages[@]}" "${fuzz_packages[@]}" && tests/Fuzz/run.sh "${FUZZ_SECONDS:-600}" ;;
build) ;;
*) echo "usage: $0 [build|run|test|heavy|fuzz]" >&2; exit 2 ;;
esac
