// sampleLight and lightPdf of Sampling/LightSampling.h: the directions sampleLight draws follow the density
// lightPdf reports (chi-square), each sample's pdf is lightPdf of its direction, lightPdf is a density
// (integrates to 1) that vanishes off the light, and both stay finite for a sphere 1e-5 radians wide.
// Research notes §2.1-2.3 and §1.2; the lights and points are in LightCases.h.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

#include "LightCases.h"
#include "StatisticsHelpers.h"
#include "Support/CapDomain.h"
#include "Support/ChiSquare.h"

namespace rt
{
namespace
{
using test::CapDomain;
using test::LightCase;

constexpr long kChiSquareSamples = 1'000'000;
constexpr double kPiD = 3.14159265358979323846;

/// Where the ray p + t wi (t > 0) meets the plane of a quad or triangle light, as coordinates (a, b) along
/// its edges p1, p2 (in double, by the normal equations, independent of LightSampling.h's own test).
std::optional<glm::dvec2> edgeCoordinates(const LightData& l, const dvec3& p, const dvec3& wi)
{
    const dvec3 q(l.p0), e1(l.p1), e2(l.p2);
    const dvec3 n = glm::cross(e1, e2);
    const double denom = glm::dot(n, wi);
    if (denom == 0.0)
        return std::nullopt;
    const double t = glm::dot(n, q - p) / denom;
    if (!(t > 0.0))
        return std::nullopt;
    const dvec3 r = p + t * wi - q;
    const double g11 = glm::dot(e1, e1), g12 = glm::dot(e1, e2), g22 = glm::dot(e2, e2);
    const double r1 = glm::dot(r, e1), r2 = glm::dot(r, e2);
    const double det = g11 * g22 - g12 * g12;
    return glm::dvec2((r1 * g22 - r2 * g12) / det, (r2 * g11 - r1 * g12) / det);
}

/// The light's own surface cut into n x n cells, for histogramming a planar light's directions: a cap of
/// directions around the light would have cells cut by the light's edges, where the expected count jumps;
/// a cell with a sliver of light between its quadrature points would expect 0 samples and fail outright.
/// Here every cell lies on the light and the density is smooth (research notes §2.1, second recipe).
/// Quad: cells in (a, b). Triangle: cells in (s, t) = (a, b / (1 - a)), which maps the square onto it.
/// Expected counts integrate lightPdf(w(y)) |n . w| / |y - p|^2 dA over each cell: lightPdf turned into a
/// density per unit area, so the test compares sampleLight against lightPdf and nothing else.
class LightSurfaceDomain
{
public:
    LightSurfaceDomain(const LightData& light, const vec3& p, int n) : m_light(light), m_p(p), m_n(n) {}

    int cellCount() const { return m_n * m_n; }

    /// Cell of the point a sampled direction reaches; -1 if the direction misses the light (a parameter
    /// tolerance of 1e-5 absorbs the rounding of a float direction at the light's edge).
    int cell(const vec3& wi) const
    {
        const auto ab = edgeCoordinates(m_light, m_p, dvec3(wi));
        if (!ab)
            return -1;
        constexpr double tol = 1e-5;
        const double a = ab->x, b = ab->y;
        if (a < -tol || b < -tol || b > 1.0 + tol || a > 1.0 + tol || (triangle() && a + b > 1.0 + tol))
            return -1;
        const double s = a;
        const double t = triangle() ? (a < 1.0 ? b / (1.0 - a) : 0.0) : b;
        const int i = std::clamp(int(s * m_n), 0, m_n - 1);
        const int j = std::clamp(int(t * m_n), 0, m_n - 1);
        return i * m_n + j;
    }

    std::vector<double> expectedCounts(long samples, int subdivisions) const
    {
        const dvec3 e1(m_light.p1), e2(m_light.p2);
        const dvec3 cross = glm::cross(e1, e2);
        const double parallelogramArea = glm::length(cross);
        const dvec3 normal = cross / parallelogramArea;
        const double h = 1.0 / (m_n * subdivisions);
        std::vector<double> counts(cellCount(), 0.0);
        for (int i = 0; i < m_n; ++i)
            for (int j = 0; j < m_n; ++j)
            {
                double integral = 0.0;
                for (int si = 0; si < subdivisions; ++si)
                    for (int ti = 0; ti < subdivisions; ++ti)
                    {
                        const double s = (i * subdivisions + si + 0.5) * h;
                        const double t = (j * subdivisions + ti + 0.5) * h;
                        const double b = triangle() ? t * (1.0 - s) : t;
                        const dvec3 y = dvec3(m_light.p0) + s * e1 + b * e2;
                        const double jacobian = parallelogramArea * (triangle() ? 1.0 - s : 1.0); // dA / (ds dt)
                        dvec3 w = y - dvec3(m_p);
                        const double r2 = glm::dot(w, w);
                        w /= std::sqrt(r2);
                        const double pdf = lightPdf(m_light, m_p, vec3(w));
                        integral += pdf * std::fabs(glm::dot(normal, w)) / r2 * jacobian;
                    }
                counts[i * m_n + j] = integral * h * h * double(samples);
            }
        return counts;
    }

private:
    bool triangle() const { return m_light.shape == LightShape::Triangle; }

