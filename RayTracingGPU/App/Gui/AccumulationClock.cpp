#include "App/Gui/AccumulationClock.h"

#include <chrono>

namespace rt::gpu::gui
{
AccumulationClock::AccumulationClock(std::uint32_t frameSlots, std::uint32_t mostSamples)
    : m_slotAccumulation(frameSlots, 0), m_slotSamples(frameSlots, 0), m_most(mostSamples)
{
}

void AccumulationClock::start(ProgressiveFrame& frame, const FrameRequest& request)
{
    ++m_accumulation;
    m_seconds = 0.0;
    m_untimed = false;
    m_nextPoint = 1;
    m_ended = false;
    m_compileSeconds.reset();
    const auto begin = std::chrono::steady_clock::now();
    if (frame.preparePipeline(request))
    {
        frame.warmUp(request);
        m_compileSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    }
}

void AccumulationClock::traced(std::uint32_t slot, std::uint32_t samples)
{
    m_slotAccumulation.at(slot) = m_accumulation;
    m_slotSamples.at(slot) = samples;
}

void AccumulationClock::take(ProgressiveFrame& frame, std::uint32_t slot)
{
    const std::optional<double> seconds = frame.takeTraceSeconds(slot);
    if (seconds && m_slotSamples.at(slot) > 0)
        m_automatic = autoFrameSamples(m_slotSamples[slot], *seconds, m_most);
    m_slotSamples.at(slot) = 0;
    if (m_slotAccumulation.at(slot) == 0 || m_slotAccumulation[slot] != m_accumulation)
        return;
    if (seconds)
        m_seconds += *seconds;
    else
        m_untimed = true;
    m_slotAccumulation[slot] = 0; // taken
}

void AccumulationClock::takeAll(ProgressiveFrame& frame)
{
    for (std::uint32_t slot = 0; slot < m_slotAccumulation.size(); ++slot)
        take(frame, slot);
}

std::optional<double> AccumulationClock::seconds() const
{
    return m_untimed || m_seconds <= 0.0 ? std::nullopt : std::optional(m_seconds);
}

void AccumulationClock::pointTaken(std::uint32_t spp)
{
    while (m_nextPoint <= spp)
        m_nextPoint *= 2;
}
} // namespace rt::gpu::gui
