// The panel's frames per second and samples per second, over the last second of frames.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <deque>

namespace rt::gpu::gui
{
class Throughput final
{
public:
    using Clock = std::chrono::steady_clock;

    /// A frame presented at `now` that traced `samples` camera samples (paths).
    void add(Clock::time_point now, std::uint64_t samples)
    {
        m_events.push_back({now, samples});
        while (m_events.size() > 2 && now - m_events.front().time > std::chrono::seconds(1))
            m_events.pop_front();
    }

    double framesPerSecond() const { return m_events.size() < 2 ? 0.0 : double(m_events.size() - 1) / span(); }

    double samplesPerSecond() const
    {
        if (m_events.size() < 2)
            return 0.0;
        std::uint64_t samples = 0;
        for (std::size_t i = 1; i < m_events.size(); ++i) // the first frame's samples were traced before the span
            samples += m_events[i].samples;
        return double(samples) / span();
    }

private:
    double span() const
    {
        return std::max(1e-6, std::chrono::duration<double>(m_events.back().time - m_events.front().time).count());
    }

    struct Event
    {
        Clock::time_point time;
        std::uint64_t samples;
    };
    std::deque<Event> m_events;
};
} // namespace rt::gpu::gui