    LightData m_light;
    vec3 m_p;
    int m_n;
};

/// Directions from p to a sphere light seen from outside: the cone about the centre, in double.
struct Cone
{
    dvec3 axis;
    double sin2; // sin^2(theta_max)
    double cosMax;
};

Cone coneOf(const LightData& sphere, const vec3& p)
{
    const dvec3 toCenter = dvec3(sphere.p0) - dvec3(p);
    const double d2 = glm::dot(toCenter, toCenter);
    const double sin2 = double(sphere.radius) * double(sphere.radius) / d2;
    return {toCenter / std::sqrt(d2), sin2, std::sqrt(1.0 - sin2)};
}

/// sin^2 of the angle between a direction and a unit axis, exact for tiny angles.
double sin2ToAxis(const dvec3& w, const dvec3& axis)
{
    const dvec3 c = glm::cross(w, axis);
    return glm::dot(c, c) / glm::dot(w, w);
}

std::vector<LightCase> allCases()
{
    std::vector<LightCase> cases = test::planarCases();
    for (const auto& list : {test::sphereOutsideCases(), test::sphereInsideCases()})
        cases.insert(cases.end(), list.begin(), list.end());
    return cases;
}

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
    // its orientation is the sphere's. Samples sampleLight declines are SamplesAreNeverDropped's business.
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

// ---- lightPdf is a density of directions that vanishes off the light -------------------------------------

TEST(LightSampling, LightPdfIntegratesToOneOverDirections)
{
    // Midpoint quadrature of lightPdf over a cap of directions around the light (400 x 800 cells, 2 x 2
    // points each). A sphere's cone ends on a row boundary (the cap is 1.25 times its 1 - cos), so only the
    // outline of a quad or triangle cuts cells, where the rule errs by part of a cell: measured below 4e-5
    // for these lights. The small sphere measures 3e-4: lightPdf puts its cone's edge at a float cos(theta_max),
    // rounded by up to 1e-3 of its 1 - cos. 1e-3 still catches a missing cosine, a wrong area or a pdf outside
    // the light. Grazing cases are left to LightPdfIntegratesToOneOverTheLight (their mass hugs the outline).
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

TEST(LightSampling, LightPdfIntegratesToOneOverTheLight)
{
    // The same integral over the directions that reach a planar light, by the change of variables to its
    // surface (dw = |n.w| dA / r^2), where the integrand is smooth even for grazing and near-field points
    // (for uniform area sampling it is the constant 1 / area, if lightPdf is right): measured within 2e-7,
    // so 1e-4 is float rounding with margin. LightPdfVanishesOffTheLight covers every other direction.
    for (const LightCase& c : test::planarCases())
    {
        const auto cells = LightSurfaceDomain(c.light, c.p, 64).expectedCounts(1, 8);
        double integral = 0.0;
        for (double x : cells)
            integral += x;
        EXPECT_NEAR(integral, 1.0, 1e-4) << c.name;
    }
}

TEST(LightSampling, LightPdfVanishesOffTheLight)
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

// ---- Robustness and the sample's other fields -------------------------------------------------------------

TEST(LightSampling, TinySphereGivesFinitePdfAndSamplesInsideTheCone)
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

TEST(LightSampling, SampleDistanceReachesTheLight)
{
    // The distance drives the shadow ray's extent: for planar lights and spheres seen from inside it is the
    // distance to the sampled point; for a sphere seen from outside the header promises a lower bound.
    for (const LightCase& c : allCases())
    {
        SCOPED_TRACE(c.name);
        Rng rng(pcgHash(700));
        for (int i = 0; i < 20'000; ++i)
        {
            LightSample s;
            if (!sampleLight(c.light, c.p, test::uniform2(rng), s))
                continue; // SamplesAreNeverDropped
            const dvec3 p(c.p), w(s.wi), center(c.light.p0);
            const dvec3 y = p + double(s.distance) * w;
            const double scale = std::max(1.0, glm::length(p) + double(s.distance)); // float rounding scales with it
            if (c.light.shape != LightShape::Sphere)
            {
                const dvec3 n(c.light.normal);
                ASSERT_NEAR(glm::dot(n, y - dvec3(c.light.p0)), 0.0, 1e-5 * scale) << "not on the light's plane";
            }
            else if (glm::distance(p, center) < c.light.radius)
                ASSERT_NEAR(glm::distance(y, center), double(c.light.radius), 1e-5 * scale) << "not on the sphere";
            else
            {
                // Near root of |p + t w - c| = R in double.
                const dvec3 f = p - center;
                const double b = glm::dot(f, w), disc = b * b - (glm::dot(f, f) - double(c.light.radius) * c.light.radius);
                const double tHit = -b - std::sqrt(std::max(disc, 0.0));
                ASSERT_GE(s.distance, 0.0f);
                ASSERT_LE(double(s.distance), tHit * (1.0 + 1e-5)) << "beyond the sphere";
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
