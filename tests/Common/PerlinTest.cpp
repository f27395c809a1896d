// Scene/Perlin.h: the noise both engines read from one set of tables (RTTNW §5). Gradient noise has
// properties that follow from its construction alone: it is 0 at every lattice point, bounded by
// sqrt(3)/2 < 1 with unit gradients, continuous, and a pure function of the tables and the point.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <vector>

#include "Random/Pcg.h"
#include "Scene/Perlin.h"

namespace rt
{
namespace
{
std::vector<vec3> randomPoints(int count, float extent, std::uint32_t seed)
{
    Rng rng(pcgHash(seed));
    std::vector<vec3> points;
    for (int i = 0; i < count; ++i)
    {
        const float x = rng.nextFloat(), y = rng.nextFloat(), z = rng.nextFloat();
        points.push_back(extent * (2.0f * vec3(x, y, z) - vec3(1.0f)));
    }
    return points;
}

TEST(Perlin, TablesArePermutationsAndUnitGradients)
{
    const shader::PerlinData& t = perlinTables();
    for (const shader::uint* perm : {t.permX, t.permY, t.permZ})
    {
        std::vector<shader::uint> sorted(perm, perm + shader::kPerlinPointCount);
        std::sort(sorted.begin(), sorted.end());
        std::vector<shader::uint> identity(shader::kPerlinPointCount);
        std::iota(identity.begin(), identity.end(), 0u);
        EXPECT_EQ(sorted, identity);
        EXPECT_FALSE(std::equal(perm, perm + shader::kPerlinPointCount, identity.begin())) << "not shuffled";
    }
    for (const vec3& g : t.gradients)
        EXPECT_NEAR(glm::length(g), 1.0f, 1e-6f);
}

TEST(Perlin, NoiseIsAPureFunctionOfTablesAndPoint)
{
    // A copy of the tables (what the GPU receives) gives bit-identical noise, and so does a second call.
    const auto copy = std::make_unique<shader::PerlinData>(perlinTables());
    for (const vec3& p : randomPoints(1000, 50.0f, 1))
    {
        const float a = perlinNoise(perlinTables(), p);
        EXPECT_EQ(a, perlinNoise(*copy, p));
        EXPECT_EQ(a, perlinNoise(perlinTables(), p));
        EXPECT_EQ(perlinTurbulence(perlinTables(), p, 7), perlinTurbulence(*copy, p, 7));
    }
}

TEST(Perlin, NoiseVanishesAtLatticePoints)
{
    // At an integer point every corner term dot(g, p - corner) has p - corner = 0 or a weight of 0.
    for (int x = -3; x <= 3; ++x)
        for (int y = -3; y <= 3; ++y)
            for (int z = -3; z <= 3; ++z)
                EXPECT_NEAR(perlinNoise(perlinTables(), vec3(37.0f * float(x), 11.0f * float(y), 5.0f * float(z))), 0.0f, 1e-6f);
}

TEST(Perlin, NoiseIsBoundedContinuousAndVaries)
{
    // Bounded by sqrt(3)/2 (the farthest a corner can be, weighted); continuous: the noise's gradient is at
    // most a few units (sum of 8 unit gradients with smooth weights), so a step of 1e-3 moves it by < 1e-2.
    double sum = 0.0, sum2 = 0.0;
    const auto points = randomPoints(100'000, 100.0f, 2);
    for (const vec3& p : points)
    {
        const float n = perlinNoise(perlinTables(), p);
        ASSERT_TRUE(std::isfinite(n));
        ASSERT_LE(std::fabs(n), 0.8661f) << "at (" << p.x << ", " << p.y << ", " << p.z << ")";
        EXPECT_LT(std::fabs(perlinNoise(perlinTables(), p + vec3(1e-3f, -1e-3f, 1e-3f)) - n), 1e-2f);
        sum += n;
        sum2 += double(n) * n;
    }
    const double mean = sum / double(points.size());
    const double sd = std::sqrt(sum2 / double(points.size()) - mean * mean);
    EXPECT_NEAR(mean, 0.0, 0.02) << "gradient noise averages to 0";
    EXPECT_GT(sd, 0.1) << "noise that hardly varies";
}

TEST(Perlin, TurbulenceIsNonNegativeAndBounded)
{
    // |sum of 7 octaves with weights 1, 1/2, ...| <= (sqrt(3)/2) (2 - 2^-6).
    for (const vec3& p : randomPoints(20'000, 30.0f, 3))
    {
        const float t = perlinTurbulence(perlinTables(), p, 7);
        ASSERT_GE(t, 0.0f);
        ASSERT_LE(t, 0.8661f * 2.0f);
    }
    EXPECT_EQ(perlinTurbulence(perlinTables(), vec3(0.3f), 0), 0.0f) << "zero octaves sum to nothing";
}
} // namespace
} // namespace rt
