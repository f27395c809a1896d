// lightPdf of Sampling/LightSampling.h: a density of directions (integrates to 1, research notes §2.2) that
// vanishes off the light, and stays finite and right for a sphere 1e-5 radians wide (§1.2).
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

// ---- lightPdf is a density of directions that vanishes off the light -------------------------------------

TEST(LightPdf, IntegratesToOneOverDirections)
{
    // Midpoint quadrature of lightPdf over a cap of directions around the light (400 x 800 cells, 2 x 2
    // points each). A sphere's cone ends on a row boundary (the cap is 1.25 times its 1 - cos), so only the
    // outline of a quad or triangle cuts cells, where the rule errs by part of a cell: measured below 4e-5
    // for these lights. The small sphere measures 3e-4: lightPdf puts its cone's edge at a float cos(theta_max),
    // rounded by up to 1e-3 of its 1 - cos. 1e-3 still catches a missing cosine, a wrong area or a pdf outside
    // the light. Grazing cases are left to LightPdf.IntegratesToOneOverTheLight (their mass hugs the outline).
    for (const LightCase& c : allCases())
    {
        if (c.grazing)
            continue;
        dvec3 axis;
        double cosMin;
        if (c.light.shape == LightShape::Sphere)
        {
            const Cone cone = coneOf(c.light, c.p);
            const bool inside = glm::distance(dvec3(c.p), dvec3(c.light.p0)) < c.light.radius;
            axis = inside ? dvec3(0, 0, 1) : cone.axis;
            cosMin = inside ? -1.0 : 1.0 - 1.25 * (cone.sin2 / (1.0 + cone.cosMax));
        }
        else
        {
            const dvec3 q(c.light.p0), e1(c.light.p1), e2(c.light.p2), p(c.p);
            const bool tri = c.light.shape == LightShape::Triangle;
            const std::vector<dvec3> corners = tri ? std::vector<dvec3>{q, q + e1, q + e2}
                                                   : std::vector<dvec3>{q, q + e1, q + e1 + e2, q + e2};
            dvec3 centroid(0.0);
            for (const dvec3& v : corners)
                centroid += v / double(corners.size());
            axis = glm::normalize(centroid - p);
            double widest = 0.0;
            for (const dvec3& v : corners)
                widest = std::max(widest, std::acos(std::clamp(glm::dot(glm::normalize(v - p), axis), -1.0, 1.0)));
            cosMin = std::cos(std::min(1.1 * widest + 1e-3, kPiD));
        }
        const CapDomain cap(axis, cosMin, 400, 800);
        const double integral = cap.integrate([&](const dvec3& w) { return double(lightPdf(c.light, c.p, vec3(w))); }, 2);
        EXPECT_NEAR(integral, 1.0, 1e-3) << c.name;
    }
}

TEST(LightPdf, IntegratesToOneOverTheLight)
{
    // The same integral over the directions that reach a planar light, by the change of variables to its
    // surface (dw = |n.w| dA / r^2), where the integrand is smooth even for grazing and near-field points
    // (for uniform area sampling it is the constant 1 / area, if lightPdf is right): measured within 2e-7,
    // so 1e-4 is float rounding with margin. LightPdf.VanishesOffTheLight covers every other direction.
    for (const LightCase& c : test::planarCases())
    {
        const auto cells = LightSurfaceDomain(c.light, c.p, 64).expectedCounts(1, 8);
        double integral = 0.0;
        for (double x : cells)
            integral += x;
        EXPECT_NEAR(integral, 1.0, 1e-4) << c.name;
    }
}

