// The device time of the accumulation image's samples, frame by frame: the GPU window's timed render (an
// accumulation that reaches its stop is a render as headless ones are, timed on the GPU's clock) and the size of
// its frames. Each frame in flight is tagged with the accumulation it traced for and the samples it traced; when
// its slot comes round again (its frame completed), its timestamps (ProgressiveFrame::takeTraceSeconds) go to
// that accumulation, and size the next frame when the count is automatic (autoFrameSamples). The compilation
// and warm-up of the accumulation's pipeline are timed apart, and the plot's points fall due after 1, 2, 4, ...
// spp.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "Engine/ProgressiveFrame.h"

namespace rt::gpu::gui
{
class AccumulationClock
{
public:
    /// `frameSlots`: frames in flight; `mostSamples`: the automatic count's cap.
    AccumulationClock(std::uint32_t frameSlots, std::uint32_t mostSamples);

    /// A new accumulation of `request`: its time from zero, its first point due at 1 spp, its pipeline compiled and
    /// warmed up on `frame` now, out of its time (timed: compileSeconds).
    void start(ProgressiveFrame& frame, const FrameRequest& request);
    /// Frame `slot` traced `samples` for the accumulation.
    void traced(std::uint32_t slot, std::uint32_t samples);
    /// Takes `slot`'s timestamps from `frame` (its frame has completed): to the accumulation's time when they were
    /// its, and to the automatic count.
    void take(ProgressiveFrame& frame, std::uint32_t slot);
    /// take() for every slot: the device is idle.
    void takeAll(ProgressiveFrame& frame);

    /// The automatic samples of the next frame.
    std::uint32_t automaticSamples() const { return m_automatic; }
    /// The device seconds of the accumulation's samples taken so far; nullopt when a frame of it had no
    /// timestamps (the queue has none).
    std::optional<double> seconds() const;
    std::optional<double> compileSeconds() const { return m_compileSeconds; }

    /// A plot point is due at `spp` accumulated (the first frame past each power of two).
    bool pointDue(std::uint32_t spp) const { return spp >= m_nextPoint; }
    /// The point at `spp` was taken: the next is due at the next power of two above it.
    void pointTaken(std::uint32_t spp);
    /// The accumulation's end was recorded (once per accumulation).
    void ended() { m_ended = true; }
    bool hasEnded() const { return m_ended; }

private:
    std::uint64_t m_accumulation = 0; // 0: none
    std::vector<std::uint64_t> m_slotAccumulation; // what each slot's last frame traced for (0: nothing, or taken)
    std::vector<std::uint32_t> m_slotSamples;
    std::uint32_t m_most;
    std::uint32_t m_automatic = 1;
    double m_seconds = 0.0;
    bool m_untimed = false;
    std::uint32_t m_nextPoint = 1;
    bool m_ended = false;
    std::optional<double> m_compileSeconds;
};
} // namespace rt::gpu::gui
