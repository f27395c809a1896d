// Shared between a running render and whoever watches it (the headless progress line, the GUI): a cancel
// flag the render driver polls between batches and an engine may poll within one, a count of finished units
// of work (camera paths, advanced by the engine) for progress and ETA, and how often the watcher wants a
// preview.
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
    /// A cancel was asked for, or the time limit has passed.
    bool cancelRequested() const
    {
        return m_cancel.load(std::memory_order_relaxed) ||
               (m_timeLimitNs.load(std::memory_order_relaxed) > 0 && timeLimitPassed());
    }
    /// Cancels the render once it has run `limit` since begin() (0: never). Set before the render.
    void setTimeLimit(std::chrono::nanoseconds limit) { m_timeLimitNs.store(limit.count()); }
    /// Whether a time limit set is past (what cancelled the render, when no cancel was asked for).
    bool timeLimitPassed() const;

    /// Called by the render driver before it starts: `totalUnits` units of work (the render's camera paths).
    void begin(std::uint64_t totalUnits);
    void advance(std::uint64_t units = 1) { m_done.fetch_add(units, std::memory_order_relaxed); }

    std::uint64_t done() const { return m_done.load(std::memory_order_relaxed); }
    /// Units of the same total done by other processes (an MPI job's other ranks, Cluster/SplitRender.h): counted
    /// in fraction() and etaSeconds(), not in done().
    void setDoneElsewhere(std::uint64_t units) { m_doneElsewhere.store(units, std::memory_order_relaxed); }
    std::uint64_t total() const { return m_total.load(std::memory_order_relaxed); }
    /// In [0, 1]; 0 before begin().
    double fraction() const;
    double elapsedSeconds() const;
    /// Remaining seconds extrapolated from the rate so far; negative while unknown.
    double etaSeconds() const;

    /// At most one preview per `interval` (default 0: one after every batch). Set before the render.
    void setPreviewInterval(std::chrono::nanoseconds interval) { m_previewIntervalNs.store(interval.count()); }
    /// Asked by the render driver before it builds a preview (an estimate image, a read-back from the device), so
    /// previews the watcher would drop cost nothing. True the first time and once `interval` has passed since
    /// the last true; a true counts as the preview taken.
    bool previewDue();

private:
    std::atomic<bool> m_cancel{false};
    std::atomic<std::uint64_t> m_done{0};
    std::atomic<std::uint64_t> m_doneElsewhere{0};
    std::atomic<std::uint64_t> m_total{0};
    std::atomic<std::int64_t> m_startNs{0};
    std::atomic<std::int64_t> m_previewIntervalNs{0};
    std::atomic<std::int64_t> m_lastPreviewNs{-1}; // -1: none yet
    std::atomic<std::int64_t> m_timeLimitNs{0}; // 0: none
};
} // namespace rt
