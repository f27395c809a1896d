// How a render is cut into dispatches: each dispatch traces a few samples per pixel (one vkCmdTraceRaysKHR
// looping over them), few enough that a dispatch stays well under a second (no driver watchdog, responsive cancel
// and progress), many enough that submission overhead does not matter.
#pragma once

#include <cstdint>

namespace rt::gpu
{
/// Camera paths one dispatch aims at: ~16 M on a GPU (30 ms on an H100; 16 M ran 15 % faster than 4 M there,
/// docs/PERFORMANCE.md), ~64 K on a CPU device such as lavapipe (a fraction of a second at the test sizes).
inline constexpr std::uint64_t kPathsPerDispatchGpu = std::uint64_t(1) << 24;
inline constexpr std::uint64_t kPathsPerDispatchCpu = std::uint64_t(1) << 16;

struct DispatchPlan
{
    std::uint32_t samplesPerDispatch = 1;
    std::uint32_t dispatchCount = 1; // the last dispatch may trace fewer samples

    std::uint32_t samplesIn(std::uint32_t dispatch, std::uint32_t totalSamples) const;
};

/// `totalSamples` (>= 1) per pixel over `pixels` pixels, at most `pathsPerDispatch` paths per dispatch (at
/// least one sample). `progressive` (accumulate sampling) makes every dispatch one sample, so that a
/// preview follows each pass.
DispatchPlan planDispatches(std::uint32_t totalSamples, std::uint64_t pixels, std::uint64_t pathsPerDispatch,
                            bool progressive);
} // namespace rt::gpu
