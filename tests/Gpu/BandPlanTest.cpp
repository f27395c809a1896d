// Engine/BandPlan and Shared/BandOrder.h: how the GPU engine cuts a batch into submissions of rows, and the
// interleaved row order that makes every band a sample of the whole frame. Host-only (label unit); the
// shaders' side of the order is checked by the GPU tests OnePassTracesEverySixteenthRow (the rows one pass
// traces) and BandsGiveTheImageOfOneSubmission (every pixel once per sample, whatever the bands).
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

TEST(BandOrder, EveryBandOfAPassSpansTheFrame)
{
    // Wherever a band of one pass (ceil(height / 16) rows) starts, it holds a row of
    // every whole block of sixteen rows, top to bottom (the last rows, height mod 16 of them, only the longer
    // phases reach): its time is a sample of the whole frame's.
    for (const std::uint32_t height : {17u, 200u, 337u, 600u})
    {
        const std::uint32_t pass = BandPlan(height).passRows();
        ASSERT_EQ(pass, (height + kBandInterleave - 1) / kBandInterleave);
        for (std::uint32_t first = 0; first + pass <= height; ++first)
        {
            std::vector<bool> block(height / kBandInterleave, false);
            for (std::uint32_t j = first; j < first + pass; ++j)
            {
                const std::uint32_t row = bandOrderRow(j, height, kBandInterleave);
                if (row / kBandInterleave < block.size())
                    block[row / kBandInterleave] = true;
            }
            ASSERT_EQ(std::count(block.begin(), block.end(), false), 0)
                << "height " << height << ", band from " << first;
        }
    }
}

TEST(BandPlan, WithoutACapTheFirstBandIsTheFrameAtOneSample)
{
    for (const std::uint32_t height : {1u, 5u, 17u, 200u, 337u, 600u})
    {
        const BandPlan plan(height);
        const std::uint32_t rows = plan.nextRows(1, height);
        EXPECT_EQ(rows, height) << height;
        EXPECT_EQ(BandPlan::interleaveFor(rows, height), 1u) << "one band: the rows in order";
    }
    EXPECT_EQ(BandPlan(337).passRows(), 22u); // 337 = 16 x 21 + 1: phase 0 holds 22 rows, 0 to 336
    // Capped below the frame, the first band takes the interleaved order's first rows (a pass or more spans
    // the frame), the frame's rows spread evenly over the bands the cap allows: 12 of at most 30 rows.
    const BandPlan capped(337, 30);
    EXPECT_EQ(capped.nextRows(1, 337), 29u);
    EXPECT_EQ(BandPlan::interleaveFor(29, 337), kBandInterleave);
}

TEST(BandPlan, AFastFirstPassLetsTheRestOfTheFrameGoInOneBand)
{
    BandPlan plan(337, 22); // a first band of one pass
    const std::uint32_t first = plan.nextRows(1, 337);
    ASSERT_EQ(first, plan.passRows());
    plan.record(first, 1, 1e-5); // far under the target: the growth limit decides
    EXPECT_EQ(plan.nextRows(1, 337 - first), 337 - first);
    plan.record(337 - first, 1, 1e-4);
    // The frame traced once: a batch of kBatchGrowthLimit samples is one band, in the rows' own order.
    const auto samples = static_cast<std::uint32_t>(kBatchGrowthLimit);
    EXPECT_EQ(plan.nextRows(samples, 337), 337u);
    EXPECT_EQ(BandPlan::interleaveFor(337, 337), 1u);
    EXPECT_LT(plan.nextRows(2 * samples, 337), 337u) << "twice the growth limit is not trusted";
}

TEST(BandPlan, FirstBandKeepsToItsCap)
{
    BandPlan plan(800, 5); // a pass is 50 rows; 5 rows of 800 px are a CPU device's 4 K paths
    EXPECT_EQ(plan.nextRows(1, 800), 5u);
    plan.record(5, 1, 1e-6);
    EXPECT_EQ(plan.nextRows(1, 795), 20u) << "a band shorter than a pass: 4x";
    EXPECT_EQ(BandPlan(800, 500).nextRows(1, 800), 400u) << "a cap above a pass: two even bands";
}

TEST(BandPlan, AFrameOfAFewSamplesWithinTheCapIsOneBand)
{
    // A GPU's cap: 268 M paths per batch over 16 x 416 px, 40,329 rows x samples. A pilot's measurement is a frame
    // of 416 x 416 px at 30 samples (two seed blocks of 15): 12,480, one band, its rows in order.
    BandPlan plan(416, 40329);
    EXPECT_EQ(plan.nextRows(30, 416), 416u);
    EXPECT_EQ(plan.nextRows(128, 416), 208u) << "past the cap (315 rows at 128 samples): two even bands";
    EXPECT_EQ(BandPlan(416).nextRows(30, 416), 13u) << "without one, the frame at one sample: 32 bands of 13";
}

TEST(BandPlan, ABandShorterThanAPassGrowsAtMostFourTimes)
{
    // A slow device's large image: a band of a few rows is a run of one phase, top to bottom, and does not
    // tell the cost of the rows below it.
    BandPlan plan(4000); // a pass is 250 rows
    plan.record(10, 1, 1e-6);
    EXPECT_EQ(plan.nextRows(1, 3990), 40u) << "4x the band, not 64x the frame's work";
    plan.record(250, 1, 1e-6); // a whole pass: the frame's rate
    EXPECT_EQ(plan.nextRows(1, 3740), 3740u) << "64x the 260 rows measured: the rest in one band";
}

TEST(BandPlan, SizesBandsToTheTargetTime)
{
    BandPlan plan(1000);
    plan.record(50, 1, 2.0 * kBatchTargetSeconds); // 25 rows fit the target
    EXPECT_EQ(plan.nextRows(1, 950), 25u);         // 38 bands of 25
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
