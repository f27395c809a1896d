#include "Engine/DispatchPlan.h"

#include <algorithm>

namespace rt::gpu
{
std::uint32_t DispatchPlan::samplesIn(std::uint32_t dispatch, std::uint32_t totalSamples) const
{
    const std::uint64_t first = std::uint64_t(dispatch) * samplesPerDispatch;
    if (first >= totalSamples)
        return 0;
    return static_cast<std::uint32_t>(std::min<std::uint64_t>(samplesPerDispatch, totalSamples - first));
}

DispatchPlan planDispatches(std::uint32_t totalSamples, std::uint64_t pixels, std::uint64_t pathsPerDispatch,
                            bool progressive)
{
    DispatchPlan plan;
    const std::uint64_t fit = pathsPerDispatch / std::max<std::uint64_t>(pixels, 1);
    plan.samplesPerDispatch = progressive ? 1u : static_cast<std::uint32_t>(std::clamp<std::uint64_t>(fit, 1, totalSamples));
    plan.dispatchCount = (totalSamples + plan.samplesPerDispatch - 1) / plan.samplesPerDispatch;
    return plan;
}
} // namespace rt::gpu
