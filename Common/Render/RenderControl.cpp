#include "Render/RenderControl.h"

#include <algorithm>

namespace rt
{
namespace
{
std::int64_t nowNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}
} // namespace

void RenderControl::begin(std::uint64_t totalUnits)
{
    m_done.store(0);
    m_doneElsewhere.store(0);
    m_total.store(totalUnits);
    m_startNs.store(nowNs());
}

bool RenderControl::timeLimitPassed() const
{
    const std::int64_t limit = m_timeLimitNs.load(std::memory_order_relaxed);
    const std::int64_t start = m_startNs.load(std::memory_order_relaxed);
    return limit > 0 && start != 0 && nowNs() - start > limit;
}

double RenderControl::fraction() const
{
    const std::uint64_t t = total();
    const std::uint64_t all = done() + m_doneElsewhere.load(std::memory_order_relaxed);
    return t == 0 ? 0.0 : std::min(1.0, static_cast<double>(all) / static_cast<double>(t));
}

double RenderControl::elapsedSeconds() const
{
    const std::int64_t start = m_startNs.load();
    return start == 0 ? 0.0 : static_cast<double>(nowNs() - start) * 1e-9;
}

bool RenderControl::previewDue()
{
    const std::int64_t now = nowNs();
    const std::int64_t last = m_lastPreviewNs.load();
    if (last >= 0 && now - last < m_previewIntervalNs.load())
        return false;
    m_lastPreviewNs.store(now);
    return true;
}

double RenderControl::etaSeconds() const
{
    const double f = fraction();
    if (f <= 0.0)
        return -1.0;
    return elapsedSeconds() * (1.0 - f) / f;
}
} // namespace rt
