// Shared between a running render and whoever watches it (the headless progress line, the GUI): a cancel
// flag the engine polls between units of work, and a count of finished units for progress and ETA.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>

namespace rt
{
class RenderControl
{
public:
    void requestCancel() { m_cancel.store(true, std::memory_order_relaxed); }
    bool cancelRequested() const { return m_cancel.load(std::memory_order_relaxed); }

    /// Called by the engine before it starts: `totalUnits` units of work (rows x passes, dispatches, ...).
    void begin(std::uint64_t totalUnits);
    void advance(std::uint64_t units = 1) { m_done.fetch_add(units, std::memory_order_relaxed); }

    std::uint64_t done() const { return m_done.load(std::memory_order_relaxed); }
    std::uint64_t total() const { return m_total.load(std::memory_order_relaxed); }
    /// In [0, 1]; 0 before begin().
    double fraction() const;
    double elapsedSeconds() const;
    /// Remaining seconds extrapolated from the rate so far; negative while unknown.
    double etaSeconds() const;

private:
    std::atomic<bool> m_cancel{false};
    std::atomic<std::uint64_t> m_done{0};
    std::atomic<std::uint64_t> m_total{0};
    std::atomic<std::int64_t> m_startNs{0};
};
} // namespace rt
