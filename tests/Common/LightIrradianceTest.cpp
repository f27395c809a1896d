// Direct lighting through the light samplers against closed forms: the irradiance E = ∫ L max(0, n.w) dw at
// a point, estimated as the mean of L max(0, n.wi) / pdf over sampleLight's samples, must match research
// notes §4.1 (sphere), §4.3 (rectangle parallel to the receiver) and Lambert's polygon formula (§4.2).
// A wrong pdf scale, a missing cosine or a sampler that misses part of the light all shift the mean.
// The suite is not named DirectLighting: rt_cpu_tests has one, and ctest names must be unique.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "Render/RenderSettings.h"
#include "Support/LightCases.h"
#include "Support/StatisticsHelpers.h"

namespace rt
{
namespace
{
constexpr double kPiD = 3.14159265358979323846;
constexpr long kSamples = 1 << 18;
constexpr float kRadiance = 1.0f; // L; E is then the projected solid angle

/// The receiver: at the origin, facing +z.
const dvec3 kNormal(0.0, 0.0, 1.0);

/// Mean of L max(0, n.wi) / pdf from the origin over sampleLight (book 3's, or NEE's `strategy`), with its
/// standard error.
test::MeanEstimate estimateIrradiance(const LightData& light, std::uint32_t seed,
                                      std::optional<LightSampler> strategy = std::nullopt)
{
    Rng rng(pcgHash(seed));
    return test::estimateMean(kSamples, [&](long) {
        LightSample s;
        const vec2 u = test::uniform2(rng);
        if (!(strategy ? sampleLight(light, *strategy, vec3(0.0f), vec3(kNormal), u, s)
                       : sampleLight(light, vec3(0.0f), u, s)))
            return 0.0;
        return double(kRadiance) * std::max(0.0, glm::dot(kNormal, dvec3(s.wi))) / double(s.pdf);
    });
}

/// Book 3's samplers, then NEE's three: each must find the same irradiance.
const std::optional<LightSampler> kStrategies[] = {std::nullopt, LightSampler::Area, LightSampler::SolidAngle,
                                                   LightSampler::Projected};

std::string nameOf(std::optional<LightSampler> strategy)
{
    return strategy ? toString(*strategy) : "book 3";
}

/// Within 3 standard errors (the brief's criterion; each configuration is one fixed-seed draw), plus 1e-5
/// relative for the float rounding of the pdf and directions (single ulps, 1e-7).
void expectIrradiance(const test::MeanEstimate& e, double expected, const std::string& what)
{
    EXPECT_NEAR(e.mean, expected, 3.0 * e.standardError + 1e-5 * expected)
        << what << ": expected " << expected << ", estimate " << e.mean << " +- " << e.standardError;
    EXPECT_GT(e.standardError, 0.0) << what; // a zero spread would mean the estimator saw no samples
}

// ---- Sphere (§4.1) ----------------------------------------------------------------------------------------

/// Projected solid angle of a sphere whose centre is at angle theta from the normal and subtends sin(alpha)
/// = R / d: pi sin^2(alpha) cos(theta) when fully above the horizon, else the form of the Frostbite course
/// notes (Lagarde & de Rousiers 2014), research notes §4.1 (checked there against 4M-sample Monte Carlo).
double sphereProjectedSolidAngle(double sinAlpha, double theta)
{
    const double s2 = sinAlpha * sinAlpha, c = std::cos(theta), s = std::sin(theta);
    if (c * c > s2)
        return kPiD * s2 * std::max(0.0, c);
    const double x = std::sqrt(1.0 / s2 - 1.0);
    const double y = -x * c / s;
    return (c * std::acos(y) - x * s * std::sqrt(1.0 - y * y)) * s2 + std::atan(s * std::sqrt(1.0 - y * y) / x);
}

/// A sphere of radius R with centre at distance d, at angle theta from +z (and azimuth 40 degrees, so that
/// nothing lines up with an axis).
LightData sphereAt(double radius, double distance, double thetaDegrees)
{
    const double theta = thetaDegrees * kPiD / 180.0, phi = 40.0 * kPiD / 180.0;
    const dvec3 dir(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    return test::makeSphereLight(vec3(distance * dir), float(radius));
}

TEST(LightIrradiance, SphereAboveTheHorizon)
{
    struct Case
    {
        double radius, distance, thetaDegrees;
    };
    // Mid-distance, near field (alpha = 56 degrees) and far (a point light in all but name).
    std::uint32_t seed = 1;
    for (const Case& c : {Case{1.0, 4.0, 30.0}, Case{1.0, 1.2, 20.0}, Case{0.5, 50.0, 60.0}, Case{2.0, 5.0, 0.0}})
    {
        const double sinAlpha = c.radius / c.distance;
        const double theta = c.thetaDegrees * kPiD / 180.0;
        ASSERT_LE(theta, kPiD / 2 - std::asin(sinAlpha)) << "the case must be fully above the horizon";
        // E = pi L (R/d)^2 cos(theta): the closed form, written out rather than through the helper.
        const double expected = kPiD * kRadiance * sinAlpha * sinAlpha * std::cos(theta);
        for (const auto strategy : kStrategies)
            expectIrradiance(estimateIrradiance(sphereAt(c.radius, c.distance, c.thetaDegrees), seed++, strategy),
                             expected,
                             nameOf(strategy) + ": R " + std::to_string(c.radius) + ", d " +
                                 std::to_string(c.distance) + ", theta " + std::to_string(c.thetaDegrees));
    }
}

TEST(LightIrradiance, SphereStraddlingTheHorizon)
{
    struct Case
    {
        double sinAlpha, thetaDegrees;
    };
    // Centre above, on and below the horizon, for a small and a large sphere (|cos theta| < sin alpha each).
    std::uint32_t seed = 11;
    for (const Case& c : {Case{0.3, 80.0}, Case{0.3, 100.0}, Case{0.7, 60.0}, Case{0.7, 90.0}, Case{0.7, 120.0}})
    {
        const double theta = c.thetaDegrees * kPiD / 180.0;
        ASSERT_LT(std::cos(theta) * std::cos(theta), c.sinAlpha * c.sinAlpha) << "the case must straddle";
        const double expected = kRadiance * sphereProjectedSolidAngle(c.sinAlpha, theta);
        for (const auto strategy : kStrategies)
            expectIrradiance(estimateIrradiance(sphereAt(1.0, 1.0 / c.sinAlpha, c.thetaDegrees), seed++, strategy),
                             expected,
                             nameOf(strategy) + ": sin(alpha) " + std::to_string(c.sinAlpha) + ", theta " +
                                 std::to_string(c.thetaDegrees));
    }
}

// ---- Rectangle parallel to the receiver (§4.3) ------------------------------------------------------------

/// Form factor from a differential area to an a x b rectangle at height c, parallel to it, with one corner
/// straight above it (research notes §4.3).
double cornerRectangleFormFactor(double a, double b, double c)
{
    const double A = a / c, B = b / c;
    const double sa = std::sqrt(1.0 + A * A), sb = std::sqrt(1.0 + B * B);
    return (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb)) / (2.0 * kPiD);
}

TEST(LightIrradiance, RectangleWithACornerAbove)
{
    struct Case
    {
        double a, b, c;
    };
    // An ordinary one, and one 20 times wider than high: directions reach down to 3 degrees above the horizon.
    std::uint32_t seed = 21;
    for (const Case& c : {Case{1.0, 2.0, 1.0}, Case{1.0, 1.0, 0.05}, Case{3.0, 0.5, 2.0}})
    {
        const LightData quad = test::makeQuadLight({0.0f, 0.0f, float(c.c)}, {float(c.a), 0, 0}, {0, float(c.b), 0});
        const double expected = kRadiance * kPiD * cornerRectangleFormFactor(c.a, c.b, c.c);
        for (const auto strategy : kStrategies)
            expectIrradiance(estimateIrradiance(quad, seed++, strategy), expected,
                             nameOf(strategy) + ": " + std::to_string(c.a) + " x " + std::to_string(c.b) + " at " +
                                 std::to_string(c.c));
    }
}

TEST(LightIrradiance, RectangleCentredAbove)
{
    // Four corner rectangles meet under the point: by superposition E = 4 pi L F(a/2, b/2, c).
    const LightData quad = test::makeQuadLight({-0.5f, -1.0f, 0.7f}, {0, 2, 0}, {1, 0, 0}); // faces down
    const double expected = kRadiance * 4.0 * kPiD * cornerRectangleFormFactor(0.5, 1.0, 0.7);
    std::uint32_t seed = 31;
    for (const auto strategy : kStrategies)
        expectIrradiance(estimateIrradiance(quad, seed++, strategy), expected, nameOf(strategy) + ": 1 x 2 centred at 0.7");
}

// ---- Polygons by Lambert's formula (§4.2) -----------------------------------------------------------------

/// Projected solid angle of a polygon wholly above the receiver's horizon, seen from the origin:
/// 1/2 |sum_i Theta_i (n . Gamma_i)| with Theta_i the angle between consecutive vertex directions and Gamma_i
/// the unit normal of the plane through them (Lambert, as written by Arvo; research notes §4.2).
double lambertProjectedSolidAngle(const std::vector<dvec3>& vertices)
{
    double sum = 0.0;
    for (std::size_t i = 0; i < vertices.size(); ++i)
    {
        const dvec3 u0 = glm::normalize(vertices[i]);
        const dvec3 u1 = glm::normalize(vertices[(i + 1) % vertices.size()]);
        const dvec3 c = glm::cross(u0, u1);
        const double theta = std::atan2(glm::length(c), glm::dot(u0, u1));
        sum += theta * glm::dot(kNormal, glm::normalize(c));
    }
    return 0.5 * std::fabs(sum);
}

TEST(LightIrradiance, LambertFormulaMatchesTheRectangleFormula)
{
    // The reference of the next test checked against the §4.3 closed form (research notes: equal to 1e-8).
    const double lambert = lambertProjectedSolidAngle({{0, 0, 1}, {1, 0, 1}, {1, 2, 1}, {0, 2, 1}});
    EXPECT_NEAR(lambert, kPiD * cornerRectangleFormFactor(1.0, 2.0, 1.0), 1e-9);
}

TEST(LightIrradiance, TriangleAndGrazingQuad)
{
    struct Case
    {
        std::string name;
        LightData light;
        std::vector<dvec3> vertices; // in order around the polygon
    };
    const vec3 a(-0.5f, 0.2f, 1.0f), b(1.0f, 0.5f, 1.5f), c(0.2f, 1.5f, 0.7f);
    const vec3 gq(1.0f, -1.0f, 0.05f), gu(2.0f, 0.0f, 0.0f), gv(0.0f, 2.0f, 0.0f);
    const vec3 ta(2.0f, -1.0f, 0.03f), tb(3.0f, 1.0f, 0.03f), tc(2.0f, 1.0f, 0.03f);
    const std::vector<Case> cases = {
        {"tilted triangle", test::makeTriangleLight(a, b, c), {dvec3(a), dvec3(b), dvec3(c)}},
        // Low and to the side: every direction within 3 degrees of the horizon, and of the light's plane.
        {"grazing quad", test::makeQuadLight(gq, gu, gv), {dvec3(gq), dvec3(gq + gu), dvec3(gq + gu + gv), dvec3(gq + gv)}},
        {"grazing triangle", test::makeTriangleLight(ta, tb, tc), {dvec3(ta), dvec3(tb), dvec3(tc)}},
    };
    std::uint32_t seed = 41;
    for (const Case& k : cases)
    {
        const double expected = kRadiance * lambertProjectedSolidAngle(k.vertices);
        for (const auto strategy : kStrategies)
            expectIrradiance(estimateIrradiance(k.light, seed++, strategy), expected, nameOf(strategy) + ": " + k.name);
    }
}
TEST(LightIrradiance, TrianglesForTheSphericalSampler)
{
    // Triangles Arvo's sampler takes (3e-4 to 6.22 sr), where it replaced area sampling: a 355 x 10 sliver 4
    // units overhead and 300 units away, a triangle 0.5 above the point that fills 6.07 sr of the hemisphere,
    // and one of 3.6e-4 sr. Area, solid-angle and projected sampling must each find Lambert's irradiance.
    struct Case
    {
        std::string name;
        vec3 a, b, c;
    };
    const std::vector<Case> cases = {
        {"sliver overhead", {-150, -2, 4}, {205, -2, 4}, {205, 8, 4}},
        {"sliver across the room", {177, -200, 300}, {-178, -200, 300}, {-178, -190, 310}},
        {"near hemisphere", {-20, -12, 0.5f}, {20, -12, 0.5f}, {0, 25, 0.5f}},
        {"tiny", {0.3f, 0.2f, 1.0f}, {0.33f, 0.2f, 1.01f}, {0.31f, 0.23f, 0.99f}},
    };
    std::uint32_t seed = 51;
    for (const Case& k : cases)
    {
        const double expected = kRadiance * lambertProjectedSolidAngle({dvec3(k.a), dvec3(k.b), dvec3(k.c)});
        const LightData light = test::makeTriangleLight(k.a, k.b, k.c);
        for (const auto strategy : kStrategies)
            expectIrradiance(estimateIrradiance(light, seed++, strategy), expected,
                             nameOf(strategy) + ": " + k.name);
    }
}
} // namespace
} // namespace rt
