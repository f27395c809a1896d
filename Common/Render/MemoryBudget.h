// Whether a render fits the machine's memory, estimated before anything is built or allocated, so that a
// huge request (--count 2000000000, --width 65536) ends with one line giving the figures instead of a
// bare std::bad_alloc, the OOM killer, or minutes of swapping (issue 13). The GPU app's device limits are
// checked beside this (RayTracingGPU/Engine/RenderLimits.h); this is the host's share, for both apps.
#pragma once

#include <cstdint>
#include <string>

#include "Render/RenderSettings.h"

namespace rt
{
/// Host bytes per pixel, an upper bound of what was measured at 1500-3000 px wide (peak RSS): 42 on the CPU
/// (the accumulator, its copy for cancellation, the estimate and the written PNG/PFM), 47 on the GPU app
/// (readback and estimate, and lavapipe's device memory, which is host memory).
inline constexpr std::uint64_t kRenderBytesPerPixel = 64;
/// restir-di's frame adds two reservoirs (64 bytes) and a surface (64 bytes) per pixel (Shared/HostDevice.h).
inline constexpr std::uint64_t kRestirBytesPerPixel = 128;
/// Host bytes per scene object (sphere, quad, triangle, medium or light), an upper bound of what was
/// measured with a million objects: 170 (white-spheres) to 590 (many-lights: light BVH, alias table and
/// lookup) on the CPU, up to 980 through the GPU app (the scene's upload and BLAS build on lavapipe).
inline constexpr std::uint64_t kSceneBytesPerObject = 1024;

/// Estimated host bytes for a render of `pixels` pixels of a scene of `sceneObjects` objects.
std::uint64_t renderBytes(std::uint64_t pixels, std::uint64_t sceneObjects);
/// Estimated host bytes for a render of `settings` (its pixels, restir-di's frame beside them) of a scene of
/// `sceneObjects` objects: what the command line checks before it renders, and the windows show and check.
std::uint64_t renderBytes(const RenderSettings& settings, std::uint64_t sceneObjects);
/// "0.3 MB", "1.2 GB": a byte count as the windows show it.
std::string describeBytes(std::uint64_t bytes);

/// What the machine can give now: MemAvailable of /proc/meminfo, else free physical pages (sysconf);
/// 0 when neither can be read.
std::uint64_t availableMemoryBytes();

/// What a render that replaces one holding `heldBytes` can have: availableMemoryBytes() plus what the old one
/// frees (a window that holds a 4K render and asks for another 4K needs no more than it has); 0 when unknown.
std::uint64_t availableMemoryBytesReplacing(std::uint64_t heldBytes);

/// Throws UsageError "<what> needs about N GB of memory; this machine has M GB available" when `neededBytes`
/// exceeds `availableBytes` (nothing when availableBytes is 0: unknown).
void checkMemory(std::uint64_t neededBytes, const std::string& what, std::uint64_t availableBytes);
} // namespace rt
