// Engine/WavefrontPipeline's planWaves: how the wavefront cuts a band of a batch into waves of at most the wave
// buffers' capacity. Host-only (label unit); that waves of any size give the same image is the GPU test
// GpuWavefront.TheWaveSizeDoesNotChangeTheImage.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "Engine/WavefrontPipeline.h"

namespace rt::gpu
{
namespace
{
struct Case
{
    std::uint32_t firstSample, count, width, rows, firstRow, capacity;
};

// Every (pixel, sample) of the band exactly once, a pixel's samples in order, no wave above the capacity, and
// the waves of one sample range within a pixel of each other in size (no short last wave).
TEST(WavePlan, CoversEveryPathOnceInSampleOrderInEvenWaves)
{
    const Case cases[] = {
        {0, 96, 600, 600, 0, 1u << 24}, // many-lights' batch: 175 K, 175 K and 10 K pixels before
        {1, 1, 600, 337, 0, 1u << 24},  // one wave
        {7, 5, 13, 11, 3, 10},          // more samples than a wave holds pixels of: two per wave
        {0, 3, 7, 5, 0, 100},
        {2, 40, 8, 9, 4, 64},           // samples split over waves too: at most 64 at once
        {0, 9, 5, 5, 0, 4},
    };
    for (const Case& c : cases)
    {
        SCOPED_TRACE(::testing::Message() << "count " << c.count << ", " << c.width << "x" << c.rows
                                          << ", capacity " << c.capacity);
        const std::vector<Wave> waves = planWaves(c.firstSample, c.count, {c.width, c.rows}, c.firstRow, c.capacity);
        const std::uint64_t pixels = std::uint64_t(c.width) * c.rows;
        const std::uint64_t firstPixel = std::uint64_t(c.firstRow) * c.width;
        std::vector<std::uint32_t> nextSample(pixels, c.firstSample); // per pixel of the band
        std::uint32_t rangeStart = ~0u;
        std::uint32_t smallest = ~0u, largest = 0;
        const auto checkRange = [&] {
            if (rangeStart != ~0u)
            {
                EXPECT_LE(largest - smallest, 1u) << "waves of samples from " << rangeStart;
            }
        };
        for (const Wave& w : waves)
        {
            ASSERT_GE(w.samples, 1u);
            ASSERT_GE(w.pixelCount, 1u);
            EXPECT_LE(std::uint64_t(w.samples) * w.pixelCount, c.capacity);
            ASSERT_GE(w.pixelBegin, firstPixel);
            ASSERT_LE(w.pixelBegin - firstPixel + w.pixelCount, pixels);
            if (w.firstSample != rangeStart)
            {
                checkRange();
                rangeStart = w.firstSample;
                smallest = ~0u;
                largest = 0;
            }
            smallest = std::min(smallest, w.pixelCount);
            largest = std::max(largest, w.pixelCount);
            for (std::uint32_t p = 0; p < w.pixelCount; ++p)
            {
                std::uint32_t& next = nextSample[w.pixelBegin - firstPixel + p];
                EXPECT_EQ(next, w.firstSample) << "pixel " << w.pixelBegin + p << ": a sample skipped or repeated";
                next = w.firstSample + w.samples;
            }
        }
        checkRange();
        for (const std::uint32_t next : nextSample)
            EXPECT_EQ(next, c.firstSample + c.count);
    }
}

// The case the even spread is for, by number: 360,000 pixels at 96 samples in waves of at most 16 M paths.
TEST(WavePlan, ManyLightsBatchIsThreeEqualWaves)
{
    const std::vector<Wave> waves = planWaves(0, 96, {600, 600}, 0, 1u << 24);
    ASSERT_EQ(waves.size(), 3u);
    for (const Wave& w : waves)
        EXPECT_EQ(w.pixelCount, 120000u);
}
} // namespace
} // namespace rt::gpu
