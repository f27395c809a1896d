// Random numbers of Random/Pcg.h: each camera sample's stream is a pure function of (seed, pixel, sample),
// streams of different samples differ and look independent, nextFloat is uniform on [0, 1) and never 1,
// and pcgHash mixes its input. Known answers come from inverting PCG's output permutation here, not from
// running the code under test.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "Random/Pcg.h"
#include "Support/ChiSquare.h"
#include "Support/StatisticsHelpers.h"

namespace rt
{
namespace
{
// PCG32's LCG step and RXS-M-XS output constants (O'Neill 2014, and Jarzynski & Olano 2020's pcg_hash).
constexpr std::uint32_t kMultiplier = 747796405u;
constexpr std::uint32_t kIncrement = 2891336453u;
constexpr std::uint32_t kOutputMultiplier = 277803737u;

/// Inverse of an odd number modulo 2^32 by Newton's iteration (each step doubles the correct low bits).
constexpr std::uint32_t inverseOdd(std::uint32_t a)
{
    std::uint32_t x = a; // correct to 3 bits: a * a = 1 mod 8 for odd a
    for (int i = 0; i < 5; ++i)
        x *= 2u - a * x;
    return x;
}

/// The PCG state whose RXS-M-XS output is `out`: each of the three steps of the output is a bijection.
constexpr std::uint32_t stateWithOutput(std::uint32_t out)
{
    const std::uint32_t word = out ^ (out >> 22); // undoes word ^ (word >> 22): the top 10 bits are unchanged
    const std::uint32_t x = word * inverseOdd(kOutputMultiplier);
    const int shift = int(x >> 28) + 4; // the xorshift keeps the top 4 bits that chose it
    std::uint32_t state = 0;
    for (int s = 0; s < 32; s += shift)
        state ^= x >> s;
    return state;
}

/// A generator whose next nextUint() returns `out`.
Rng rngWhoseNextOutputIs(std::uint32_t out)
{
    return Rng((stateWithOutput(out) - kIncrement) * inverseOdd(kMultiplier));
}

std::array<std::uint32_t, 8> firstOutputs(Rng rng)
{
    std::array<std::uint32_t, 8> out{};
    for (auto& x : out)
        x = rng.nextUint();
    return out;
}

TEST(Rng, OutputInversionIsRight)
{
    // The known-answer tests below rest on stateWithOutput: check it against pcgHash(v) = output(v a + c).
    for (std::uint32_t v : {0u, 1u, 12345u, 0x80000000u, 0xFFFFFFFFu})
        EXPECT_EQ(stateWithOutput(pcgHash(v)), v * kMultiplier + kIncrement) << v;
    EXPECT_EQ(rngWhoseNextOutputIs(0xDEADBEEFu).nextUint(), 0xDEADBEEFu);
}

TEST(Rng, NextFloatIsInUnitIntervalAndNeverOne)
{
    // The largest output maps to the largest float below 1, the smallest to 0 (the top 24 bits, exactly).
    EXPECT_EQ(rngWhoseNextOutputIs(0xFFFFFFFFu).nextFloat(), 1.0f - 0x1p-24f);
    EXPECT_LT(rngWhoseNextOutputIs(0xFFFFFFFFu).nextFloat(), 1.0f);
    EXPECT_EQ(rngWhoseNextOutputIs(0xFFFFFF00u).nextFloat(), 1.0f - 0x1p-24f);
    EXPECT_EQ(rngWhoseNextOutputIs(0x000000FFu).nextFloat(), 0.0f);
    EXPECT_EQ(rngWhoseNextOutputIs(0x00000100u).nextFloat(), 0x1p-24f);
    Rng rng = Rng::forSample(3, 4, 5);
    for (int i = 0; i < 1'000'000; ++i)
    {
        const float u = rng.nextFloat();
        ASSERT_GE(u, 0.0f);
        ASSERT_LT(u, 1.0f);
    }
}

TEST(Rng, SameSampleGivesTheSameStream)
{
    for (std::uint32_t seed : {0u, 7u})
        for (std::uint32_t pixel : {0u, 1u, 640u * 480u - 1u})
            for (std::uint32_t sample : {0u, 99u})
                EXPECT_EQ(firstOutputs(Rng::forSample(seed, pixel, sample)),
                          firstOutputs(Rng::forSample(seed, pixel, sample)));
}

TEST(Rng, DifferentSamplesGiveDifferentStreams)
{
    // 4 seeds x 64 pixels x 64 samples: no two streams share their first two outputs. A construction that
    // combined the three counters symmetrically (a sum, a plain xor) would collide here at once.
    std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
    for (std::uint32_t seed = 0; seed < 4; ++seed)
        for (std::uint32_t pixel = 0; pixel < 64; ++pixel)
            for (std::uint32_t sample = 0; sample < 64; ++sample)
            {
                Rng rng = Rng::forSample(seed, pixel, sample);
                const std::uint32_t a = rng.nextUint();
                const std::uint32_t b = rng.nextUint();
                EXPECT_TRUE(seen.insert({a, b}).second)
                    << "seed " << seed << ", pixel " << pixel << ", sample " << sample << " repeats a stream";
            }
}

TEST(PcgHash, DistinctInputsGiveDistinctOutputs)
{
    // The hash is a bijection of 32-bit words; on the first 1e5 inputs no output may repeat.
    std::vector<std::uint32_t> outputs;
    for (std::uint32_t v = 0; v < 100'000; ++v)
        outputs.push_back(pcgHash(v));
    std::sort(outputs.begin(), outputs.end());
    EXPECT_EQ(std::adjacent_find(outputs.begin(), outputs.end()), outputs.end());
}

TEST(PcgHash, FlippingAnInputBitFlipsHalfTheOutput)
{
    // Avalanche: over 2^12 inputs, flipping any one input bit flips each output bit with probability near
    // 1/2. Per (input bit, output bit) the flip rate of 4096 trials has standard deviation 0.008; 0.1 is
    // 12 deviations, far beyond chance yet far inside what a weak mixer shows (a bare LCG flips the low
    // output bits with rate 0 or 1).
    constexpr int trials = 4096;
    for (int inBit = 0; inBit < 32; ++inBit)
    {
        std::array<int, 32> flips{};
        for (std::uint32_t v = 0; v < trials; ++v)
        {
            const std::uint32_t x = pcgHash(v * 0x9E3779B9u); // inputs spread over the whole word
            const std::uint32_t y = pcgHash((v * 0x9E3779B9u) ^ (1u << inBit));
            for (int outBit = 0; outBit < 32; ++outBit)
                flips[outBit] += ((x ^ y) >> outBit) & 1u;
        }
        for (int outBit = 0; outBit < 32; ++outBit)
            EXPECT_NEAR(double(flips[outBit]) / trials, 0.5, 0.1) << "input bit " << inBit << ", output bit " << outBit;
    }
}

TEST(SceneRandom, StaysInItsRanges)
{
    SceneRandom rnd(42);
    std::array<int, 7> hits{};
    for (int i = 0; i < 100'000; ++i)
    {
        const float x = rnd.uniform(-2.0f, 3.0f);
        ASSERT_GE(x, -2.0f);
        ASSERT_LT(x, 3.0f);
        const int k = rnd.integer(2, 8); // both ends included
        ASSERT_GE(k, 2);
        ASSERT_LE(k, 8);
        ++hits[k - 2];
    }
    for (int count : hits)
        EXPECT_GT(count, 0); // every value of [lo, hi] occurs, the upper end included
}

// ---- Statistics -------------------------------------------------------------------------------------------

TEST(RngStatistics, UniformChiSquare)
{
    // Three ways a renderer draws: the first number of a million pixels' streams (across streams), a million
    // numbers of one stream (along a stream), and the first pair of each stream in 32 x 32 cells (what a
    // warp sees). Šidák over the three.
    constexpr int bins = 1000;
    constexpr long n = 1'000'000;
    const std::vector<double> expected1(bins, double(n) / bins), expected2(32 * 32, double(n) / (32 * 32));
    std::vector<double> across(bins, 0.0), along(bins, 0.0), pairs(32 * 32, 0.0);
    Rng stream = Rng::forSample(1, 2, 3);
    for (long i = 0; i < n; ++i)
    {
        Rng pixel = Rng::forSample(5, std::uint32_t(i), 0);
        across[std::size_t(pixel.nextFloat() * bins)] += 1.0;
        const float u1 = pixel.nextFloat();
        const float u2 = pixel.nextFloat();
        pairs[std::size_t(u1 * 32) * 32 + std::size_t(u2 * 32)] += 1.0;
        along[std::size_t(stream.nextFloat() * bins)] += 1.0;
    }
    for (const auto& [name, observed, expected] :
         {std::tuple{"across streams", &across, &expected1}, std::tuple{"along a stream", &along, &expected1},
          std::tuple{"pairs", &pairs, &expected2}})
    {
        const auto r = test::chiSquareTest(*observed, *expected, test::kChiSquareAlpha, 3);
        EXPECT_TRUE(r.passed) << name << ": " << r.message;
    }
}

TEST(RngStatistics, NeighbouringStreamsAreUncorrelated)
{
    // Pearson correlation of the first numbers of neighbouring pixels, of neighbouring sample indices, and of
    // consecutive numbers in one stream, over 1e5 pairs: |r| has standard deviation 1 / sqrt(n) = 0.0032,
    // so 0.0126 is 4 deviations (one in 16,000 by chance, per check).
    constexpr int n = 100'000;
    const auto correlation = [](const std::vector<std::pair<double, double>>& xy) {
        double mx = 0, my = 0;
        for (auto [x, y] : xy)
            mx += x, my += y;
        mx /= double(xy.size()), my /= double(xy.size());
        double sxy = 0, sxx = 0, syy = 0;
        for (auto [x, y] : xy)
            sxy += (x - mx) * (y - my), sxx += (x - mx) * (x - mx), syy += (y - my) * (y - my);
        return sxy / std::sqrt(sxx * syy);
    };
    std::vector<std::pair<double, double>> pixels, samples, lag1;
    Rng stream = Rng::forSample(9, 9, 9);
    for (std::uint32_t i = 0; i < n; ++i)
    {
        pixels.emplace_back(Rng::forSample(0, i, 0).nextFloat(), Rng::forSample(0, i + 1, 0).nextFloat());
        samples.emplace_back(Rng::forSample(0, 17, i).nextFloat(), Rng::forSample(0, 17, i + 1).nextFloat());
        const double a = stream.nextFloat();
        lag1.emplace_back(a, stream.nextFloat());
    }
    EXPECT_LT(std::fabs(correlation(pixels)), 4.0 / std::sqrt(double(n))) << "neighbouring pixels";
    EXPECT_LT(std::fabs(correlation(samples)), 4.0 / std::sqrt(double(n))) << "neighbouring samples";
    EXPECT_LT(std::fabs(correlation(lag1)), 4.0 / std::sqrt(double(n))) << "consecutive numbers";
}
} // namespace
} // namespace rt
