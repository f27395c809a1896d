// How GpuEngine cuts a batch (Render/BatchPlan.h: a few samples of every pixel) into submissions of rows. The
// engine cancels between submissions, so each must stay near kBatchTargetSeconds on any device: one sample of
// a 200x200 heavy scene is seconds on lavapipe. A frame's first band is as many rows x samples as the engine's
// cap allows (a sixteenth of its paths per batch: a pass or less on a CPU device's large image, a frame of a few
// samples on a GPU), in the interleaved order (every sixteenth row first) where it is not the whole batch; each
// band after is sized by the time the last one took.
//
// A batch of several bands takes its rows in the interleaved order (Shared/BandOrder.h), so that every band
// of a pass or more, the first included, samples the whole frame and its rate holds for the next. Bands of
// consecutive rows sized the lower rows from the top ones: with a growth of 64 that ran 1.6 s past a Ctrl-C
// on lavapipe, and with a growth of 4 the H100 traced a 600x337 render of a light scene in eleven
// submissions, up to 1.3x its time (docs/notebook/PERFORMANCE.md §8.6, §8.7). A band shorter than a pass (a slow
// device's large image) is a run of one phase, top to bottom, so the band after it grows at most 4x, as bands
// of consecutive rows did. A batch of one band keeps the rows in order.
#pragma once

#include <cstdint>

namespace rt::gpu
{
class BandPlan
{
public:
    /// A frame of `height` (>= 1) rows whose first band is `firstWork` rows x samples (0: `height`, the frame at
    /// one sample). The engine's is its cap on a first band's paths over the image's width: below the frame at
    /// one sample on a slow device's large image (800x800 of many-lights is 24 ms a row on lavapipe, so a pass of
    /// 50 rows ran past the 1 s a Ctrl-C may take), and above it on a GPU, whose frames of a few samples in one
    /// batch (a pilot's) then take one band: with a first band of the frame at one sample they took three, and
    /// an H200's pilot of cornell-box-lights spent 0.2 s of its 1.2 s search in their submissions (notebook §69).
    /// A first band of one pass, the rule before these, cost the H100 a submission: 0-3 % of a 256-spp light book
    /// render (docs/notebook/PERFORMANCE.md §8.8).
    explicit BandPlan(std::uint32_t height, std::uint64_t firstWork = 0);

    /// Rows of the next band of a batch of `samples` per pixel, of which `rowsLeft` (>= 1) rows are not
    /// traced yet: the rows the measured rate gives kBatchTargetSeconds, spread evenly over the bands the
    /// batch's rest then needs (no short band at its end, whose few rows would leave the device idle).
    std::uint32_t nextRows(std::uint32_t samples, std::uint32_t rowsLeft) const;

    /// Reports that a band of `rows` x `samples` took `seconds` (<= 0: unmeasured). The next band aims at the
    /// target time at that rate, but at most kBatchGrowthLimit times the work measured so far in the frame
    /// after a band of a pass or more (a measurement of microseconds is not trusted with seconds), and at
    /// most kShortBandGrowth times this band's work after a shorter one (its rows were not a sample of the
    /// frame).
    void record(std::uint32_t rows, std::uint32_t samples, double seconds);

    /// Rows of one pass of the interleaved order: a band of this many rows or more spans the frame.
    std::uint32_t passRows() const { return m_pass; }

    /// The growth after a band shorter than a pass.
    static constexpr double kShortBandGrowth = 4.0;

    /// The row order of a batch whose first band has `rows` of the frame's `height`: kBandInterleave when it
    /// takes several bands, else 1 (rows in order, as coherent as can be).
    static std::uint32_t interleaveFor(std::uint32_t rows, std::uint32_t height);

private:
    std::uint32_t m_pass;
    std::uint64_t m_work; // rows x samples of the next band
    std::uint64_t m_measured = 0; // rows x samples traced so far in the frame
};
} // namespace rt::gpu
