// How the render driver cuts a frame into batches: each batch traces a few samples of every pixel (on the GPU
// one vkCmdTraceRaysKHR looping over them). A batch is the unit of cancellation on the GPU and of progress
// and previews on both engines, so it must stay short whatever the scene, size and device: a fixed count of
// paths was 10 s on lavapipe in a heavy scene (issue 13: Ctrl-C took that long). The plan therefore sizes
// batches by time: it starts with one sample per pixel, measures, and sizes the next batch to take about
// kBatchTargetSeconds, never above the engine's paths per batch. Any cut gives the same image (each pixel
// adds its samples in sample order), so sizing by a clock costs no determinism.
#pragma once

#include <algorithm>
#include <cstdint>

namespace rt
{
/// What a batch aims at, in seconds: the GPU engine cancels between batches, so this bounds Ctrl-C there
/// (within a second even at a few times this), while the per-batch cost (a submit and wait; the CPU's
/// parallel loop tail, ~3 ms on 2 cores) stays near a percent. The CPU engine cancels within a batch.
inline constexpr double kBatchTargetSeconds = 0.25;

/// How much a batch may grow on the next, a bound on what one measurement is trusted with. The target time
/// bounds every batch anyway; this only keeps a first batch measured in microseconds from sizing the second to
/// the whole render: every batch covers every pixel, so its rate holds for the next. It was 4: a 600x337
/// render at 256 spp then took five batches (1, 4, 16, 64, 171 spp), each waited for and each ending in the
/// tail of its slowest paths, which cost the H100's light renders of 10-100 ms up to 1.2x (docs/notebook/PERFORMANCE.md
/// §8.6). GpuEngine's bands of rows take the same limit, of the work measured so far in the frame rather than
/// of the last band, after a band that spans the frame (Engine/BandPlan.h).
inline constexpr double kBatchGrowthLimit = 64.0;

/// Work (samples, or rows x samples) of the next submission after one of `work` took `seconds`: `target`
/// seconds' worth at that rate, at most `grown`; `grown` when unmeasured (`seconds` <= 0). Not rounded.
inline double workForTarget(double work, double seconds, double grown, double target = kBatchTargetSeconds)
{
    return seconds > 0.0 ? std::min(grown, work * target / seconds) : grown;
}

/// The first of the even parts `left` (>= 1) takes when cut into as few parts of at most `most` (>= 1) as it
/// needs: no short part at the end.
inline std::uint64_t evenPart(std::uint64_t left, std::uint64_t most)
{
    const std::uint64_t parts = (left + most - 1) / most;
    return (left + parts - 1) / parts;
}

class BatchPlan
{
public:
    /// `totalSamples` (>= 1) per pixel over `pixels` pixels, at most `pathsPerBatch` paths per batch (but
    /// at least one sample). `progressive` (accumulate sampling) makes every batch one sample, so that a
    /// preview can follow each pass.
    BatchPlan(std::uint32_t totalSamples, std::uint64_t pixels, std::uint64_t pathsPerBatch, bool progressive,
              double targetSeconds = kBatchTargetSeconds);

    /// Samples per pixel of the next batch, given `samplesDone` (< totalSamples) so far: >= 1. The samples
    /// left are spread evenly over the batches they need at the planned size, so that no batch of a few
    /// samples ends the render: on a GPU its few paths per thread would leave most of the device idle while
    /// the launch still pays its whole tail.
    std::uint32_t next(std::uint32_t samplesDone) const;
    /// Reports that a batch of `samples` took `seconds` (wall clock; <= 0 when unmeasured): the next batch
    /// aims at the target time at that rate, growing at most kBatchGrowthLimit times.
    void record(std::uint32_t samples, double seconds);

    /// The most samples a batch may hold: the path budget's share of each pixel.
    std::uint32_t maxSamples() const { return m_max; }

private:
    std::uint32_t m_total;
    std::uint32_t m_max;
    std::uint32_t m_samples = 1; // the next batch's, before the remainder cuts it
    double m_target;
};
} // namespace rt
