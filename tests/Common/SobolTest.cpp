// Owen-scrambled Sobol points (Shared/Sobol.h) and the camera-sample streams built on them (Rng::
// forSobolSample): the fast dimension-1 generator equals the direction-number recurrence, and a draw is the
// definition's bit for bit; every power-of-two
// prefix of a draw's points over a pixel's samples is a (0, m, 2)-net (one point in every elementary interval),
// whatever the scramble; the points are uniform over many pixels (chi-square); and distinct draws of a sample
// are uncorrelated.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "Random/Pcg.h"
#include "Shared/Sobol.h"
#include "Support/ChiSquare.h"
#include "Support/StatisticsHelpers.h"

namespace rt
{
namespace
{
/// Sobol dimension 1 straight from its direction numbers (v_0 = 2^31, v_k = v_{k-1} ^ (v_{k-1} >> 1)).
std::uint32_t sobolDimension1Reference(std::uint32_t i)
{
    std::uint32_t result = 0;
    std::uint32_t v = 0x80000000u;
    for (int k = 0; k < 32; ++k, v ^= v >> 1)
        if ((i >> k) & 1u)
            result ^= v;
    return result;
}

TEST(Sobol, DimensionOneMatchesItsDirectionNumbers)
{
    Rng rng(pcgHash(3));
    for (std::uint32_t i = 0; i < 4096; ++i)
        ASSERT_EQ(shader::sobolDimension1(i), sobolDimension1Reference(i)) << "index " << i;
    for (int k = 0; k < 100000; ++k)
    {
        const std::uint32_t i = rng.nextUint();
        ASSERT_EQ(shader::sobolDimension1(i), sobolDimension1Reference(i)) << "index " << i;
    }
    // The first points: 0, 1/2, 3/4, 1/4 (Joe & Kuo's dimension 2).
    EXPECT_EQ(shader::sobolDimension1(1), 0x80000000u);
    EXPECT_EQ(shader::sobolDimension1(2), 0xC0000000u);
    EXPECT_EQ(shader::sobolDimension1(3), 0x40000000u);
}

TEST(Sobol, BitfieldReverseReversesBits)
{
    EXPECT_EQ(shader::bitfieldReverse(1u), 0x80000000u);
    EXPECT_EQ(shader::bitfieldReverse(0x80000000u), 1u);
    EXPECT_EQ(shader::bitfieldReverse(0x0000F00Du), 0xB00F0000u);
    EXPECT_EQ(shader::bitfieldReverse(0xFFFFFFFFu), 0xFFFFFFFFu);
}

TEST(Sobol, DrawIsBurleysScrambleOfSobolsFirstTwoDimensions)
{
    // owenScrambledSobol2D leaves out reversals that cancel: its points must be, bit for bit, those of the
    // definition (Burley 2020, listing 2): the shuffled index's Sobol dimensions 0 (the reversed index) and 1,
    // each through nestedUniformScramble.
    Rng seeds(pcgHash(17));
    for (std::uint32_t k = 0; k < 20000; ++k)
    {
        const std::uint32_t index = k < 10000 ? k : seeds.nextUint();
        const std::uint32_t shuffle = seeds.nextUint();
        const std::uint32_t xSeed = seeds.nextUint();
        const std::uint32_t ySeed = seeds.nextUint();
        const std::uint32_t i = shader::nestedUniformScramble(index, shuffle);
        const vec2 expected(
            shader::fixedPointToUnitFloat(shader::nestedUniformScramble(shader::bitfieldReverse(i), xSeed)),
            shader::fixedPointToUnitFloat(shader::nestedUniformScramble(sobolDimension1Reference(i), ySeed)));
        const vec2 point = shader::owenScrambledSobol2D(index, shuffle, xSeed, ySeed);
        ASSERT_EQ(point.x, expected.x) << "index " << index;
        ASSERT_EQ(point.y, expected.y) << "index " << index;
    }
}

/// True when the points hold exactly one point in each 2^-a x 2^-(m-a) elementary interval, every a.
bool isZeroMTwoNet(const std::vector<vec2>& points, int m)
{
    for (int a = 0; a <= m; ++a)
    {
        const int nx = 1 << a;
        const int ny = 1 << (m - a);
        std::vector<int> count(std::size_t(nx * ny), 0);
        for (const vec2& p : points)
        {
            const int x = std::min(int(p.x * float(nx)), nx - 1);
            const int y = std::min(int(p.y * float(ny)), ny - 1);
            if (++count[std::size_t(y * nx + x)] > 1)
                return false;
        }
    }
    return true;
}

TEST(Sobol, EveryPowerOfTwoPrefixOfADrawIsANet)
{
    // Draw d of samples 0 .. 2^m - 1 of one pixel, for several pixels, seeds and draws; m up to 12 (24-bit
    // floats keep 12 + 12 bits of every interval exact).
    for (std::uint32_t pixel : {0u, 17u, 40000u})
        for (std::uint32_t seed : {0u, 7u})
            for (int draw = 0; draw < 6; ++draw)
                for (int m : {1, 4, 8, 12})
                {
                    std::vector<vec2> points;
                    for (std::uint32_t s = 0; s < (1u << m); ++s)
                    {
                        Rng rng = Rng::forSobolSample(seed, pixel, s);
                        vec2 p(0.0f);
                        for (int d = 0; d <= draw; ++d)
                            p = rng.next2D();
                        points.push_back(p);
                    }
                    EXPECT_TRUE(isZeroMTwoNet(points, m))
                        << "pixel " << pixel << ", seed " << seed << ", draw " << draw << ", 2^" << m << " samples";
                }
}

TEST(Sobol, PointsAreUniformOverPixels)
{
    // One sample index, many pixels: the scrambles make each pixel's point an independent uniform one.
    constexpr int kCells = 16 * 16;
    constexpr long kPixels = 400'000;
    std::vector<double> counts(kCells, 0.0);
    for (long pixel = 0; pixel < kPixels; ++pixel)
    {
        Rng rng = Rng::forSobolSample(11, std::uint32_t(pixel), 5);
        rng.next2D();
        const vec2 p = rng.next2D();
        counts[std::size_t(int(p.y * 16.0f) * 16 + int(p.x * 16.0f))] += 1.0;
    }
    const std::vector<double> expected(kCells, double(kPixels) / kCells);
    const auto r = test::chiSquareTest(counts, expected, test::kChiSquareAlpha);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(Sobol, DrawsOfASampleAreUncorrelated)
{
    // Draws 0 and 1 (a camera sample's pixel jitter and its lens or first light point) over 4096 samples of
    // one pixel: their coordinates' correlation is that of independent points, |r| < 4 / sqrt(n).
    constexpr int n = 4096;
    double sxy = 0.0;
    double sx = 0.0;
    double sy = 0.0;
    double sxx = 0.0;
    double syy = 0.0;
    for (std::uint32_t s = 0; s < n; ++s)
    {
        Rng rng = Rng::forSobolSample(1, 1234, s);
        const float x = rng.next2D().x;
        const float y = rng.next2D().x;
        sx += x;
        sy += y;
        sxy += double(x) * y;
        sxx += double(x) * x;
        syy += double(y) * y;
    }
    const double cov = sxy / n - (sx / n) * (sy / n);
    const double r = cov / std::sqrt((sxx / n - (sx / n) * (sx / n)) * (syy / n - (sy / n) * (sy / n)));
    EXPECT_LT(std::abs(r), 4.0 / std::sqrt(double(n)));
}
} // namespace
} // namespace rt
