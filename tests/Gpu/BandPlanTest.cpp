// Engine/BandPlan and Shared/BandOrder.h: how the GPU engine cuts a batch into submissions of rows, and the
// interleaved row order that makes every band a sample of the whole frame. Host-only (label unit); the
// shaders' side of the order is checked by GpuEngineTest's banded renders, which must give every pixel.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <vector>

#include "Engine/BandPlan.h"
#include "Render/BatchPlan.h"
#include "Shared/BandOrder.h"

namespace rt::gpu
{
namespace
{
using shader::bandOrderRow;
using shader::kBandInterleave;

TEST(BandOrder, IsAPermutationOfTheRowsForEveryHeight)
{
    for (std::uint32_t interleave : {1u, 3u, kBandInterleave})
        for (std::uint32_t height = 1; height <= 300; ++height)
        {
            std::vector<std::uint32_t> rows(height);
            for (std::uint32_t j = 0; j < height; ++j)
                rows[j] = bandOrderRow(j, height, interleave);
            std::sort(rows.begin(), rows.end());
            std::vector<std::uint32_t> expected(height);
            std::iota(expected.begin(), expected.end(), 0u);
            ASSERT_EQ(rows, expected) << "height " << height << ", interleave " << interleave;
        }
}

TEST(BandOrder, TakesEverySixteenthRowFirstThenTheNextPhase)
{
    const std::uint32_t height = 337; // 21 rows in each phase, one more in the first
    for (std::uint32_t j = 0; j < 22; ++j)
        EXPECT_EQ(bandOrderRow(j, height, kBandInterleave), 16 * j) << j;
    EXPECT_EQ(bandOrderRow(22, height, kBandInterleave), 1u);
    EXPECT_EQ(bandOrderRow(height - 1, height, kBandInterleave), 335u) << "the last phase's last row";
    EXPECT_EQ(bandOrderRow(7, height, 1), 7u) << "interleave 1: the rows in order";
}

TEST(BandOrder, EveryBandOfASixteenthSpansTheFrame)
{
    // Wherever a band of a sixteenth of the rows starts, it holds rows of the frame's top and bottom
    // sixteenths: its time is a sample of the whole frame's.
    const std::uint32_t height = 600;
    const std::uint32_t band = height / kBandInterleave;
    for (std::uint32_t first = 0; first + band <= height; ++first)
    {
        std::uint32_t top = height;
        std::uint32_t bottom = 0;
        for (std::uint32_t j = first; j < first + band; ++j)
        {
            top = std::min(top, bandOrderRow(j, height, kBandInterleave));
            bottom = std::max(bottom, bandOrderRow(j, height, kBandInterleave));
        }
        ASSERT_LT(top, band) << "band from " << first;
        ASSERT_GE(bottom, height - band) << "band from " << first;
    }
}

TEST(BandPlan, FirstBandIsASixteenthAtOneSampleInTheInterleavedOrder)
{
    const BandPlan plan(337);
    const std::uint32_t rows = plan.nextRows(1, 337);
    EXPECT_GE(rows, 1u);
    EXPECT_LE(rows, 337u / 16);
    EXPECT_EQ(BandPlan::interleaveFor(rows, 337), kBandInterleave);
    EXPECT_EQ(BandPlan(5).nextRows(1, 5), 1u) << "at least one row";
}

TEST(BandPlan, AFastFirstBandLetsTheRestOfTheFrameGoInOneBand)
{
    BandPlan plan(337);
    const std::uint32_t first = plan.nextRows(1, 337);
    plan.record(first, 1, 1e-5); // far under the target: the growth limit decides
    EXPECT_EQ(plan.nextRows(1, 337 - first), 337 - first);
    plan.record(337 - first, 1, 1e-4);
    // The frame traced once: a batch of kBatchGrowthLimit samples is one band, in the rows' own order.
    const auto samples = static_cast<std::uint32_t>(kBatchGrowthLimit);
    EXPECT_EQ(plan.nextRows(samples, 337), 337u);
    EXPECT_EQ(BandPlan::interleaveFor(337, 337), 1u);
    EXPECT_LT(plan.nextRows(2 * samples, 337), 337u) << "twice the growth limit is not trusted";
}

TEST(BandPlan, SizesBandsToTheTargetTime)
{
    BandPlan plan(1000);
    plan.record(50, 1, 2.0 * kBatchTargetSeconds); // 25 rows fit the target
    EXPECT_EQ(plan.nextRows(1, 950), 25u); // 38 bands of 25
    EXPECT_EQ(plan.nextRows(5, 950), 5u) << "five samples a row: a fifth of the rows";
    plan.record(25, 1, 100.0); // slower than the target at one row: still one row
    EXPECT_EQ(plan.nextRows(1, 925), 1u);
}

TEST(BandPlan, SpreadsTheRowsLeftEvenlyOverTheBands)
{
    BandPlan plan(1000);
    plan.record(100, 1, kBatchTargetSeconds / 3.0); // 300 rows fit the target
    // 337 rows left: two bands of 169 and 168, not 300 and a band of 37 that leaves the device idle.
    EXPECT_EQ(plan.nextRows(1, 337), 169u);
    EXPECT_EQ(plan.nextRows(1, 168), 168u);
    EXPECT_EQ(plan.nextRows(1, 900), 300u) << "three full bands";
}
} // namespace
} // namespace rt::gpu
