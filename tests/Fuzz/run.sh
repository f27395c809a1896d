#!/usr/bin/env bash
# Usage: tests/Fuzz/run.sh [SECONDS] [BUILD_DIR]
# Coverage-guided fuzzing of every reader of outside input (issue 41): configures a build of its own with clang
# (-DRT_FUZZ=ON: libFuzzer, AddressSanitizer, UBSan; no GPU, windows or MPI), builds the six fuzz targets and runs
# `ctest -L fuzz`: each target for SECONDS (default 600) from the seed corpus of tests/Fuzz/corpus/. A crash
# leaves its input as BUILD_DIR/tests/Fuzz/crash-<target>-*: fix the reader, then copy the input into
# tests/Fuzz/regressions/<target>/, which the default suite replays (fuzz.replay.<target>). Each run's final
# coverage line ("cov: ... ft: ... corp: ...") is in BUILD_DIR/Testing/Temporary/LastTest.log.
set -eu
command -v clang++ >/dev/null ||
    { echo "tests/Fuzz/run.sh: needs clang and libFuzzer (Debian: clang libclang-rt-14-dev; ./build.sh fuzz installs them)" >&2; exit 2; }
seconds=${1:-600}
here=$(cd "$(dirname "$0")/../.." && pwd)
build=${2:-$here/build-fuzz}
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang \
    -DRT_FUZZ=ON -DRT_FUZZ_SECONDS="$seconds" -DRT_BUILD_GPU=OFF -DRT_BUILD_GUI=OFF -DRT_BUILD_BENCHMARKS=OFF \
    -DRT_WITH_MPI=OFF -DRT_X86_LEVEL=x86-64-v2 >/dev/null
targets=()
for t in json_scene gltf obj pfm exr actions; do targets+=(--target "fuzz_$t"); done
cmake --build "$build" -j"$(nproc)" "${targets[@]}"
cd "$build" && ctest -L fuzz -j"${JOBS:-$(nproc)}" --output-on-failure
