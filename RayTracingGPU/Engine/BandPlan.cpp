#include "Engine/BandPlan.h"

#include <algorithm>
#include <cmath>

#include "Render/BatchPlan.h"
#include "Shared/BandOrder.h"

namespace rt::gpu
{
BandPlan::BandPlan(std::uint32_t height, std::uint64_t firstWork)
    : m_pass((std::max(height, 1u) + shader::kBandInterleave - 1) / shader::kBandInterleave),
      m_work(firstWork > 0 ? firstWork : std::max(height, 1u))
{
}

std::uint32_t BandPlan::nextRows(std::uint32_t samples, std::uint32_t rowsLeft) const
{
    const std::uint64_t perBand = std::max<std::uint64_t>(m_work / std::max(samples, 1u), 1);
    return static_cast<std::uint32_t>(evenPart(std::max(rowsLeft, 1u), perBand));
}

void BandPlan::record(std::uint32_t rows, std::uint32_t samples, double seconds)
{
    const std::uint64_t work = std::uint64_t(rows) * samples;
    m_measured += work;
    const double grown =
        rows >= m_pass ? kBatchGrowthLimit * double(m_measured) : kShortBandGrowth * double(work);
    const double ideal = workForTarget(double(work), seconds, grown);
    m_work = static_cast<std::uint64_t>(std::clamp(std::floor(ideal), 1.0, 1e15));
}

std::uint32_t BandPlan::interleaveFor(std::uint32_t rows, std::uint32_t height)
{
    return rows < height ? shader::kBandInterleave : 1u;
}
} // namespace rt::gpu
