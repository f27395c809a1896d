// Exact projected-solid-angle sampling of quads and triangles (Shared/Lights/ProjectedPolygon.h, after Peters
// 2021), over lights overhead (the zenith inside the polygon) and to the side, near and far, slivers (1000:1),
// small ones just above the sampler's threshold, and lights the receiver's horizon cuts:
//   - its projected solid angle P against a float64 quadrature over the light's surface of cos_r cos_l / d^2
//     (independent of the sampler's sweeps), 1e-4;
//   - zero variance for a Lambertian receiver: every sample's cos / pdf is P (1e-3, research notes §1.6);
//   - chi-square of its points on the light against the density cos_r / P of the quadrature (not lightPdf);
//   - lightPdf equal to each sample's pdf; no receiver: solid-angle sampling; tiny: area sampling.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "Sampling/LightSampling.h"
#include "Support/ChiSquare.h"
#include "Support/LightGeometry.h"
#include "Support/StatisticsHelpers.h"

namespace rt
{
namespace
{
struct PolygonCase
{
    std::string name;
    LightData light;
    vec3 p;
    vec3 n;
};

std::vector<PolygonCase> polygonCases()
{
    const vec3 up(0.0f, 0.0f, 1.0f);
    const vec3 tilted = glm::normalize(vec3(0.3f, -0.2f, 1.0f));
    const vec3 acrossTheHorizon = glm::normalize(vec3(0.2f, 1.0f, 0.1f));
    return {
        {"quad overhead, zenith inside", test::makeQuadLight({-1, -1, 1}, {2, 0, 0}, {0, 2, 0}), vec3(0.0f), up},
        {"quad to the side, near", test::makeQuadLight({0.5f, -0.5f, 0.2f}, {1.5f, 0, 0}, {0, 1, 0.5f}), vec3(0.0f),
         tilted},
        {"quad far (0.02 sr)", test::makeQuadLight({3, -0.5f, 5}, {1, 0, 0}, {0, 1, 0}), vec3(0.0f), tilted},
        {"quad grazing, horizon across it", test::makeQuadLight({1, -1, 0.05f}, {2, 0, 0}, {0, 2, 0}), vec3(0.0f),
         acrossTheHorizon},
        {"quad upright on the floor (rect-light-closeup)", test::makeQuadLight({200, 5, 0}, {-400, 0, 0}, {0, 200, 0}),
         {30.0f, 0.0f, -40.0f}, vec3(0.0f, 1.0f, 0.0f)},
        {"triangle overhead", test::makeTriangleLight({-1, -1, 1}, {2, -1, 1}, {0, 2, 1}), vec3(0.0f), up},
        {"triangle to the side", test::makeTriangleLight({0.5f, 0, 0.3f}, {2, 0.5f, 0.2f}, {1, 1.5f, 1}), vec3(0.0f),
         tilted},
        {"triangle grazing, horizon across it", test::makeTriangleLight({2, -1, 0.03f}, {3, 1, 0.03f}, {2, 1, 0.03f}),
         vec3(0.0f), acrossTheHorizon},
        {"sliver 1000:1", test::makeTriangleLight({-1, 0.5f, 1}, {1, 0.5f, 1}, {0, 0.502f, 1}), vec3(0.0f), up},
        {"small (2e-4 sr)", test::makeQuadLight({2, 0, 3}, {0.05f, 0, 0}, {0, 0.05f, 0}), vec3(0.0f), tilted},
    };
}

/// P by the midpoint rule over the light's surface (n x n cells; triangles through the square (s, t) ->
/// (s, t (1 - s))): the integral of max(cos_r, 0) |cos_l| / d^2 dA, in double.
double projectedSolidAngle(const LightData& l, const vec3& p, const vec3& n, int cells = 1500)
{
    const dvec3 e1(l.p1), e2(l.p2), dn = glm::normalize(dvec3(n));
    const dvec3 cross = glm::cross(e1, e2);
    const double area2 = glm::length(cross);
    const dvec3 ln = cross / area2;
    const bool triangle = l.shape == LightShape::Triangle;
    double sum = 0.0;
    for (int i = 0; i < cells; ++i)
        for (int j = 0; j < cells; ++j)
        {
            const double s = (i + 0.5) / cells, t = (j + 0.5) / cells;
            const double b = triangle ? t * (1.0 - s) : t;
            const dvec3 w = dvec3(l.p0) + s * e1 + b * e2 - dvec3(p);
            const double d2 = glm::dot(w, w), d = std::sqrt(d2);
            const double cosR = glm::dot(dn, w) / d;
            if (cosR > 0.0)
                sum += cosR * std::fabs(glm::dot(ln, w)) / (d2 * d) * area2 * (triangle ? 1.0 - s : 1.0);
        }
    return sum / (double(cells) * cells);
}

TEST(ProjectedPolygon, AreaIsTheProjectedSolidAngle)
{
    for (const PolygonCase& c : polygonCases())
    {
        SCOPED_TRACE(c.name);
        const shader::ProjectedPolygon g = shader::makeProjectedPolygon(c.light, c.p, c.n);
        const double expected = projectedSolidAngle(c.light, c.p, c.n);
        EXPECT_NEAR(g.area, expected, 1e-4 * expected);
        EXPECT_TRUE(shader::projectedPolygonApplies(g));
    }
    // What the names promise: the zenith inside only for the lights overhead; the horizon cuts the grazing ones.
    for (const PolygonCase& c : polygonCases())
        EXPECT_EQ(shader::makeProjectedPolygon(c.light, c.p, c.n).zenithInside,
                  c.name.find("overhead") != std::string::npos)
            << c.name;
    for (const PolygonCase& c : polygonCases())
    {
        const shader::ProjectedPolygon g = shader::makeProjectedPolygon(c.light, c.p, c.n);
        int onHorizon = 0;
        for (std::uint32_t i = 0; i < g.count; ++i)
            onHorizon += g.w[i].z == 0.0 ? 1 : 0;
        EXPECT_EQ(onHorizon, c.name.find("horizon across") != std::string::npos ? 2 : 0) << c.name;
    }
}

TEST(ProjectedPolygon, OneSampleGivesTheIrradianceExactly)
{
    std::uint32_t seed = 2000;
    for (const PolygonCase& c : polygonCases())
    {
        SCOPED_TRACE(c.name);
        const double expected = projectedSolidAngle(c.light, c.p, c.n);
        Rng rng(pcgHash(seed++));
        int declined = 0;
        for (int i = 0; i < 20'000; ++i)
        {
            LightSample s;
            if (!sampleLight(c.light, LightSampler::ProjectedExact, c.p, c.n, test::uniform2(rng), s))
            {
                ++declined;
                continue;
            }
            const double cosine = glm::dot(dvec3(c.n), dvec3(s.wi));
            ASSERT_GT(cosine, 0.0);
            ASSERT_NEAR(cosine / double(s.pdf), expected, 1e-3 * expected);
            ASSERT_NEAR(lightPdf(c.light, LightSampler::ProjectedExact, c.p, c.n, s.wi), s.pdf, 1e-5f * s.pdf);
            const auto ab = test::edgeCoordinates(c.light, dvec3(c.p), dvec3(s.wi));
            ASSERT_TRUE(ab.has_value());
            ASSERT_NEAR(double(s.uv.x), ab->x, 1e-3);
        }
        EXPECT_LE(declined, 2) << "samples off the light";
    }
}

TEST(ProjectedPolygon, ChiSquareFollowsTheReceiversCosine)
{
    const auto cases = polygonCases();
    constexpr long kSamples = 300'000; // ~1200 per cell: 0.5 s a case
    std::uint32_t seed = 2100;
    for (const PolygonCase& c : cases)
    {
        SCOPED_TRACE(c.name);
        const test::LightSurfaceDomain domain(c.light, c.p, 16);
        const auto h = domain.sampleHistogram(LightSampler::ProjectedExact, c.n, kSamples, seed++);
        EXPECT_LE(h.outside, 2) << "samples off the light or declined";
        const double p = projectedSolidAngle(c.light, c.p, c.n);
        const dvec3 n(c.n);
        const auto expected = domain.expectedCounts(kSamples, 8, [&](const dvec3& w) {
            return std::max(glm::dot(n, w), 0.0) / p;
        });
        const auto r = test::chiSquareTest(h.counts, expected, test::kChiSquareAlpha, int(cases.size()));
        EXPECT_TRUE(r.passed) << r.message;
    }
}

TEST(ProjectedPolygon, WithoutAReceiverItIsSolidAngleSamplingAndTinyLightsAreSampledByArea)
{
    const PolygonCase side = polygonCases()[1];
    const LightData tiny = test::makeQuadLight({2, 0, 3}, {0.01f, 0, 0}, {0, 0.01f, 0}); // 6e-6 sr
    Rng rng(pcgHash(2200));
    for (int i = 0; i < 1000; ++i)
    {
        const vec2 u = test::uniform2(rng);
        LightSample a, b;
        ASSERT_EQ(sampleLight(side.light, LightSampler::ProjectedExact, side.p, vec3(0.0f), u, a),
                  sampleLight(side.light, LightSampler::SolidAngle, side.p, vec3(0.0f), u, b));
        EXPECT_EQ(a.wi, b.wi);
        EXPECT_EQ(a.pdf, b.pdf);
        ASSERT_EQ(sampleLight(tiny, LightSampler::ProjectedExact, vec3(0.0f), side.n, u, a),
                  sampleLight(tiny, LightSampler::Area, vec3(0.0f), side.n, u, b));
        EXPECT_EQ(a.wi, b.wi);
        EXPECT_EQ(a.pdf, b.pdf);
    }
    EXPECT_FALSE(shader::projectedPolygonApplies(shader::makeProjectedPolygon(tiny, vec3(0.0f), side.n)));
    // Wholly below the horizon: no direction has a density, and the sampler declines.
    const LightData below = test::makeQuadLight({-1, -1, -1}, {2, 0, 0}, {0, 2, 0});
    LightSample s;
    EXPECT_EQ(shader::makeProjectedPolygon(below, vec3(0.0f), vec3(0, 0, 1)).count, 0u);
    EXPECT_FALSE(sampleLight(below, LightSampler::ProjectedExact, vec3(0.0f), vec3(0, 0, 1), vec2(0.5f), s));
}
} // namespace
} // namespace rt
