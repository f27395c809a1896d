// The warps of Sampling/Warps.h, tested as style pattern 14 asks: chi-square against the density each one
// claims (research notes §2.1), the pdf integrating to one (§2.2), and the invariants a renderer relies on
// at every corner of the unit square. Warps.h has no inverses, so there is no round-trip test.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "Sampling/Warps.h"
#include "Support/CapDomain.h"
#include "Support/ChiSquare.h"
#include "Support/StatisticsHelpers.h"

namespace rt
{
namespace
{
using test::CapDomain;
using test::chiSquareTest;
using test::kChiSquareAlpha;

constexpr long kSamples = 1'000'000;
constexpr double kPiD = 3.14159265358979323846;

/// The largest float below 1: the largest coordinate Rng::nextFloat returns.
constexpr float kOneMinusUlp = 1.0f - 0x1p-24f;

/// A grid over the closed-open unit square including both ends: the corners are where warps divide by zero.
std::vector<vec2> squareGrid(int n)
{
    std::vector<vec2> points;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j)
        {
            const float x = i == n ? kOneMinusUlp : float(i) / float(n);
            const float y = j == n ? kOneMinusUlp : float(j) / float(n);
            points.emplace_back(x, y);
        }
    return points;
}

/// 1 - cos(angle to +z) of a direction, from its sine so that it stays exact for tiny angles.
double oneMinusCosToZ(const vec3& d)
{
    const dvec3 v(d);
    const double length2 = glm::dot(v, v);
    const double sin2 = (v.x * v.x + v.y * v.y) / length2;
    const double cosTheta = v.z / std::sqrt(length2);
    return cosTheta > 0.0 ? sin2 / (1.0 + cosTheta) : 1.0 - cosTheta;
}

// Unit length to float rounding: a handful of float operations each off by half an ulp (6e-8).
constexpr double kUnitTolerance = 1e-6;

void expectUnitDirection(const vec3& d, const vec2& u)
{
    ASSERT_TRUE(isFinite(d)) << "u = (" << u.x << ", " << u.y << ")";
    EXPECT_NEAR(glm::length(dvec3(d)), 1.0, kUnitTolerance) << "u = (" << u.x << ", " << u.y << ")";
}

// ---- Cosine-weighted hemisphere ---------------------------------------------------------------------------

TEST(CosineHemisphere, ChiSquare)
{
    // The whole sphere, rows aligned with the horizon (50 rows of cos theta in [-1, 1]): the lower half has
    // expectation 0, so a single sample below the horizon fails the test.
    const CapDomain domain({0, 0, 1}, -1.0, 50, 100);
    const auto h = test::histogram(domain.cellCount(), kSamples, 1, [&](Rng& rng) {
        return domain.cell(dvec3(sampleCosineHemisphere(test::uniform2(rng))));
    });
    ASSERT_EQ(h.outside, 0);
    const auto expected = domain.expectedCounts([](const dvec3& d) { return double(cosineHemispherePdf(float(d.z))); },
                                                kSamples);
    const auto r = chiSquareTest(h.counts, expected, kChiSquareAlpha, 1);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(CosineHemisphere, PdfIntegratesToOne)
{
    // The pdf is linear in cos theta on each row, so the midpoint rule is exact up to rounding; 1e-3 leaves
    // room for nothing but a wrong normalisation (cos/2pi gives 0.5, a missing horizon cut gives 0).
    const CapDomain sphere({0, 0, 1}, -1.0, 100, 200);
    EXPECT_NEAR(sphere.integrate([](const dvec3& d) { return double(cosineHemispherePdf(float(d.z))); }, 4), 1.0, 1e-3);
}

TEST(CosineHemisphere, SamplesAreUnitDirectionsAboveTheHorizon)
{
    for (const vec2& u : squareGrid(256))
    {
        const vec3 d = sampleCosineHemisphere(u);
        expectUnitDirection(d, u);
        // Strictly above: a direction the pdf gives 0 would be weighted by 1/0.
        EXPECT_GT(d.z, 0.0f) << "u = (" << u.x << ", " << u.y << ")";
        EXPECT_GT(cosineHemispherePdf(d.z), 0.0f);
    }
}

// ---- Uniform sphere ---------------------------------------------------------------------------------------

TEST(UniformSphere, ChiSquare)
{
    const CapDomain domain({0, 0, 1}, -1.0, 50, 100);
    const auto h = test::histogram(domain.cellCount(), kSamples, 2, [&](Rng& rng) {
        return domain.cell(dvec3(sampleUniformSphere(test::uniform2(rng))));
    });
    ASSERT_EQ(h.outside, 0);
    const auto expected = domain.expectedCounts([](const dvec3&) { return double(uniformSpherePdf()); }, kSamples);
    const auto r = chiSquareTest(h.counts, expected, kChiSquareAlpha, 1);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(UniformSphere, PdfIntegratesToOne)
{
    const CapDomain sphere({0, 0, 1}, -1.0, 20, 40);
    EXPECT_NEAR(sphere.integrate([](const dvec3&) { return double(uniformSpherePdf()); }, 2), 1.0, 1e-3);
}

TEST(UniformSphere, SamplesAreUnitDirections)
{
    for (const vec2& u : squareGrid(256))
        expectUnitDirection(sampleUniformSphere(u), u);
}

// ---- Uniform cone -----------------------------------------------------------------------------------------

// 1 - cos(theta_max): the whole sphere, a hemisphere, wide and narrow cones, and cones so small that
// cos(theta_max) rounds to 1 in float (1e-6 is 16 ulps of 1; research notes §1.2).
const std::vector<float> kConeSizes = {2.0f, 1.0f, 0.3f, 1e-2f, 1e-4f, 1e-6f};

TEST(UniformCone, ChiSquare)
{
    int seed = 10;
    for (float oneMinusCos : kConeSizes)
    {
        SCOPED_TRACE(testing::Message() << "1 - cos(theta_max) = " << oneMinusCos);
        // The cap is the cone itself (in double): a sample outside it beyond rounding is counted as outside.
        const CapDomain domain({0, 0, 1}, 1.0 - double(oneMinusCos), 20, 40);
        const auto h = test::histogram(domain.cellCount(), kSamples, seed++, [&](Rng& rng) {
            return domain.cell(dvec3(sampleUniformCone(test::uniform2(rng), oneMinusCos)));
        });
        EXPECT_EQ(h.outside, 0);
        const auto expected =
            domain.expectedCounts([&](const dvec3&) { return double(uniformConePdf(oneMinusCos)); }, kSamples, 2);
        const auto r = chiSquareTest(h.counts, expected, kChiSquareAlpha, int(kConeSizes.size()));
        EXPECT_TRUE(r.passed) << r.message;
    }
}

TEST(UniformCone, PdfIntegratesToOne)
{
    // The pdf is constant over the cone, so this checks it against the cone's solid angle 2 pi (1 - cos),
    // which the cap computes in double: float rounding of the pdf is 1e-7, far inside 1e-3.
    for (float oneMinusCos : kConeSizes)
    {
        const CapDomain cone({0, 0, 1}, 1.0 - double(oneMinusCos), 10, 20);
        EXPECT_NEAR(cone.integrate([&](const dvec3&) { return double(uniformConePdf(oneMinusCos)); }, 2), 1.0, 1e-3)
            << "1 - cos(theta_max) = " << oneMinusCos;
    }
}

TEST(UniformCone, SamplesAreUnitDirectionsInsideTheCone)
{
    // Down to 1e-20, where sin(theta_max) = 1.4e-10 and cos(theta_max) is exactly 1 in float and in double.
    std::vector<float> sizes = kConeSizes;
    sizes.insert(sizes.end(), {1e-10f, 1e-20f});
    for (float oneMinusCos : sizes)
        for (const vec2& u : squareGrid(128))
        {
            const vec3 d = sampleUniformCone(u, oneMinusCos);
            expectUnitDirection(d, u);
            // Inside up to a relative 1e-5 of the cone's 1 - cos: the rounding of m = u (1 - cos) and sin^2.
            EXPECT_LE(oneMinusCosToZ(d), double(oneMinusCos) * (1.0 + 1e-5))
                << "1 - cos(theta_max) = " << oneMinusCos << ", u = (" << u.x << ", " << u.y << ")";
        }
}

// ---- Uniform triangle -------------------------------------------------------------------------------------

/// Cell of barycentrics (b0, b1) in the triangle cut into n^2 equal-area small triangles: the squares of an
/// n x n grid over (b0, b1) below the hypotenuse, each halved by its anti-diagonal. Index (i n + j) 2 + upper;
/// -1 outside the triangle. Rounding may put a point a few ulps beyond the hypotenuse: it counts as on it.
int triangleCell(double b0, double b1, int n)
{
    if (!(b0 >= 0.0 && b1 >= 0.0 && b0 + b1 <= 1.0 + 1e-7))
        return -1;
    const int i = std::min(int(b0 * n), n - 1);
    int j = std::min(int(b1 * n), n - 1);
    if (i + j > n - 1)
        j = n - 1 - i;
    const bool upper = i + j < n - 1 && (b0 * n - i) + (b1 * n - j) > 1.0;
    return (i * n + j) * 2 + (upper ? 1 : 0);
}

TEST(UniformTriangle, ChiSquare)
{
    constexpr int n = 30; // 900 cells of 1111 expected samples
    const auto h = test::histogram(2 * n * n, kSamples, 3, [&](Rng& rng) {
        const vec2 b = sampleUniformTriangle(test::uniform2(rng));
        return triangleCell(b.x, b.y, n);
    });
    ASSERT_EQ(h.outside, 0);
    // Uniform density: every small triangle expects the same share; the cells beyond the hypotenuse expect 0.
    std::vector<double> expected(2 * n * n, 0.0);
    for (int i = 0; i < n; ++i)
        for (int j = 0; i + j < n; ++j)
        {
            expected[(i * n + j) * 2] = double(kSamples) / (n * n);
            if (i + j < n - 1)
                expected[(i * n + j) * 2 + 1] = double(kSamples) / (n * n);
        }
    const auto r = chiSquareTest(h.counts, expected, kChiSquareAlpha, 1);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(UniformTriangle, SamplesAreBarycentricsOfTheTriangle)
{
    for (const vec2& u : squareGrid(256))
    {
        const vec2 b = sampleUniformTriangle(u);
        ASSERT_TRUE(std::isfinite(b.x) && std::isfinite(b.y));
        EXPECT_GE(b.x, 0.0f);
        EXPECT_GE(b.y, 0.0f);
        // b2 = 1 - b0 - b1 >= 0 up to one rounding of 1 - sqrt(u) (2^-25).
        EXPECT_LE(double(b.x) + double(b.y), 1.0 + 1e-7) << "u = (" << u.x << ", " << u.y << ")";
    }
}

// ---- Concentric disk --------------------------------------------------------------------------------------

TEST(ConcentricDisk, ChiSquare)
{
    // Cells of equal area: r^2 in [0, 1] and theta in [0, 2 pi) cut evenly (area = pi d(r^2) d(theta) / 2pi).
    constexpr int rings = 25, sectors = 40;
    const auto h = test::histogram(rings * sectors, kSamples, 4, [&](Rng& rng) {
        const dvec3 p(sampleUniformDiskConcentric(test::uniform2(rng)), 0.0f);
        const double r2 = p.x * p.x + p.y * p.y;
        if (r2 > 1.0 + 1e-6)
            return -1;
        double theta = std::atan2(p.y, p.x);
        if (theta < 0.0)
            theta += 2.0 * kPiD;
        const int ring = std::min(int(r2 * rings), rings - 1);
        const int sector = std::min(int(theta / (2.0 * kPiD) * sectors), sectors - 1);
        return ring * sectors + sector;
    });
    ASSERT_EQ(h.outside, 0);
    const std::vector<double> expected(rings * sectors, double(kSamples) / (rings * sectors));
    const auto r = chiSquareTest(h.counts, expected, kChiSquareAlpha, 1);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(ConcentricDisk, SamplesLieInTheUnitDisk)
{
    for (const vec2& u : squareGrid(256))
    {
        const vec2 p = sampleUniformDiskConcentric(u);
        ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y)) << "u = (" << u.x << ", " << u.y << ")";
        EXPECT_LE(glm::length(glm::dvec2(p)), 1.0 + kUnitTolerance) << "u = (" << u.x << ", " << u.y << ")";
    }
    // The centre of the square is the centre of the disk (the map's 0/0 case).
    EXPECT_EQ(sampleUniformDiskConcentric(vec2(0.5f)), vec2(0.0f));
}
} // namespace
} // namespace rt
