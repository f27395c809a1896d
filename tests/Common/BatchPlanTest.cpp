// Render/BatchPlan: batches sized by time (issue 13: a fixed path count made one lavapipe dispatch 10 s, so
// Ctrl-C waited that long), within the engine's path budget, one sample each for progressive sampling.
#include <gtest/gtest.h>

#include <vector>

#include "Render/BatchPlan.h"

namespace rt
{
namespace
{
TEST(BatchPlan, StartsWithOneSampleAndGrowsAtMostByTheLimit)
{
    static_assert(kBatchGrowthLimit == 64.0, "the expectations below are for a limit of 64");
    BatchPlan plan(10000, 64, std::uint64_t(1) << 30, false);
    EXPECT_EQ(plan.next(0), 1u);
    plan.record(1, 1e-6); // very fast: the time says 250000 samples, the growth limit 64
    EXPECT_EQ(plan.next(1), 64u);
    plan.record(64, 0.0); // unmeasured: grow
    EXPECT_EQ(plan.next(65), 3312u) << "9935 samples left, in three batches of at most 4096";
    EXPECT_EQ(plan.next(9000), 1000u) << "the remainder";
}

TEST(BatchPlan, SpreadsTheSamplesLeftEvenly)
{
    // A 600x337 render at 256 spp within 2^24 paths a batch (82 spp): after the first sample, four batches of
    // 64 or 63, not 64, 82, 82 and a last one of 27 whose few samples per thread would leave a GPU idle.
    BatchPlan plan(256, 600 * 337, std::uint64_t(1) << 24, false);
    ASSERT_EQ(plan.maxSamples(), 82u);
    std::uint32_t done = 0;
    std::vector<std::uint32_t> batches;
    while (done < 256)
    {
        batches.push_back(plan.next(done));
        done += batches.back();
        plan.record(batches.back(), 1e-9);
    }
    EXPECT_EQ(batches, (std::vector<std::uint32_t>{1, 64, 64, 64, 63}));
}

TEST(BatchPlan, SizesTheNextBatchToTheTargetTime)
{
    BatchPlan plan(1'000'000, 64, std::uint64_t(1) << 30, false, 0.1);
    plan.record(100, 0.05); // 2000 samples per second: 200 in 0.1 s
    EXPECT_EQ(plan.next(100), 200u);
    plan.record(200, 2.0); // a slow batch: shrink at once, to 10
    EXPECT_EQ(plan.next(300), 10u);
    plan.record(10, 100.0); // slower than the target at one sample: still one
    EXPECT_EQ(plan.next(310), 1u);
}

TEST(BatchPlan, FitsSamplesToThePathBudget)
{
    BatchPlan plan(100, 1000, 8000, false);
    EXPECT_EQ(plan.maxSamples(), 8u);
    for (int i = 0; i < 10; ++i)
        plan.record(plan.next(0), 1e-9);
    EXPECT_EQ(plan.next(0), 8u);
    EXPECT_EQ(plan.next(96), 4u); // the remainder
}

TEST(BatchPlan, AtLeastOneSamplePerBatchForHugeImages)
{
    const BatchPlan plan(4, 100'000'000, std::uint64_t(1) << 16, false);
    EXPECT_EQ(plan.maxSamples(), 1u);
    EXPECT_EQ(plan.next(0), 1u);
}

TEST(BatchPlan, NeverMoreSamplesThanAskedFor)
{
    BatchPlan plan(3, 16, std::uint64_t(1) << 24, false);
    EXPECT_EQ(plan.maxSamples(), 3u);
    plan.record(1, 1e-9);
    EXPECT_EQ(plan.next(1), 2u);
}

TEST(BatchPlan, ProgressiveSamplingIsOneSamplePerBatch)
{
    BatchPlan plan(16, 64, std::uint64_t(1) << 24, true);
    plan.record(1, 1e-9);
    EXPECT_EQ(plan.next(1), 1u);
}
} // namespace
} // namespace rt
