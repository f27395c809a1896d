#include "Render/BatchPlan.h"

#include <algorithm>
#include <cmath>

namespace rt
{
BatchPlan::BatchPlan(std::uint32_t totalSamples, std::uint64_t pixels, std::uint64_t pathsPerBatch, bool progressive,
                     double targetSeconds)
    : m_total(std::max<std::uint32_t>(totalSamples, 1)), m_target(targetSeconds)
{
    const std::uint64_t fit = pathsPerBatch / std::max<std::uint64_t>(pixels, 1);
    m_max = progressive ? 1u : static_cast<std::uint32_t>(std::clamp<std::uint64_t>(fit, 1, m_total));
}

std::uint32_t BatchPlan::next(std::uint32_t samplesDone) const
{
    const std::uint32_t left = samplesDone < m_total ? m_total - samplesDone : 1u;
    return static_cast<std::uint32_t>(evenPart(left, m_samples));
}

void BatchPlan::record(std::uint32_t samples, double seconds)
{
    samples = std::max<std::uint32_t>(samples, 1);
    const double ideal = workForTarget(samples, seconds, kBatchGrowthLimit * samples, m_target);
    m_samples = static_cast<std::uint32_t>(std::clamp(std::floor(ideal), 1.0, double(m_max)));
}
} // namespace rt
