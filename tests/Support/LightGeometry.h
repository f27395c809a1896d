// Geometry the light-sampling tests measure with, in double and independent of LightSampling.h: where a
// direction meets a planar light, a histogram domain on a planar light's own surface, and a sphere's cone.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

#include "Support/LightCases.h"
#include "Support/StatisticsHelpers.h"

namespace rt::test
{
inline constexpr double kPiD = 3.14159265358979323846;

/// Where the ray p + t wi (t > 0) meets the plane of a quad or triangle light, as coordinates (a, b) along
/// its edges p1, p2 (in double, by the normal equations, independent of LightSampling.h's own test).
inline std::optional<glm::dvec2> edgeCoordinates(const LightData& l, const dvec3& p, const dvec3& wi)
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

    /// Histogram of `samples` points that NEE's `strategy` samples from the domain's point with receiver normal
    /// n (fixed `seed`); a refused sample, or one off the light, counts as outside.
    Histogram sampleHistogram(LightSampler strategy, const vec3& n, long samples, std::uint32_t seed) const
    {
        return histogram(cellCount(), samples, seed, [&](Rng& rng) {
            LightSample s;
            return sampleLight(m_light, strategy, m_p, n, uniform2(rng), s) ? cell(s.wi) : -1;
        });
    }

    /// Expected samples per cell when `samples` are drawn with the density lightPdf reports: book 3's, or
    /// that of `strategy` when given.
    std::vector<double> expectedCounts(long samples, int subdivisions,
                                       std::optional<LightSampler> strategy = std::nullopt,
                                       const vec3& receiverNormal = vec3(0.0f)) const
    {
        return expectedCounts(samples, subdivisions, [&](const dvec3& w) {
            return strategy ? double(lightPdf(m_light, *strategy, m_p, receiverNormal, vec3(w)))
                            : double(lightPdf(m_light, m_p, vec3(w)));
        });
    }

    /// Expected samples per cell for a density over directions (per steradian) given by the test itself.
    /// A cell whose quadrature points all have density 0 but which borders a cell with samples expected (the
    /// density's support ends inside it: a receiver's horizon across a near light) is integrated again with 8x
    /// the subdivisions, so that the sliver of support between its points is not expected empty.
    std::vector<double> expectedCounts(long samples, int subdivisions,
                                       const std::function<double(const dvec3&)>& solidAnglePdf) const
    {
        std::vector<double> counts(cellCount(), 0.0);
        for (int i = 0; i < m_n; ++i)
            for (int j = 0; j < m_n; ++j)
                counts[i * m_n + j] = cellIntegral(i, j, subdivisions, solidAnglePdf) * double(samples);
        std::vector<double> refined = counts;
        for (int i = 0; i < m_n; ++i)
            for (int j = 0; j < m_n; ++j)
            {
                if (counts[i * m_n + j] > 0.0)
                    continue;
                const bool bordersSupport = (i > 0 && counts[(i - 1) * m_n + j] > 0.0) ||
                                            (i + 1 < m_n && counts[(i + 1) * m_n + j] > 0.0) ||
                                            (j > 0 && counts[i * m_n + j - 1] > 0.0) ||
                                            (j + 1 < m_n && counts[i * m_n + j + 1] > 0.0);
                if (bordersSupport)
                    refined[i * m_n + j] = cellIntegral(i, j, 8 * subdivisions, solidAnglePdf) * double(samples);
            }
        return refined;
    }

private:
    bool triangle() const { return m_light.shape == LightShape::Triangle; }

    /// The probability of cell (i, j) under the density: the midpoint rule with subdivisions^2 points.
    double cellIntegral(int i, int j, int subdivisions, const std::function<double(const dvec3&)>& solidAnglePdf) const
    {
        const dvec3 e1(m_light.p1), e2(m_light.p2);
        const dvec3 cross = glm::cross(e1, e2);
        const double parallelogramArea = glm::length(cross);
        const dvec3 normal = cross / parallelogramArea;
        const double h = 1.0 / (m_n * subdivisions);
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
                integral += solidAnglePdf(w) * std::fabs(glm::dot(normal, w)) / r2 * jacobian;
            }
        return integral * h * h;
    }

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

inline Cone coneOf(const LightData& sphere, const vec3& p)
{
    const dvec3 toCenter = dvec3(sphere.p0) - dvec3(p);
    const double d2 = glm::dot(toCenter, toCenter);
    const double sin2 = double(sphere.radius) * double(sphere.radius) / d2;
    return {toCenter / std::sqrt(d2), sin2, std::sqrt(1.0 - sin2)};
}

/// sin^2 of the angle between a direction and a unit axis, exact for tiny angles.
inline double sin2ToAxis(const dvec3& w, const dvec3& axis)
{
    const dvec3 c = glm::cross(w, axis);
    return glm::dot(c, c) / glm::dot(w, w);
}

/// Every light case: planar, spheres from outside and from inside.
inline std::vector<LightCase> allCases()
{
    std::vector<LightCase> cases = planarCases();
    for (const auto& list : {sphereOutsideCases(), sphereInsideCases()})
        cases.insert(cases.end(), list.begin(), list.end());
    return cases;
}
} // namespace rt::test