TEST(LightPdf, VanishesOffTheLight)
{
    // Uniform directions, classified in double; those within 1e-4 (relative) of the light's outline are
    // left out, being neither clearly in nor clearly out in float.
    for (const LightCase& c : allCases())
    {
        SCOPED_TRACE(c.name);
        Rng rng(pcgHash(500));
        long hits = 0, misses = 0;
        for (int i = 0; i < 200'000; ++i)
        {
            const dvec3 w(sampleUniformSphere(test::uniform2(rng)));
            bool hit = false, miss = false;
            if (c.light.shape == LightShape::Sphere)
            {
                const Cone cone = coneOf(c.light, c.p);
                if (glm::distance(dvec3(c.p), dvec3(c.light.p0)) < c.light.radius)
                    hit = true; // from inside, every direction reaches the sphere
                else
                {
                    const double s2 = sin2ToAxis(w, cone.axis);
                    const bool forward = glm::dot(w, cone.axis) > 0.0;
                    hit = forward && s2 < cone.sin2 * (1.0 - 1e-4);
                    miss = !forward || s2 > cone.sin2 * (1.0 + 1e-4);
                }
            }
            else
            {
                const auto ab = edgeCoordinates(c.light, dvec3(c.p), w);
                if (!ab)
                    miss = true;
                else
                {
                    const double a = ab->x, b = ab->y, e = 1e-4;
                    const bool tri = c.light.shape == LightShape::Triangle;
                    hit = a > e && b > e && (tri ? a + b < 1.0 - e : a < 1.0 - e && b < 1.0 - e);
                    miss = a < -e || b < -e || (tri ? a + b > 1.0 + e : a > 1.0 + e || b > 1.0 + e);
                }
            }
            const float pdf = lightPdf(c.light, c.p, vec3(w));
            if (hit)
            {
                ++hits;
                EXPECT_GT(pdf, 0.0f) << "direction (" << w.x << ", " << w.y << ", " << w.z << ") reaches the light";
            }
            if (miss)
            {
                ++misses;
                EXPECT_EQ(pdf, 0.0f) << "direction (" << w.x << ", " << w.y << ", " << w.z << ") misses the light";
            }
            if (HasFailure())
                return;
        }
        EXPECT_GT(hits, 0); // the classification must see both kinds, or the test proves nothing
        const bool surrounded =
            c.light.shape == LightShape::Sphere && glm::distance(dvec3(c.p), dvec3(c.light.p0)) < c.light.radius;
        if (!surrounded)
        {
            EXPECT_GT(misses, 0);
        }
    }
}

// ---- Robustness ------------------------------------------------------------------------------------------

TEST(LightPdf, TinySphereGivesFinitePdfAndSamplesInsideTheCone)
{
    // sin^2(theta_max) = 1e-10: cos(theta_max) is 1 in float, so only 1 - cos computed as sin^2 / (1 + cos)
    // keeps the pdf finite (research notes §1.2). Its value is 1 / (2 pi (1 - cos)), computed here in double.
    const LightData tiny = test::sphereSeenAt(1e-10f, {0.3f, 1.0f, 0.2f});
    const Cone cone = coneOf(tiny, vec3(0.0f));
    const double expectedPdf = 1.0 / (2.0 * kPiD * (cone.sin2 / (1.0 + cone.cosMax)));
    // A float direction resolves angles to ~1e-7 rad; the cone is 1e-5 rad wide: allow 4 float ulps of 1.
    const double sinTolerance = 4.0 * 0x1p-24;
    Rng rng(pcgHash(600));
    long dropped = 0;
    for (int i = 0; i < 100'000; ++i)
    {
        const vec2 u = test::uniform2(rng);
        LightSample s;
        if (!sampleLight(tiny, vec3(0.0f), u, s))
        {
            ++dropped;
            continue;
        }
        ASSERT_TRUE(std::isfinite(s.pdf) && isFinite(s.wi));
        ASSERT_NEAR(s.pdf / expectedPdf, 1.0, 1e-5);
        ASSERT_NEAR(glm::length(dvec3(s.wi)), 1.0, 1e-6);
        ASSERT_LE(std::sqrt(sin2ToAxis(dvec3(s.wi), cone.axis)), std::sqrt(cone.sin2) + sinTolerance)
            << "u = (" << u.x << ", " << u.y << ")";
        ASSERT_GT(glm::dot(dvec3(s.wi), cone.axis), 0.0);
    }
    EXPECT_EQ(dropped, 0) << "of 1e5 samples declined";
    // The direction straight at the centre is in the cone whatever the rounding; directions 2, 10 and 100
    // times theta_max away are not (their cosines all round to 1 in float).
    const float pdf = lightPdf(tiny, vec3(0.0f), vec3(cone.axis));
    EXPECT_TRUE(std::isfinite(pdf));
    EXPECT_NEAR(pdf / expectedPdf, 1.0, 1e-5);
    const dvec3 side = glm::normalize(glm::cross(cone.axis, dvec3(0, 0, 1)));
    for (double angle : {2e-5, 1e-4, 1e-3})
        EXPECT_EQ(lightPdf(tiny, vec3(0.0f), vec3(std::cos(angle) * cone.axis + std::sin(angle) * side)), 0.0f)
            << angle << " rad off the axis";
}

} // namespace
} // namespace rt
