// sampleLight of Sampling/LightSampling.h: its directions follow the density lightPdf reports (chi-square,
// research notes §2.1), each sample's pdf is lightPdf of its direction and the density of the strategy that
// drew it (§2.3), no sample is declined, and the distance it returns reaches the light. The lights and points
// are in LightCases.h; lightPdf's own properties are in LightPdfTest.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "Support/CapDomain.h"
#include "Support/ChiSquare.h"
#include "Support/LightGeometry.h"
#include "Support/StatisticsHelpers.h"

namespace rt
{
namespace
{
using test::allCases;
using test::CapDomain;
using test::Cone;
using test::coneOf;
using test::edgeCoordinates;
using test::kPiD;
using test::LightCase;
using test::LightSurfaceDomain;
using test::sin2ToAxis;

constexpr long kChiSquareSamples = 1'000'000;

// ---- Chi-square: the sampled directions follow lightPdf --------------------------------------------------

TEST(LightSampling, ChiSquareQuadsAndTriangles)
{
    const auto cases = test::planarCases();
    std::uint32_t seed = 100;
    for (const LightCase& c : cases)
    {
        SCOPED_TRACE(c.name);
        const LightSurfaceDomain domain(c.light, c.p, 32);
        const auto h = test::histogram(domain.cellCount(), kChiSquareSamples, seed++, [&](Rng& rng) {
            LightSample s;
            return sampleLight(c.light, c.p, test::uniform2(rng), s) ? domain.cell(s.wi) : -1;
        });
        EXPECT_EQ(h.outside, 0) << "samples missing the light, or no sample";
        const auto expected = domain.expectedCounts(kChiSquareSamples, 8);
        const auto r = test::chiSquareTest(h.counts, expected, test::kChiSquareAlpha, int(cases.size()));
        EXPECT_TRUE(r.passed) << r.message;
    }
}

TEST(LightSampling, ChiSquareSpheresFromOutside)
{
    // The cap is the cone of directions to the sphere (in double), so a sample outside it beyond rounding
    // is counted as outside; lightPdf is constant inside, and the test checks the cone's uniformity and that
    // its orientation is the sphere's. Samples sampleLight declines are LightSampling.SamplesAreNeverDropped's business.
    const auto cases = test::sphereOutsideCases();
    std::uint32_t seed = 200;
    for (const LightCase& c : cases)
    {
        SCOPED_TRACE(c.name);
        const Cone cone = coneOf(c.light, c.p);
        const CapDomain domain(cone.axis, cone.cosMax, 16, 32);
        long dropped = 0;
        const auto h = test::histogram(domain.cellCount(), kChiSquareSamples, seed++, [&](Rng& rng) {
            LightSample s;
            if (sampleLight(c.light, c.p, test::uniform2(rng), s))
                return domain.cell(dvec3(s.wi));
            ++dropped;
            return -2;
        });
        EXPECT_EQ(h.outside, dropped) << "samples outside the cone";
        const auto expected = domain.expectedCounts(
            [&](const dvec3& w) { return double(lightPdf(c.light, c.p, vec3(w))); }, kChiSquareSamples - dropped, 4);
        const auto r = test::chiSquareTest(h.counts, expected, test::kChiSquareAlpha, int(cases.size()));
        EXPECT_TRUE(r.passed) << r.message;
    }
}

TEST(LightSampling, ChiSquareSpheresFromInside)
{
    // Every direction reaches the sphere: the whole sphere of directions, with the density of uniform area
    // sampling (|y - p|^2 / (cos A)), peaked towards the far side when p is near the surface.
    const auto cases = test::sphereInsideCases();
    std::uint32_t seed = 300;
    for (const LightCase& c : cases)
    {
        SCOPED_TRACE(c.name);
        const CapDomain domain(dvec3(c.light.p0) - dvec3(c.p), -1.0, 32, 64);
        const auto h = test::histogram(domain.cellCount(), kChiSquareSamples, seed++, [&](Rng& rng) {
            LightSample s;
            return sampleLight(c.light, c.p, test::uniform2(rng), s) ? domain.cell(dvec3(s.wi)) : -1;
        });
        EXPECT_EQ(h.outside, 0) << "no sample";
        const auto expected = domain.expectedCounts(
            [&](const dvec3& w) { return double(lightPdf(c.light, c.p, vec3(w))); }, kChiSquareSamples, 8);
        const auto r = test::chiSquareTest(h.counts, expected, test::kChiSquareAlpha, int(cases.size()));
        EXPECT_TRUE(r.passed) << r.message;
    }
}

// ---- Sample / pdf consistency ----------------------------------------------------------------------------

/// The density of sampleLight's strategy at a sample, in double from the geometry: 1 / (2 pi (1 - cos))
/// for a sphere's cone, |y - p|^2 / (|n . w| area) for uniform area sampling (y = p + distance wi).
double strategyPdf(const LightData& l, const vec3& p, const LightSample& s)
{
    const dvec3 w(s.wi), origin(p), center(l.p0);
    if (l.shape == LightShape::Sphere && glm::distance(origin, center) > l.radius)
    {
        const Cone cone = coneOf(l, p);
        return 1.0 / (2.0 * kPiD * (cone.sin2 / (1.0 + cone.cosMax)));
    }
    const dvec3 y = origin + double(s.distance) * w;
    dvec3 n;
    double area;
    if (l.shape == LightShape::Sphere)
    {
        n = (y - center) / double(l.radius);
        area = 4.0 * kPiD * double(l.radius) * l.radius;
    }
    else
    {
        const dvec3 cross = glm::cross(dvec3(l.p1), dvec3(l.p2));
        n = glm::normalize(cross);
        area = glm::length(cross) * (l.shape == LightShape::Triangle ? 0.5 : 1.0);
    }
    return glm::dot(y - origin, y - origin) / (std::fabs(glm::dot(n, w)) * area);
}

/// Every sample's pdf equals lightPdf of its direction and the density of the strategy that drew it.
/// 1e-3 relative: the float pdf recomputes distance and cosine from the float direction, which for the
/// grazing and near-field cases moves the 5th digit at most; a pdf of the wrong strategy or a missing cosine
/// is off by far more.
void expectConsistent(const LightCase& c, std::uint32_t seed, long samples)
{
    SCOPED_TRACE(c.name);
    Rng rng(pcgHash(seed));
    long mismatches = 0;
    for (long i = 0; i < samples; ++i)
    {
        const vec2 u = test::uniform2(rng);
        LightSample s;
        if (!sampleLight(c.light, c.p, u, s))
            continue; // SamplesAreNeverDropped
        ASSERT_TRUE(std::isfinite(s.pdf) && s.pdf > 0.0f);
        const double pdf = lightPdf(c.light, c.p, s.wi), expected = strategyPdf(c.light, c.p, s);
        const bool ok = std::fabs(pdf - s.pdf) <= 1e-3 * s.pdf && std::fabs(s.pdf - expected) <= 1e-3 * expected;
        if (!ok && mismatches++ < 3)
            ADD_FAILURE() << "u = (" << u.x << ", " << u.y << "): sample pdf " << s.pdf << ", lightPdf " << pdf
                          << ", density of the strategy " << expected;
    }
    EXPECT_EQ(mismatches, 0) << "of " << samples << " samples";
}

TEST(LightSampling, SamplePdfMatchesLightPdfAndTheStrategy)
{
    std::uint32_t seed = 400;
    for (const LightCase& c : allCases())
        expectConsistent(c, seed++, 100'000);
}

TEST(LightSampling, SamplesAreNeverDropped)
{
    // From a point off the light (not in a planar light's plane), every u gives a sample: a declined sample
    // is light the estimator never sees. Spheres down to 1e-8 (R/d = 1e-4, a 5 cm bulb 500 m away).
    std::vector<LightCase> cases = allCases();
    for (float sin2 : {1e-6f, 1e-8f})
        cases.push_back({(std::ostringstream() << "sphere (sin^2 = " << sin2 << ")").str(),
                         test::sphereSeenAt(sin2, {0.3f, 1.0f, 0.2f}), vec3(0.0f)});
    std::uint32_t seed = 450;
    for (const LightCase& c : cases)
    {
        Rng rng(pcgHash(seed++));
        long dropped = 0;
        vec2 example(0.0f);
        for (int i = 0; i < 1'000'000; ++i)
        {
            const vec2 u = test::uniform2(rng);
            LightSample s;
            if (!sampleLight(c.light, c.p, u, s))
                ++dropped, example = u;
        }
        EXPECT_EQ(dropped, 0) << c.name << ": " << dropped << " of 1e6 samples declined, e.g. u = (" << example.x
                              << ", " << example.y << ")";
    }
}

// ---- The sample's other fields ---------------------------------------------------------------------------

TEST(LightSampling, SamplePointLiesOnTheLightAlongItsDirection)
{
    // NEE's shadow ray runs from p along wi for `distance` and evaluates the emission at `point` with `normal`:
    // all four must describe one point of the light's surface, seen from p (front side for a sphere seen from
    // outside: the near root).
    for (const LightCase& c : allCases())
    {
        SCOPED_TRACE(c.name);
        Rng rng(pcgHash(700));
        for (int i = 0; i < 20'000; ++i)
        {
            LightSample s;
            if (!sampleLight(c.light, c.p, test::uniform2(rng), s))
                continue; // SamplesAreNeverDropped
            const dvec3 p(c.p), w(s.wi), y(s.point), n(s.normal), center(c.light.p0);
            const double scale = std::max(1.0, glm::length(p) + double(s.distance)); // float rounding scales with it
            ASSERT_NEAR(glm::length(n), 1.0, 1e-5);
            // Along wi: the sphere's cone sample re-projects its point onto the sphere, which moves it by the
            // rounding of the near root (up to sqrt(eps) R at the silhouette).
            const double along = c.light.shape == LightShape::Sphere ? 1e-3 * c.light.radius : 1e-5 * scale;
            ASSERT_LE(glm::distance(p + double(s.distance) * w, y), along) << "the point is not along wi";
            ASSERT_NEAR(glm::distance(p, y), double(s.distance), along);
            if (c.light.shape != LightShape::Sphere)
            {
                ASSERT_NEAR(glm::dot(dvec3(c.light.normal), y - center), 0.0, 1e-5 * scale) << "not on the light's plane";
                ASSERT_EQ(s.normal, c.light.normal);
                continue;
            }
            ASSERT_NEAR(glm::distance(y, center), double(c.light.radius), 1e-5 * scale) << "not on the sphere";
            ASSERT_LE(glm::distance(n, (y - center) / double(c.light.radius)), 1e-4) << "not the outward normal";
            if (glm::distance(p, center) > c.light.radius)
            {
                ASSERT_LE(glm::dot(w, n), 1e-3) << "a sphere seen from outside shows its front";
            }
        }
    }
}

TEST(LightSampling, PointInTheLightPlaneGivesNoSample)
{
    // Every direction from a point in a planar light's plane grazes it: pdf infinite, so no sample.
    const LightData quad = test::makeQuadLight({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    const LightData triangle = test::makeTriangleLight({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    for (const LightData& l : {quad, triangle})
    {
        LightSample s;
        EXPECT_FALSE(sampleLight(l, {2.0f, 0.5f, 0.0f}, {0.3f, 0.3f}, s));
        EXPECT_EQ(lightPdf(l, {2.0f, 0.5f, 0.0f}, {-1.0f, 0.0f, 0.0f}), 0.0f);
    }
}
} // namespace
} // namespace rt
