// Projected-solid-angle sampling of sphere lights (Shared/Lights/ProjectedCap.h: Ureña & Georgiev 2018), over
// caps from wholly above the receiver's horizon to almost wholly below it, from 1e-3 rad to 80 degrees:
//   - the projected solid angle F it computes in float against a float64 quadrature over the cap (independent of
//     its ellipse-and-segment decomposition);
//   - zero variance for a Lambertian receiver: every sample's cos / pdf is F (research notes §1.6);
//   - chi-square of its directions, uniform over the projected region, against that region found in float64
//     from its definition (a direction of the hemisphere within alpha of the centre), cells in the tangent plane
//     (Support/ProjectedCapDomain.h);
//   - its pdf integrating to 1 over the visible cap, lightPdf equal to each sample's pdf, and its branches: a
//     medium or a point inside the sphere takes the cone, a cap wholly below the horizon no sample.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "Sampling/LightSampling.h"
#include "Support/CapDomain.h"
#include "Support/ChiSquare.h"
#include "Support/LightGeometry.h"
#include "Support/ProjectedCapDomain.h"
#include "Support/StatisticsHelpers.h"

namespace rt
{
namespace
{
using test::kPiD;

const vec3 kUp(0.0f, 0.0f, 1.0f);

/// A sphere of angular radius alpha (radians) seen from the origin, its centre at elevation beta over the
/// horizon of +z, at azimuth 30 degrees.
struct CapCase
{
    std::string name;
    LightData light;
};

CapCase capCase(double alpha, double betaOverAlpha)
{
    const double beta = betaOverAlpha * alpha, azimuth = kPiD / 6.0, d = 5.0;
    const dvec3 dir(std::cos(beta) * std::cos(azimuth), std::cos(beta) * std::sin(azimuth), std::sin(beta));
    char name[96];
    std::snprintf(name, sizeof name, "alpha %.3g, beta/alpha %+.3f", alpha, betaOverAlpha);
    return {name, test::makeSphereLight(vec3(d * dir), float(d * std::sin(alpha)))};
}

test::CapGeometry geometryOf(const LightData& l)
{
    return test::capGeometry(l, vec3(0.0f), kUp);
}

/// Caps from wholly above to almost wholly below the horizon, tiny to 80 degrees.
std::vector<CapCase> capCases()
{
    std::vector<CapCase> out;
    for (double alpha : {1e-3, 1e-2, 0.1, 0.5, 1.0, 1.4})
        for (double f : {-0.99, -0.9, -0.5, -0.1, 0.0, 0.1, 0.5, 0.9, 0.99, 1.2})
            out.push_back(capCase(alpha, f));
    return out;
}

TEST(ProjectedCap, AreaIsTheProjectedSolidAngleOfTheVisibleCap)
{
    for (const CapCase& c : capCases())
    {
        SCOPED_TRACE(c.name);
        shader::ProjectedCap cap;
        const std::uint32_t kind = shader::projectedCap(c.light, vec3(0.0f), kUp, cap);
        const test::CapGeometry g = geometryOf(c.light);
        ASSERT_EQ(kind, g.sinBeta >= g.sinAlpha ? shader::kCapWhole
                        : g.sinBeta >= 0.0      ? shader::kCapClipped
                                                : shader::kCapCrescent);
        const double expected = test::projectedSolidAngle(g);
        EXPECT_NEAR(double(cap.area), expected, 1e-3 * expected);
    }
    // Almost wholly below: the crescent's area is a difference of terms 1e4 times larger, done by its series.
    for (double alpha : {1e-2, 0.5, 1.4})
    {
        const CapCase c = capCase(alpha, -0.999);
        SCOPED_TRACE(c.name);
        shader::ProjectedCap cap;
        shader::projectedCap(c.light, vec3(0.0f), kUp, cap);
        const double expected = test::projectedSolidAngle(geometryOf(c.light));
        EXPECT_NEAR(double(cap.area), expected, 1e-3 * expected);
    }
}

TEST(ProjectedCap, DiskSegmentAreaIsAccurateInFloat)
{
    for (double theta = 1e-4; theta < kPiD; theta *= 1.07)
    {
        const double exact = theta - 0.5 * std::sin(2.0 * theta);
        ASSERT_NEAR(double(shader::diskSegmentArea(float(theta))), exact, 1e-6 * exact + 1e-12) << theta;
    }
}

TEST(ProjectedCap, OneSampleGivesTheIrradianceExactly)
{
    // Zero variance (research notes §1.6): L cos / pdf = L F for every sample, F from the float64 quadrature.
    std::uint32_t seed = 1000;
    for (const CapCase& c : capCases())
    {
        SCOPED_TRACE(c.name);
        const test::CapGeometry g = geometryOf(c.light);
        const double expected = test::projectedSolidAngle(g);
        Rng rng(pcgHash(seed++));
        int rim = 0;
        for (int i = 0; i < 5'000; ++i)
        {
            LightSample s;
            ASSERT_TRUE(sampleLight(c.light, LightSampler::Projected, vec3(0.0f), kUp, test::uniform2(rng), s));
            ASSERT_GT(s.wi.z, 0.0f);
            ASSERT_NEAR(double(s.wi.z) / double(s.pdf), expected, 1e-3 * expected);
            // Within the cap, up to float's rounding: a few 1e-8 rad of a unit direction, and up to 1e-4 alpha where
            // the crescent's tip is thinnest (beta -> -alpha: 0.14 % of the samples at beta = -0.99 alpha = -0.99).
            const double angle = std::asin(std::sqrt(test::sin2ToAxis(dvec3(s.wi), g.axis)));
            const double alpha = std::asin(g.sinAlpha);
            ASSERT_LE(angle, alpha * (1.0 + 1e-4) + 2e-7);
            const float pdf = lightPdf(c.light, LightSampler::Projected, vec3(0.0f), kUp, s.wi);
            if (pdf == 0.0f) // the rim samples rounding moved out of the cone (the sampler keeps them)
                ++rim;
            else
                ASSERT_NEAR(pdf, s.pdf, 1e-5f * s.pdf);
            ASSERT_NEAR(glm::distance(dvec3(s.point), dvec3(c.light.p0)), double(c.light.radius),
                        1e-5 * (1.0 + glm::length(dvec3(c.light.p0))));
        }
        EXPECT_LE(rim, 50); // 1 %
    }
}

TEST(ProjectedCap, ChiSquareIsUniformOverTheProjectedVisibleCap)
{
    const std::vector<CapCase> cases = {
        capCase(0.5, 1.2), capCase(0.5, 0.3), capCase(0.5, 0.0),   capCase(0.5, -0.5), capCase(0.5, -0.9),
        capCase(1.3, 0.2), capCase(1.3, -0.6), capCase(0.01, 0.5), capCase(0.01, -0.8),
    };
    constexpr long kSamples = 1'000'000;
    std::uint32_t seed = 1100;
    for (const CapCase& c : cases)
    {
        SCOPED_TRACE(c.name);
        const test::ProjectedCapDomain domain(geometryOf(c.light));
        const auto h = test::histogram(domain.cellCount(), kSamples, seed++, [&](Rng& rng) {
            LightSample s;
            return sampleLight(c.light, LightSampler::Projected, vec3(0.0f), kUp, test::uniform2(rng), s)
                       ? domain.cell(s.wi)
                       : -2;
        });
        EXPECT_LE(h.outside, kSamples / 100'000) << "samples outside the region's box, or none";
        const auto r = test::chiSquareTest(h.counts, domain.expectedCounts(kSamples), test::kChiSquareAlpha,
                                           int(cases.size()));
        EXPECT_TRUE(r.passed) << r.message;
    }
}

TEST(ProjectedCap, PdfIntegratesToOneOverTheVisibleCap)
{
    for (const CapCase& c : {capCase(0.5, 0.3), capCase(0.5, -0.5), capCase(1.3, 0.2), capCase(0.1, 0.0)})
    {
        SCOPED_TRACE(c.name);
        const test::Cone cone = test::coneOf(c.light, vec3(0.0f));
        const test::CapDomain domain(cone.axis, cone.cosMax, 64, 128);
        const double integral = domain.integrate(
            [&](const dvec3& w) { return double(lightPdf(c.light, LightSampler::Projected, vec3(0.0f), kUp, vec3(w))); },
            8);
        EXPECT_NEAR(integral, 1.0, 2e-3);
    }
}

TEST(ProjectedCap, InAMediumOrInsideTheSphereItIsTheCone)
{
    const LightData above = capCase(0.5, 0.3).light;
    const LightData around = test::makeSphereLight({0.2f, 0.1f, 0.3f}, 1.0f); // p inside
    Rng rng(pcgHash(1200));
    for (int i = 0; i < 1000; ++i)
    {
        const vec2 u = test::uniform2(rng);
        for (const auto& [light, normal] : {std::pair{above, vec3(0.0f)}, std::pair{around, kUp}})
        {
            LightSample a, b;
            ASSERT_EQ(sampleLight(light, LightSampler::Projected, vec3(0.0f), normal, u, a),
                      sampleLight(light, LightSampler::SolidAngle, vec3(0.0f), normal, u, b));
            EXPECT_EQ(a.pdf, b.pdf);
            EXPECT_EQ(a.wi, b.wi);
        }
    }
}

TEST(ProjectedCap, WhollyBelowTheHorizonThereIsNoSample)
{
    const LightData below = capCase(0.5, -1.01).light;
    shader::ProjectedCap cap;
    EXPECT_EQ(shader::projectedCap(below, vec3(0.0f), kUp, cap), shader::kCapBelow);
    LightSample s;
    EXPECT_FALSE(sampleLight(below, LightSampler::Projected, vec3(0.0f), kUp, vec2(0.3f, 0.6f), s));
    EXPECT_EQ(s.pdf, 0.0f);
    const vec3 towardsCentre = glm::normalize(below.p0);
    EXPECT_EQ(lightPdf(below, LightSampler::Projected, vec3(0.0f), kUp, towardsCentre), 0.0f);
}
} // namespace
} // namespace rt
