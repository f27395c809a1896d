// NEE's triangle samplers (Shared/SphericalTriangle.h through LightSampling.h): Arvo's map (SolidAngle) and
// the bilinear cosine warp composed with it (Projected). The solid angle against L'Huilier's theorem in long
// double; the directions against the density (chi-square, research notes §2.1: SolidAngle's from the
// reference solid angle alone, Projected's as lightPdf reports it); each sample's pdf against lightPdf of its
// direction and the point on the light (§2.3); E[1/pdf] = the solid angle (§2.2); the inverse map against the
// forward one (§2.5); finite samples with positive pdfs for slivers, degenerate and near-hemisphere
// triangles. Direct lighting through them (area, solid angle, projected and Lambert's formula agreeing) is in
// LightIrradianceTest.cpp.
#include "Render/RenderSettings.h"
#include "Support/ChiSquare.h"
#include "Support/LightGeometry.h"
#include "Support/StatisticsHelpers.h"

#include <cmath>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace rt
{
namespace
{
constexpr long kChiSquareSamples = 1'000'000;

struct TriangleCase
{
    std::string name;
    LightData light;
    vec3 p; // shading point
};

/// Triangles the spherical sampler takes (3e-4 to 6.22 sr): a general one (pbrt-v4's sampling test), the near
/// field and a large triangle just below the point (both beyond 5.8 sr: nearly the hemisphere), grazing
/// (every direction within 1 degree of the light's plane), tiny (3.6e-4 sr), distant (1e-3 sr from 400
/// units), and the sliver seen from 4 units and from across the room.
std::vector<TriangleCase> triangleCases()
{
    return {
        {"general", test::makeTriangleLight({4, 1, 1}, {-10, 3, 3}, {-2, -8, 10}), {0.5f, -0.4f, 0.7f}},
        {"near field", test::makeTriangleLight({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), {0.25f, 0.25f, 0.01f}},
        {"near hemisphere", test::makeTriangleLight({-20, -12, 0.5f}, {20, -12, 0.5f}, {0, 25, 0.5f}),
         vec3(0.0f)},
        {"grazing", test::makeTriangleLight({2, -1, 0.03f}, {3, 1, 0.03f}, {2, 1, 0.03f}), vec3(0.0f)},
        {"tiny", test::makeTriangleLight({0.3f, 0.2f, 1.0f}, {0.33f, 0.2f, 1.01f}, {0.31f, 0.23f, 0.99f}),
         vec3(0.0f)},
        {"distant", test::makeTriangleLight({-10, 0, 400}, {10, 0, 400}, {0, 16, 400}), vec3(0.0f)},
        {"sliver, near", test::sliverTriangle(), {280, 104, 550}},
        {"sliver, across the room", test::sliverTriangle(), {278, 300, 254}},
    };
}

/// Solid angle of the triangle seen from p by L'Huilier's theorem, tan(E/4)^2 = tan(s/2) tan((s - a)/2)
/// tan((s - b)/2) tan((s - c)/2) over the sides a, b, c (arcs, from atan2) and s their half sum: a formula
/// independent of Van Oosterom & Strackee's, in long double.
double lhuilierSolidAngle(const LightData& l, const vec3& p)
{
    using V = glm::tvec3<long double>;
    const V o(p.x, p.y, p.z);
    const V v0 = V(l.p0.x, l.p0.y, l.p0.z) - o;
    const V v1 = v0 + V(l.p1.x, l.p1.y, l.p1.z);
    const V v2 = v0 + V(l.p2.x, l.p2.y, l.p2.z);
    const auto arc = [](const V& x, const V& y)
    { return std::atan2(glm::length(glm::cross(x, y)), glm::dot(x, y)); };
    const long double a = arc(v1, v2), b = arc(v0, v2), c = arc(v0, v1);
    const long double s = 0.5L * (a + b + c);
    const long double product =
        std::tan(0.5L * s) * std::tan(0.5L * (s - a)) * std::tan(0.5L * (s - b)) * std::tan(0.5L * (s - c));
    return double(4.0L * std::atan(std::sqrt(std::max(product, 0.0L))));
}

/// A receiver normal tilted away from the triangle's centroid, so that the cosine varies across it.
vec3 tiltedNormal(const TriangleCase& c)
{
    const vec3 centroid = c.light.p0 + (c.light.p1 + c.light.p2) / 3.0f - c.p;
    return glm::normalize(glm::normalize(centroid) + vec3(0.5f, -0.3f, 0.2f));
}

shader::SphericalTriangle sphericalTriangleOf(const TriangleCase& c)
{
    return shader::makeSphericalTriangle(c.p, c.light.p0, c.light.p1, c.light.p2);
}

TEST(SphericalTriangle, SolidAngleMatchesLhuilier)
{
    // Every case lies within the sampler's bounds (else it would test area sampling), and Van Oosterom &
    // Strackee in double agree with L'Huilier in long double to double rounding.
    for (const TriangleCase& c : triangleCases())
    {
        const double expected = lhuilierSolidAngle(c.light, c.p);
        EXPECT_GE(expected, double(shader::kMinSphericalTriangle)) << c.name;
        EXPECT_LE(expected, double(shader::kMaxSphericalTriangle)) << c.name;
        EXPECT_NEAR(sphericalTriangleOf(c).solidAngle, expected, 1e-12 * expected) << c.name;
    }
}

TEST(SphericalTriangle, InverseRecoversU)
{
    // Forward and inverse in the header's own precision (double here) over a grid of u, down to 1/64 from
    // the corners: the inverse is what Projected's pdf evaluates the warp with.
    for (const TriangleCase& c : triangleCases())
    {
        SCOPED_TRACE(c.name);
        const auto tri = sphericalTriangleOf(c);
        for (int i = 0; i < 32; ++i)
            for (int j = 0; j < 32; ++j)
            {
                const vec2 u((float(i) + 0.5f) / 32.0f, (float(j) + 0.5f) / 32.0f);
                const glm::dvec3 w = shader::sphericalTriangleDirection(tri, u);
                ASSERT_NEAR(glm::length(w), 1.0, 1e-12);
                const vec2 back = shader::invertSphericalTriangle(tri, w);
                ASSERT_NEAR(back.x, u.x, 1e-6) << "u = " << u.x << ", " << u.y;
                ASSERT_NEAR(back.y, u.y, 1e-6) << "u = " << u.x << ", " << u.y;
            }
    }
}

TEST(SphericalTriangle, MapReachesTheVerticesAtTheCorners)
{
    // u.y = 0 is B, (0, 1) is A, (1, 1) is C: the corners the cosine warp's weights are assigned to.
    for (const TriangleCase& c : triangleCases())
    {
        const auto tri = sphericalTriangleOf(c);
        for (const auto& [u, vertex] :
             {std::pair{vec2(0.0f, 0.0f), tri.b}, std::pair{vec2(1.0f, 0.0f), tri.b},
              std::pair{vec2(0.0f, 1.0f), tri.a}, std::pair{vec2(1.0f, 1.0f), tri.c}})
            EXPECT_LT(glm::distance(shader::sphericalTriangleDirection(tri, u), vertex), 1e-9)
                << c.name << ", u = " << u.x << ", " << u.y;
    }
}

TEST(SphericalTriangle, ChiSquareUniformOverTheSolidAngle)
{
    // Expected counts from 1 / (the reference solid angle) alone: nothing of the sampler's own algebra.
    const auto cases = triangleCases();
    std::uint32_t seed = 2000;
    for (const TriangleCase& c : cases)
    {
        SCOPED_TRACE(c.name);
        const test::LightSurfaceDomain domain(c.light, c.p, 32);
        const auto h = domain.sampleHistogram(LightSampler::SolidAngle, vec3(0.0f), kChiSquareSamples, seed++);
        EXPECT_EQ(h.outside, 0) << "samples missing the light, or no sample";
        const double solidAngle = lhuilierSolidAngle(c.light, c.p);
        // The area density cos / (r^2 Omega) peaks under the point for the near-hemisphere cases: 16 x 16
        // quadrature points per cell resolve it.
        const auto expected =
            domain.expectedCounts(kChiSquareSamples, 16, [&](const dvec3&) { return 1.0 / solidAngle; });
        const auto r = test::chiSquareTest(h.counts, expected, test::kChiSquareAlpha, int(cases.size()));
        EXPECT_TRUE(r.passed) << r.message;
    }
}

TEST(ProjectedTriangle, ChiSquareFollowsTheWarpedDensityItReports)
{
    const auto cases = triangleCases();
    std::uint32_t seed = 2100;
    for (const TriangleCase& c : cases)
    {
        SCOPED_TRACE(c.name);
        const vec3 n = tiltedNormal(c);
        const test::LightSurfaceDomain domain(c.light, c.p, 32);
        const auto h = domain.sampleHistogram(LightSampler::Projected, n, kChiSquareSamples, seed++);
        EXPECT_EQ(h.outside, 0) << "samples missing the light, or no sample";
        const auto expected = domain.expectedCounts(kChiSquareSamples, 16, LightSampler::Projected, n);
        const auto r = test::chiSquareTest(h.counts, expected, test::kChiSquareAlpha, int(cases.size()));
        EXPECT_TRUE(r.passed) << r.message;
    }
}

/// Every sample of `strategy` from c.p (receiver normal n): accepted, on the light along its direction, with
/// a finite positive pdf that lightPdf finds again for its direction to 1e-4. Returns the mean of 1 / pdf and
/// its standard error.
test::MeanEstimate checkEverySample(const TriangleCase& c, LightSampler strategy, const vec3& n,
                                    std::uint32_t seed)
{
    Rng rng(pcgHash(seed));
    constexpr long kSamples = 20'000;
    return test::estimateMean(
        kSamples,
        [&](long)
        {
            LightSample s;
            const vec2 u = test::uniform2(rng);
            EXPECT_TRUE(sampleLight(c.light, strategy, c.p, n, u, s)) << "u = " << u.x << ", " << u.y;
            EXPECT_TRUE(std::isfinite(s.pdf) && s.pdf > 0.0f) << s.pdf;
            const float pdf = lightPdf(c.light, strategy, c.p, n, s.wi);
            EXPECT_NEAR(pdf, s.pdf, 1e-4f * s.pdf) << "u = " << u.x << ", " << u.y;
            // The point lies on the triangle (barycentrics uv), along wi at the distance given.
            EXPECT_TRUE(s.uv.x >= 0.0f && s.uv.y >= 0.0f && s.uv.x + s.uv.y <= 1.0f + 1e-6f)
                << s.uv.x << ", " << s.uv.y;
            const dvec3 y(s.point);
            const dvec3 onLight =
                dvec3(c.light.p0) + double(s.uv.x) * dvec3(c.light.p1) + double(s.uv.y) * dvec3(c.light.p2);
            EXPECT_LE(glm::distance(onLight, y), 1e-6 * (1.0 + glm::length(y)));
            EXPECT_LE(glm::distance(dvec3(c.p) + double(s.distance) * dvec3(s.wi), y),
                      1e-6 * (1.0 + glm::length(y)));
            return 1.0 / double(s.pdf);
        });
}

TEST(SphericalTriangle, EverySamplePdfIsOneOverTheSolidAngle)
{
    // SolidAngle's 1 / pdf is the solid angle itself for every sample: E[1/pdf] = Omega with no spread
    // (§2.2).
    std::uint32_t seed = 2200;
    for (const TriangleCase& c : triangleCases())
    {
        SCOPED_TRACE(c.name);
        const test::MeanEstimate e = checkEverySample(c, LightSampler::SolidAngle, vec3(0.0f), seed++);
        const double solidAngle = lhuilierSolidAngle(c.light, c.p);
        EXPECT_NEAR(e.mean, solidAngle, 1e-6 * solidAngle);
        EXPECT_LE(e.standardError, 1e-6 * solidAngle);
    }
}

TEST(ProjectedTriangle, SamplePdfMatchesLightPdfAndIntegratesToOne)
{
    std::uint32_t seed = 2300;
    for (const TriangleCase& c : triangleCases())
    {
        SCOPED_TRACE(c.name);
        const test::MeanEstimate e = checkEverySample(c, LightSampler::Projected, tiltedNormal(c), seed++);
        // E[1 / pdf] over the samples = the solid angle the density lives on (§2.2), to 4 standard errors.
        const double solidAngle = lhuilierSolidAngle(c.light, c.p);
        EXPECT_NEAR(e.mean, solidAngle, 4.0 * e.standardError + 1e-6 * solidAngle);
    }
}

TEST(ProjectedTriangle, WithoutAReceiverItIsSolidAngleSampling)
{
    // In a medium (n = 0) there is no cosine to follow.
    const TriangleCase c = triangleCases()[0];
    Rng rng(pcgHash(2400));
    for (int i = 0; i < 1000; ++i)
    {
        const vec2 u = test::uniform2(rng);
        LightSample a, b;
        ASSERT_TRUE(sampleLight(c.light, LightSampler::Projected, c.p, vec3(0.0f), u, a));
        ASSERT_TRUE(sampleLight(c.light, LightSampler::SolidAngle, c.p, vec3(0.0f), u, b));
        EXPECT_EQ(a.pdf, b.pdf);
        EXPECT_EQ(a.point, b.point);
    }
}

TEST(SphericalTriangle, OutsideItsBoundsTrianglesAreSampledByArea)
{
    // Below 3e-4 sr (a 0.02-unit triangle at distance 1: 1.9e-4 sr) and above 6.22 sr (a large triangle 0.1
    // below the point: 6.24 sr) the densities are area sampling's.
    const TriangleCase small{
        "small", test::makeTriangleLight({0.3f, 0.2f, 1.0f}, {0.32f, 0.2f, 1.0f}, {0.31f, 0.22f, 1.0f}),
        vec3(0.0f)};
    const TriangleCase huge{"huge", test::makeTriangleLight({-20, -12, 0.1f}, {20, -12, 0.1f}, {0, 25, 0.1f}),
                            vec3(0.0f)};
    EXPECT_LT(lhuilierSolidAngle(small.light, small.p), double(shader::kMinSphericalTriangle));
    EXPECT_GT(lhuilierSolidAngle(huge.light, huge.p), double(shader::kMaxSphericalTriangle));
    for (const TriangleCase& c : {small, huge})
    {
        Rng rng(pcgHash(2500));
        for (int i = 0; i < 1000; ++i)
        {
            const vec2 u = test::uniform2(rng);
            for (const LightSampler strategy : {LightSampler::SolidAngle, LightSampler::Projected})
            {
                LightSample a, b;
                ASSERT_EQ(sampleLight(c.light, strategy, c.p, vec3(0, 0, 1), u, a),
                          sampleLight(c.light, LightSampler::Area, c.p, vec3(0, 0, 1), u, b))
                    << c.name;
                EXPECT_EQ(a.pdf, b.pdf) << c.name;
                EXPECT_EQ(a.point, b.point) << c.name;
                EXPECT_EQ(lightPdf(c.light, strategy, c.p, vec3(0, 0, 1), b.wi),
                          lightPdf(c.light, LightSampler::Area, c.p, vec3(0, 0, 1), b.wi))
                    << c.name;
            }
        }
    }
}

// ---- Robustness
// ---------------------------------------------------------------------------------------------

struct StressCase
{
    std::string name;
    LightData light;
    vec3 p;
    bool degenerate; // no solid angle to sample: samples may be declined, never returned broken
};

std::vector<StressCase> stressCases()
{
    // A 300 x 3 sliver (triangle-lights' back-wall light) from near, far, edge-on and from its own plane;
    // collinear vertices, a zero edge, the point at a vertex; triangles filling the hemisphere on either
    // side of the 6.22 sr bound and around the point at a distance of 1e-3; a unit triangle 1e5 from the
    // origin.
    const LightData thin = test::makeTriangleLight({428, 400, 554}, {128, 400, 554}, {278, 403, 554});
    const LightData big = test::makeTriangleLight({-20, -12, 0}, {20, -12, 0}, {0, 25, 0});
    const vec3 far(1e5f, -3e4f, 2e5f);
    return {
        {"sliver from the floor", thin, {278, 1, 278}, false},
        {"sliver from 2 units", thin, {300, 401.5f, 552}, false},
        {"sliver from across the room", thin, {10, 10, 10}, false},
        {"sliver edge-on", thin, {600, 401, 553.9f}, false},
        {"sliver along its long edge", thin, {500, 400, 553.999f}, false},
        {"sliver from its plane", thin, {278, 300, 554}, true},
        {"collinear", test::makeTriangleLight({0, 0, 1}, {1, 1, 1}, {2, 2, 1}), vec3(0.0f), true},
        {"zero edge", test::makeTriangleLight({0, 0, 1}, {0, 0, 1}, {1, 0, 1}), vec3(0.0f), true},
        {"point at a vertex", big, {-20, -12, 0}, true},
        {"hemisphere, 6.07 sr", big, {0, 0, -0.5f}, false},
        {"hemisphere, 6.21 sr", big, {0, 0, -0.14f}, false},
        {"hemisphere, 6.24 sr", big, {0, 0, 0.1f}, false},
        {"hemisphere, 1e-3 away", big, {0, 0, 1e-3f}, false},
        {"far from the origin", test::makeTriangleLight(far, far + vec3(1, 0, 0), far + vec3(0, 1, 0.5f)),
         far + vec3(0.2f, 0.3f, 3.0f), false},
    };
}

TEST(SphericalTriangle, EveryReturnedSampleIsFiniteWithAPositivePdf)
{
    std::uint32_t seed = 2600;
    for (const StressCase& c : stressCases())
    {
        SCOPED_TRACE(c.name);
        const vec3 n =
            glm::normalize(c.light.p0 + (c.light.p1 + c.light.p2) / 3.0f - c.p + vec3(0.1f, 0.2f, 0.0f));
        for (const LightSampler strategy :
             {LightSampler::Area, LightSampler::SolidAngle, LightSampler::Projected})
        {
            Rng rng(pcgHash(seed++));
            long declined = 0, disagreeing = 0;
            constexpr long kSamples = 4096;
            for (long i = 0; i < kSamples; ++i)
            {
                LightSample s;
                if (!sampleLight(c.light, strategy, c.p, n, test::uniform2(rng), s))
                {
                    ++declined;
                    continue;
                }
                ASSERT_TRUE(std::isfinite(s.pdf) && s.pdf > 0.0f) << toString(strategy) << ": pdf " << s.pdf;
                ASSERT_TRUE(isFinite(s.wi) && isFinite(s.point) && isFinite(s.normal)) << toString(strategy);
                ASSERT_TRUE(std::isfinite(s.uv.x) && std::isfinite(s.uv.y)) << toString(strategy);
                ASSERT_TRUE(std::isfinite(s.distance) && s.distance > 0.0f) << toString(strategy);
                ASSERT_NEAR(glm::length(s.wi), 1.0f, 1e-6f) << toString(strategy);
                const float pdf = lightPdf(c.light, strategy, c.p, n, s.wi);
                ASSERT_TRUE(std::isfinite(pdf)) << toString(strategy);
                disagreeing += std::fabs(pdf - s.pdf) > 1e-4f * s.pdf ? 1 : 0;
            }
            if (c.degenerate)
                continue;
            // Area sampling declines the far side of nothing here, but a point whose direction rounding puts
            // off the light, as its pdf does; the spherical samplers must keep every sample and agree.
            if (strategy != LightSampler::Area)
            {
                EXPECT_EQ(declined, 0) << toString(strategy);
            }
            EXPECT_EQ(disagreeing, 0) << toString(strategy);
        }
    }
}

TEST(SphericalTriangle, RandomTrianglesGiveConsistentSamples)
{
    // pbrt-v4's configuration (§2.2): vertices uniform in [-10, 10]^3, the point pushed out of that box.
    Rng rng(pcgHash(2700));
    int spherical = 0;
    for (int k = 0; k < 300; ++k)
    {
        const auto point = [&]
        {
            return vec3(20.0f * rng.nextFloat() - 10.0f, 20.0f * rng.nextFloat() - 10.0f,
                        20.0f * rng.nextFloat() - 10.0f);
        };
        const vec3 a = point(), b = point(), c = point();
        vec3 p = point();
        p[int(rng.nextUint() % 3u)] = rng.nextFloat() < 0.5f ? -13.0f : 13.0f;
        const LightData light = test::makeTriangleLight(a, b, c);
        const double solidAngle = lhuilierSolidAngle(light, p);
        const bool inBounds = solidAngle >= double(shader::kMinSphericalTriangle);
        spherical += inBounds ? 1 : 0;
        const vec3 n = glm::normalize(a + b + c - 3.0f * p);
        for (int i = 0; i < 64; ++i)
        {
            const vec2 u = test::uniform2(rng);
            for (const LightSampler strategy : {LightSampler::SolidAngle, LightSampler::Projected})
            {
                LightSample s;
                const bool ok = sampleLight(light, strategy, p, n, u, s);
                if (inBounds)
                {
                    ASSERT_TRUE(ok) << "triangle " << k;
                }
                if (!ok)
                    continue;
                ASSERT_TRUE(std::isfinite(s.pdf) && s.pdf > 0.0f) << "triangle " << k;
                ASSERT_NEAR(lightPdf(light, strategy, p, n, s.wi), s.pdf, 1e-4f * s.pdf) << "triangle " << k;
                if (inBounds && strategy == LightSampler::SolidAngle)
                {
                    ASSERT_NEAR(1.0 / double(s.pdf), solidAngle, 1e-6 * solidAngle) << "triangle " << k;
                }
            }
        }
    }
    EXPECT_GT(spherical, 250);
}
} // namespace
} // namespace rt
