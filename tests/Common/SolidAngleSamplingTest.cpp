// NEE's light samplers (LightSampling.h with a LightSampler): spherical rectangles (Ureña, Fajardo & King
// 2013) and area sampling of spheres seen from outside. Their solid angle against double precision, their
// directions against the density lightPdf reports (chi-square, research notes §2.1), each sample's pdf against
// lightPdf and the geometry (§2.3), and E[1/pdf] = the solid angle, with zero variance for the rectangle
// (§2.2). Direct lighting through them is in LightIrradianceTest.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "Support/CapDomain.h"
#include "Support/ChiSquare.h"
#include "Support/LightGeometry.h"
#include "Support/StatisticsHelpers.h"

namespace rt
{
namespace
{
using test::kPiD;
using test::LightCase;

constexpr long kChiSquareSamples = 1'000'000;
const vec3 kNoNormal(0.0f); // these samplers ignore the receiver's normal

/// Solid angle of the triangle (a, b, c) seen from the origin: Van Oosterom & Strackee (1983),
/// tan(Omega / 2) = |a . (b x c)| / (|a||b||c| + (a.b)|c| + (a.c)|b| + (b.c)|a|), in double.
double triangleSolidAngle(const dvec3& a, const dvec3& b, const dvec3& c)
{
    const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    const double numerator = std::fabs(glm::dot(a, glm::cross(b, c)));
    const double denominator = la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
    return 2.0 * std::atan2(numerator, denominator);
}

double rectangleSolidAngle(const LightData& l, const vec3& p)
{
    const dvec3 s = dvec3(l.p0) - dvec3(p), u(l.p1), v(l.p2);
    return triangleSolidAngle(s, s + u, s + u + v) + triangleSolidAngle(s, s + u + v, s + v);
}

/// Rectangles (orthogonal edges) from the planar cases, and a long thin strip like cornell-box-lights'
/// (355 x 10 seen from 20 and from 300 units).
std::vector<LightCase> rectangleCases()
{
    std::vector<LightCase> out;
    for (const LightCase& c : test::planarCases())
        if (shader::isRectangle(c.light))
            out.push_back(c);
    out.push_back({"strip, near", test::makeQuadLight({455, 100, 554}, {-355, 0, 0}, {0, 10, 0}), {300, 90, 534}});
    out.push_back({"strip, across the room", test::makeQuadLight({455, 100, 554}, {-355, 0, 0}, {0, 10, 0}), {278, 300, 254}});
    return out;
}

TEST(SphericalRectangle, CasesAreRectanglesLargeEnoughForTheSampler)
{
    const auto cases = rectangleCases();
    ASSERT_GE(cases.size(), 6u);
    for (const LightCase& c : cases)
        EXPECT_GE(rectangleSolidAngle(c.light, c.p), double(shader::kMinSphericalRectangle)) << c.name;
}

TEST(SphericalRectangle, SolidAngleMatchesDoublePrecision)
{
    // The sum of four internal angles minus 2 pi, in float: good to the few 1e-7 sr of its cancellation.
    for (const LightCase& c : rectangleCases())
    {
        const auto r = shader::makeSphericalRectangle(c.p, c.light.p0, c.light.p1, c.light.p2);
        const double expected = rectangleSolidAngle(c.light, c.p);
        EXPECT_NEAR(r.solidAngle, expected, 2e-6 + 1e-5 * expected) << c.name;
    }
}

TEST(SphericalRectangle, ChiSquareUniformOverTheSolidAngle)
{
    const auto cases = rectangleCases();
    std::uint32_t seed = 500;
    for (const LightCase& c : cases)
    {
        SCOPED_TRACE(c.name);
        const test::LightSurfaceDomain domain(c.light, c.p, 32);
        const auto h = domain.sampleHistogram(LightSampler::SolidAngle, kNoNormal, kChiSquareSamples, seed++);
        EXPECT_EQ(h.outside, 0) << "samples missing the light, or no sample";
        const auto expected = domain.expectedCounts(kChiSquareSamples, 8, LightSampler::SolidAngle);
        const auto r = test::chiSquareTest(h.counts, expected, test::kChiSquareAlpha, int(cases.size()));
        EXPECT_TRUE(r.passed) << r.message;
    }
}

TEST(SphericalRectangle, EverySamplePdfIsOneOverTheSolidAngle)
{
    // Consistency (§2.3) and zero variance (§2.2): 1/pdf is the solid angle for every sample, so its mean
    // is the solid angle with no spread at all, and lightPdf of the sample's direction agrees.
    std::uint32_t seed = 600;
    for (const LightCase& c : rectangleCases())
    {
        SCOPED_TRACE(c.name);
        const double solidAngle = rectangleSolidAngle(c.light, c.p);
        Rng rng(pcgHash(seed++));
        for (int i = 0; i < 20'000; ++i)
        {
            LightSample s;
            ASSERT_TRUE(sampleLight(c.light, LightSampler::SolidAngle, c.p, kNoNormal, test::uniform2(rng), s));
            ASSERT_NEAR(1.0 / double(s.pdf), solidAngle, 2e-6 + 1e-5 * solidAngle);
            ASSERT_EQ(lightPdf(c.light, LightSampler::SolidAngle, c.p, kNoNormal, s.wi), s.pdf);
            // The point is on the rectangle, along wi, and uv are its edge coordinates.
            const dvec3 y(s.point);
            ASSERT_NEAR(glm::distance(dvec3(c.p) + double(s.distance) * dvec3(s.wi), y), 0.0, 1e-5 * (1.0 + s.distance));
            const dvec3 expectedY = dvec3(c.light.p0) + double(s.uv.x) * dvec3(c.light.p1) + double(s.uv.y) * dvec3(c.light.p2);
            ASSERT_LE(glm::distance(expectedY, y), 1e-4 * (1.0 + glm::length(y)));
            ASSERT_GE(s.uv.x, -1e-5f);
            ASSERT_LE(s.uv.x, 1.0f + 1e-5f);
        }
    }
}

TEST(SphericalRectangle, InversionReturnsTheSamplesCoordinates)
{
    // sampleSphericalRectangle's cut (its closed form for xu, notebook §37) and invertSphericalRectangle's part
    // (three planes shared with the rectangle) are computed independently: u -> point -> u must come back, to the
    // float solid angle's cancellation (a few 1e-7 sr over S >= 0.01 sr), also at the ends of [0, 1].
    const float grid[] = {0.0f, 1e-6f, 0.01f, 0.25f, 0.5f, 0.75f, 0.99f, 1.0f - 1e-6f};
    for (const LightCase& c : rectangleCases())
    {
        SCOPED_TRACE(c.name);
        const auto r = shader::lightSphericalRectangle(c.light, c.p);
        for (const float ux : grid)
            for (const float uy : grid)
            {
                const vec3 y = shader::sampleSphericalRectangle(r, vec2(ux, uy)) - r.o;
                const vec2 back = shader::invertSphericalRectangle(r, dot(y, r.x), dot(y, r.y));
                ASSERT_NEAR(back.x, ux, 2e-4f) << "u = (" << ux << ", " << uy << ")";
                ASSERT_NEAR(back.y, uy, 2e-4f) << "u = (" << ux << ", " << uy << ")";
            }
    }
}

TEST(SphericalRectangle, SmallOrSkewedQuadsFallBackToAreaSampling)
{
    // Below kMinSphericalRectangle, for parallelograms, and from 1e-5 above a unit rectangle (nearly 2 pi sr,
    // which float's setup cannot resolve: every sample at one edge), the density is area sampling's.
    const LightData far = test::makeQuadLight({-0.05f, -0.05f, 10.0f}, {0.1f, 0, 0}, {0, 0.1f, 0});
    const LightData skewed = test::makeQuadLight({0, 0, 1}, {1, 0, 0}, {0.5f, 1, 0});
    const LightData grazed = test::makeQuadLight({-0.3f, -0.4f, 1e-5f}, {1, 0, 0}, {0, 1, 0});
    EXPECT_FALSE(shader::isRectangle(skewed));
    EXPECT_GT(shader::lightSphericalRectangle(grazed, vec3(0.0f)).solidAngle, 6.0f);
    for (const LightData& l : {far, skewed, grazed})
    {
        Rng rng(pcgHash(700));
        for (int i = 0; i < 1000; ++i)
        {
            const vec2 u = test::uniform2(rng);
            LightSample a, b;
            ASSERT_EQ(sampleLight(l, LightSampler::SolidAngle, vec3(0.0f), kNoNormal, u, a),
                      sampleLight(l, LightSampler::Area, vec3(0.0f), kNoNormal, u, b));
            EXPECT_EQ(a.pdf, b.pdf);
            EXPECT_EQ(a.point, b.point);
        }
    }
    // 1e-2 above it the setup resolves the rectangle (z0^2 / the farthest edge's square: 2e-4): its own sampler.
    const LightData near = test::makeQuadLight({-0.3f, -0.4f, 1e-2f}, {1, 0, 0}, {0, 1, 0});
    LightSample a, b;
    ASSERT_TRUE(sampleLight(near, LightSampler::SolidAngle, vec3(0.0f), kNoNormal, vec2(0.3f, 0.6f), a));
    ASSERT_TRUE(sampleLight(near, LightSampler::Area, vec3(0.0f), kNoNormal, vec2(0.3f, 0.6f), b));
    EXPECT_NE(a.pdf, b.pdf);
}

// ---- Spheres by area from outside ---------------------------------------------------------------------------

TEST(SphereAreaSampling, ChiSquareUniformOverTheVisibleCap)
{
    // Points on the far side face away and give no sample: (1 + sin alpha) / 2 of them. The rest are uniform
    // in area over the cap that faces p, histogrammed by their normal about the axis towards p (uniform in
    // area = uniform in (cos, phi), Archimedes). The density over directions diverges at the silhouette, where
    // no grid of directions could integrate it: the surface is where this sampler is uniform.
    const auto cases = test::sphereOutsideCases();
    std::uint32_t seed = 800;
    for (const LightCase& c : cases)
    {
        SCOPED_TRACE(c.name);
        const dvec3 toP = dvec3(c.p) - dvec3(c.light.p0);
        const double sinAlpha = double(c.light.radius) / glm::length(toP);
        const test::CapDomain domain(toP, sinAlpha, 16, 32);
        long declined = 0;
        const auto h = test::histogram(domain.cellCount(), kChiSquareSamples, seed++, [&](Rng& rng) {
            LightSample s;
            if (sampleLight(c.light, LightSampler::Area, c.p, kNoNormal, test::uniform2(rng), s))
                return domain.cell(dvec3(s.normal));
            ++declined;
            return -2;
        });
        EXPECT_EQ(h.outside, declined) << "samples from the far side";
        EXPECT_NEAR(double(declined) / kChiSquareSamples, 0.5 * (1.0 + sinAlpha), 2e-3);
        const auto expected = domain.expectedCounts([](const dvec3&) { return 1.0 / (4.0 * kPiD); }, kChiSquareSamples, 1);
        const auto r = test::chiSquareTest(h.counts, expected, test::kChiSquareAlpha, int(cases.size()));
        EXPECT_TRUE(r.passed) << r.message;
    }
}

TEST(SphereAreaSampling, SamplePdfIsTheNearPointsAreaDensity)
{
    std::uint32_t seed = 900;
    for (const LightCase& c : test::sphereOutsideCases())
    {
        SCOPED_TRACE(c.name);
        Rng rng(pcgHash(seed++));
        int samples = 0;
        for (int i = 0; i < 20'000; ++i)
        {
            LightSample s;
            if (!sampleLight(c.light, LightSampler::Area, c.p, kNoNormal, test::uniform2(rng), s))
                continue;
            ++samples;
            const dvec3 w(s.wi), y(s.point), n(s.normal), center(c.light.p0);
            const double r = c.light.radius;
            const double cosLight = -glm::dot(n, w);
            const double expected = glm::dot(y - dvec3(c.p), y - dvec3(c.p)) / (cosLight * 4.0 * kPiD * r * r);
            // The float cosine of the sample itself carries 1e-7 absolute: 1e-7 / cos relative.
            ASSERT_NEAR(s.pdf, expected, (1e-4 + 2e-7 / cosLight) * expected);
            // lightPdf finds the point again from the float direction: near the silhouette its cosine is the
            // root of a discriminant r^2 cos^2 that the direction's rounding (6e-8 d across) moves by 1e-7 d r,
            // so the pdf carries about 1e-7 (d / r) / cos^2 relative (8 % at cos = 1.7e-3 seen from d = 2 r,
            // unbounded at the silhouette itself, where the density diverges: the irradiance tests integrate
            // through it). Compared where that is below 1 %.
            const double d = glm::distance(dvec3(c.p), center);
            const double tolerance = 1e-4 + 3e-7 * (d / r) / (cosLight * cosLight);
            if (tolerance < 1e-2)
            {
                ASSERT_NEAR(lightPdf(c.light, LightSampler::Area, c.p, kNoNormal, s.wi), s.pdf, tolerance * s.pdf);
            }
            ASSERT_NEAR(glm::distance(y, center), r, 1e-5 * (1.0 + glm::length(center)));
        }
        EXPECT_GT(samples, 500); // (1 - sin alpha) / 2 of 20,000: 4.5 % for the nearest
    }
}
// ---- Rectangles by the bilinear cosine warp -------------------------------------------------------------

/// A receiver normal tilted away from the rectangle's centre, so that the cosine varies across it.
vec3 tiltedNormal(const LightCase& c)
{
    const vec3 centre = c.light.p0 + 0.5f * (c.light.p1 + c.light.p2) - c.p;
    return glm::normalize(glm::normalize(centre) + vec3(0.5f, -0.3f, 0.2f));
}

TEST(ProjectedRectangle, SamplesFollowTheWarpedDensityItReports)
{
    // Chi-square against lightPdf(Projected): that pdf inverts the spherical rectangle's parametrisation
    // (the solid angle of a sub-rectangle) and evaluates the bilinear warp there, so the test checks the
    // inversion and the warp's sampling against each other.
    const auto cases = rectangleCases();
    std::uint32_t seed = 1300;
    for (const LightCase& c : cases)
    {
        SCOPED_TRACE(c.name);
        const vec3 n = tiltedNormal(c);
        const test::LightSurfaceDomain domain(c.light, c.p, 32);
        const auto h = domain.sampleHistogram(LightSampler::Projected, n, kChiSquareSamples, seed++);
        EXPECT_EQ(h.outside, 0) << "samples missing the light, or no sample";
        const auto expected = domain.expectedCounts(kChiSquareSamples, 8, LightSampler::Projected, n);
        const auto r = test::chiSquareTest(h.counts, expected, test::kChiSquareAlpha, int(cases.size()));
        EXPECT_TRUE(r.passed) << r.message;
    }
}

TEST(ProjectedRectangle, SamplePdfMatchesLightPdfAndIntegratesToOne)
{
    std::uint32_t seed = 1400;
    for (const LightCase& c : rectangleCases())
    {
        SCOPED_TRACE(c.name);
        const vec3 n = tiltedNormal(c);
        const double solidAngle = rectangleSolidAngle(c.light, c.p);
        Rng rng(pcgHash(seed++));
        double inverseSum = 0.0;
        constexpr int kSamples = 20'000;
        for (int i = 0; i < kSamples; ++i)
        {
            LightSample s;
            ASSERT_TRUE(sampleLight(c.light, LightSampler::Projected, c.p, n, test::uniform2(rng), s));
            const float pdf = lightPdf(c.light, LightSampler::Projected, c.p, n, s.wi);
            ASSERT_NEAR(pdf, s.pdf, 2e-3f * s.pdf) << "the inversion disagrees with the sample";
            inverseSum += 1.0 / double(s.pdf);
        }
        // E[1 / pdf] over the samples = the solid angle the density lives on (§2.2).
        EXPECT_NEAR(inverseSum / kSamples, solidAngle, 0.02 * solidAngle);
    }
}
} // namespace
} // namespace rt
