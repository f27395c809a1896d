#!/usr/bin/env bash
# Prepares what tests/Bench/device_run.sh needs on the lent NVIDIA machine (Ubuntu 24.04, none of our Debian
# packages, no network): .devcarry/ (bin: the built binaries, shaders and assets; lib: the shared libraries
# ldd lists beyond glibc and libstdc++, which the host has newer; layers: the Khronos validation layer) and
# .gl/ (Debian's Vulkan loader and the GL vendor-neutral libraries the NVIDIA ICD loads through). Both folders
# are git-ignored; name them in the device tool's `carry`. Run from the repository root after a build.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${BUILD_DIR:-build}
rm -rf .devcarry
mkdir -p .devcarry/lib .devcarry/layers .gl
cp -rL "$build/bin" .devcarry/bin
# The window needs a display; benchmarks and the CPU-only suites run here (and the carry must stay under 64 MiB).
rm -f .devcarry/bin/rt_gui_gpu_tests .devcarry/bin/rt_gui_cpu_tests .devcarry/bin/rt_bench .devcarry/bin/rt_common_tests \
    .devcarry/bin/rt_cpu_tests .devcarry/bin/fuzz_*_replay
strip .devcarry/bin/ray-tracing-* .devcarry/bin/rt_*_tests .devcarry/bin/rt_gpu_bench 2>/dev/null || true
for exe in .devcarry/bin/ray-tracing-gpu .devcarry/bin/ray-tracing-cpu .devcarry/bin/rt_gpu_tests .devcarry/bin/rt_gpu_bench; do
    [ -e "$exe" ] || continue # a build without tests or without the CPU app
    ldd "$exe" | awk '/=>/ {print $3}'
done | sort -u | grep -vE '/(libc|libm|libdl|libpthread|librt|libstdc\+\+|libgcc_s)\.so' |
    grep -vE '/(libmpi|libopen-rte|libopen-pal|libpmix|libhwloc|libevent[a-z_]*-2\.1|libudev)\.so' |
    xargs -r -I{} cp -L {} .devcarry/lib/
# Compressed (22 MB to a fifth): the carry's 64 MiB hold the tracked files too; device_run.sh unpacks it.
xz -c /usr/lib/x86_64-linux-gnu/libVkLayer_khronos_validation.so >.devcarry/layers/libVkLayer_khronos_validation.so.xz
sed 's|"library_path": "[^"]*"|"library_path": "./libVkLayer_khronos_validation.so"|' \
    /usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json >.devcarry/layers/VkLayer_khronos_validation.json
# A baseline build for tests/Bench/gpu_ab.sh (device_run.sh ab): BASELINE_BIN, a bin folder of another build
# (its ray-tracing-gpu, shaders and assets; the same shared libraries).
if [ -n "${BASELINE_BIN:-}" ]; then
    mkdir -p .devcarry/baseline
    cp -rL "$BASELINE_BIN/ray-tracing-gpu" "$BASELINE_BIN/shaders" "$BASELINE_BIN/Assets" .devcarry/baseline/
    strip .devcarry/baseline/ray-tracing-gpu
fi
# Shader variants for tests/Bench/shader_variants.sh (device_run.sh variants): VARIANTS, folders of SPIR-V in the
# layout of build/bin/shaders, each copied under its own name.
for v in ${VARIANTS:-}; do
    mkdir -p .devcarry/variants
    name=$(basename "$v")
    [ ! -e ".devcarry/variants/$name" ] || { echo "device_carry.sh: two variants named $name" >&2; exit 2; }
    cp -rL "$v" ".devcarry/variants/$name"
done
# The glTF models tests/Cli/scene_files.sh renders (Debian's assimp-testmodels; the host has none).
mkdir -p .devcarry/gltf
for m in BoxTextured-glTF BoxTextured-glTF-Binary cameras; do
    cp -r "/usr/share/assimp/models/glTF2/$m" .devcarry/gltf/ 2>/dev/null || true
done
(cd .gl && apt-get download libvulkan1 libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2 2>/dev/null)
# Open MPI: the lent machines' image has Ubuntu's 4.1.6 (libmpi.so.40, the ABI of Debian's 4.1.4), whose mpirun
# must launch the apps with its own libraries: Debian's carried beside it crashed its mpirun (two PMIx in one
# process, seen 2026-11-27). For a machine without one, MPI_DEBS=1 carries Debian's in .mpi/, which
# device_run.sh unpacks only where no mpirun is found.
rm -rf .mpi
if [ "${MPI_DEBS:-0}" = 1 ]; then
    mkdir -p .mpi
    (cd .mpi && apt-get download openmpi-bin openmpi-common libopenmpi3 libpmix2 libhwloc15 libevent-core-2.1-7 \
        libevent-pthreads-2.1-7 libmunge2 2>/dev/null)
fi
# LEAN=1: only what the benchmarks of the GPU app need (no GPU test binary, no CPU app, no validation layer): the
# working tree's tracked files count against the same 64 MiB (26 MB of them on 2026-11-29, with a baseline build
# the full carry no longer fitted).
if [ "${LEAN:-0}" = 1 ]; then
    rm -rf .devcarry/bin/rt_gpu_tests .devcarry/bin/ray-tracing-cpu .devcarry/layers
fi
du -sh .devcarry .gl
