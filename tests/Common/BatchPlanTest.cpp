#include <gtest/gtest.h>

#include "Render/BatchPlan.h"

namespace rt
{
namespace
{
TEST(BatchPlan, FitsSamplesToThePathBudget)
{
    const BatchPlan plan = planBatches(100, 1000, 8000, false);
    EXPECT_EQ(plan.samplesPerBatch, 8u);
    EXPECT_EQ(plan.batchCount, 13u);
    EXPECT_EQ(plan.samplesIn(0, 100), 8u);
    EXPECT_EQ(plan.samplesIn(12, 100), 4u); // the remainder
    std::uint32_t total = 0;
    for (std::uint32_t b = 0; b < plan.batchCount; ++b)
        total += plan.samplesIn(b, 100);
    EXPECT_EQ(total, 100u);
}

TEST(BatchPlan, AtLeastOneSamplePerBatchForHugeImages)
{
    const BatchPlan plan = planBatches(4, 100'000'000, std::uint64_t(1) << 16, false);
    EXPECT_EQ(plan.samplesPerBatch, 1u);
    EXPECT_EQ(plan.batchCount, 4u);
}

TEST(BatchPlan, NeverMoreSamplesThanAskedFor)
{
    const BatchPlan plan = planBatches(3, 16, std::uint64_t(1) << 24, false);
    EXPECT_EQ(plan.samplesPerBatch, 3u);
    EXPECT_EQ(plan.batchCount, 1u);
}

TEST(BatchPlan, ProgressiveSamplingIsOneSamplePerBatch)
{
    const BatchPlan plan = planBatches(16, 64, std::uint64_t(1) << 24, true);
    EXPECT_EQ(plan.samplesPerBatch, 1u);
    EXPECT_EQ(plan.batchCount, 16u);
}
} // namespace
} // namespace rt
