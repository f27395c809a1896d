#include "Render/BatchPlan.h"

#include <algorithm>

namespace rt
{
std::uint32_t BatchPlan::samplesIn(std::uint32_t batch, std::uint32_t totalSamples) const
{
    const std::uint64_t first = std::uint64_t(batch) * samplesPerBatch;
    if (first >= totalSamples)
        return 0;
    return static_cast<std::uint32_t>(std::min<std::uint64_t>(samplesPerBatch, totalSamples - first));
}

BatchPlan planBatches(std::uint32_t totalSamples, std::uint64_t pixels, std::uint64_t pathsPerBatch,
                      bool progressive)
{
    BatchPlan plan;
    const std::uint64_t fit = pathsPerBatch / std::max<std::uint64_t>(pixels, 1);
    plan.samplesPerBatch = progressive ? 1u : static_cast<std::uint32_t>(std::clamp<std::uint64_t>(fit, 1, totalSamples));
    plan.batchCount = (totalSamples + plan.samplesPerBatch - 1) / plan.samplesPerBatch;
    return plan;
}
} // namespace rt
