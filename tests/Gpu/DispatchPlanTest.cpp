#include <gtest/gtest.h>

#include "Engine/DispatchPlan.h"

namespace rt::gpu
{
namespace
{
TEST(DispatchPlan, FitsSamplesToThePathBudget)
{
    const DispatchPlan plan = planDispatches(100, 1000, 8000, false);
    EXPECT_EQ(plan.samplesPerDispatch, 8u);
    EXPECT_EQ(plan.dispatchCount, 13u);
    EXPECT_EQ(plan.samplesIn(0, 100), 8u);
    EXPECT_EQ(plan.samplesIn(12, 100), 4u); // the remainder
    std::uint32_t total = 0;
    for (std::uint32_t d = 0; d < plan.dispatchCount; ++d)
        total += plan.samplesIn(d, 100);
    EXPECT_EQ(total, 100u);
}

TEST(DispatchPlan, AtLeastOneSamplePerDispatchForHugeImages)
{
    const DispatchPlan plan = planDispatches(4, 100'000'000, kPathsPerDispatchCpu, false);
    EXPECT_EQ(plan.samplesPerDispatch, 1u);
    EXPECT_EQ(plan.dispatchCount, 4u);
}

TEST(DispatchPlan, NeverMoreSamplesThanAskedFor)
{
    const DispatchPlan plan = planDispatches(3, 16, kPathsPerDispatchGpu, false);
    EXPECT_EQ(plan.samplesPerDispatch, 3u);
    EXPECT_EQ(plan.dispatchCount, 1u);
}

TEST(DispatchPlan, ProgressiveSamplingIsOneSamplePerDispatch)
{
    const DispatchPlan plan = planDispatches(16, 64, kPathsPerDispatchGpu, true);
    EXPECT_EQ(plan.samplesPerDispatch, 1u);
    EXPECT_EQ(plan.dispatchCount, 16u);
}
} // namespace
} // namespace rt::gpu
