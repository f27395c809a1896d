// How the render driver cuts a frame into batches: each batch traces a few samples of every pixel (on the GPU
// one vkCmdTraceRaysKHR looping over them), few enough that a batch stays well under a second (responsive
// cancel and progress, no GPU driver watchdog), many enough that the cost of a batch does not matter.
#pragma once

#include <cstdint>

namespace rt
{
struct BatchPlan
{
    std::uint32_t samplesPerBatch = 1;
    std::uint32_t batchCount = 1; // the last batch may trace fewer samples

    std::uint32_t samplesIn(std::uint32_t batch, std::uint32_t totalSamples) const;
};

/// `totalSamples` (>= 1) per pixel over `pixels` pixels, at most `pathsPerBatch` paths per batch (at least
/// one sample). `progressive` (accumulate sampling) makes every batch one sample, so that a preview can
/// follow each pass.
BatchPlan planBatches(std::uint32_t totalSamples, std::uint64_t pixels, std::uint64_t pathsPerBatch,
                      bool progressive);
} // namespace rt
