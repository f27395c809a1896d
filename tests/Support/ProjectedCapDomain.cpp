#include "Support/ProjectedCapDomain.h"

#include <algorithm>
#include <cmath>

namespace rt::test
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
}

CapGeometry capGeometry(const LightData& sphere, const vec3& p, const vec3& n)
{
    CapGeometry g;
    const glm::dvec3 c = glm::dvec3(sphere.p0) - glm::dvec3(p);
    const double d = glm::length(c);
    g.n = glm::normalize(glm::dvec3(n));
    g.axis = c / d;
    g.sinAlpha = double(sphere.radius) / d;
    g.cosAlpha = std::sqrt(1.0 - g.sinAlpha * g.sinAlpha);
    g.sinBeta = glm::dot(g.axis, g.n);
    const glm::dvec3 horizontal = g.axis - g.sinBeta * g.n;
    g.cosBeta = glm::length(horizontal);
    g.x = horizontal / g.cosBeta;
    g.y = glm::cross(g.n, g.x);
    return g;
}

double projectedSolidAngle(const CapGeometry& g)
{
    const double alpha = std::asin(g.sinAlpha), beta = std::asin(g.sinBeta);
    const auto ring = [&](double t) {
        const double a = g.sinBeta * std::cos(t), b = g.cosBeta * std::sin(t);
        double phiIntegral; // of max(0, a + b cos(phi)) over [0, 2 pi]
        if (a >= b)
            phiIntegral = 2.0 * kPi * a;
        else if (a <= -b)
            phiIntegral = 0.0;
        else
            phiIntegral = 2.0 * (a * std::acos(-a / b) + std::sqrt(b * b - a * a));
        return phiIntegral * std::sin(t);
    };
    const auto simpson = [&](double t0, double t1, bool kinkAtStart) {
        // t = t0 + (t1 - t0) s^2 when the kink is at t0: the integrand is smooth in s.
        constexpr int n = 20000;
        double sum = 0.0;
        for (int i = 0; i <= n; ++i)
        {
            const double s = double(i) / n;
            const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
            const double t = kinkAtStart ? t0 + (t1 - t0) * s * s : t0 + (t1 - t0) * s;
            const double jacobian = kinkAtStart ? 2.0 * s * (t1 - t0) : (t1 - t0);
            sum += w * ring(t) * jacobian;
        }
        return sum / (3.0 * n);
    };
    const double kink = std::fabs(beta);
    if (kink >= alpha)
        return simpson(0.0, alpha, false);
    return simpson(0.0, kink, false) + simpson(kink, alpha, true);
}

ProjectedCapDomain::ProjectedCapDomain(const CapGeometry& g, int cells) : m_g(g), m_n(cells)
{
    // Every direction of the cap is within alpha + |beta| of x: xi <= 1 - cos(alpha + |beta|).
    const double reach = std::min(kPi, std::asin(g.sinAlpha) + std::fabs(std::asin(g.sinBeta)));
    const double xiReach = 2.0 * std::sin(0.5 * reach) * std::sin(0.5 * reach);
    constexpr int scan = 200'000;
    for (int i = 0; i <= scan; ++i)
    {
        const double xi = xiReach * i / scan;
        const Chord c = chordAt(xi);
        if (c.outer >= c.inner && c.outer > 0.0)
        {
            m_xi0 = std::min(m_xi0, xi);
            m_xi1 = std::max(m_xi1, xi);
            m_yMax = std::max(m_yMax, c.outer);
        }
    }
    const double pad = xiReach / scan; // the scan's step: the region's ends lie within it
    m_xi0 = std::max(0.0, m_xi0 - pad);
    m_xi1 += pad;
    m_yMax *= 1.0 + 1e-6;
}

ProjectedCapDomain::Chord ProjectedCapDomain::chordAt(double xi) const
{
    // x cos(beta) + z sin(beta) >= cos(alpha), z = sqrt(1 - x^2 - y^2) >= 0.
    Chord c;
    const double x = 1.0 - xi;
    const double disk2 = xi * (2.0 - xi); // 1 - x^2
    if (disk2 <= 0.0)
        return c;
    const double rest = m_g.cosAlpha - x * m_g.cosBeta; // what z sin(beta) must reach
    if (m_g.sinBeta > 0.0)
    {
        const double zMin = rest / m_g.sinBeta;
        c.outer = zMin <= 0.0 ? std::sqrt(disk2) : (zMin * zMin < disk2 ? std::sqrt(disk2 - zMin * zMin) : -1.0);
        return c;
    }
    if (rest > 0.0)
        return c; // z sin(beta) <= 0 < rest
    c.outer = std::sqrt(disk2);
    if (m_g.sinBeta < 0.0)
    {
        const double zMax = rest / m_g.sinBeta; // z <= zMax
        c.inner = zMax * zMax < disk2 ? std::sqrt(disk2 - zMax * zMax) : 0.0;
    }
    return c;
}

int ProjectedCapDomain::cell(const vec3& w) const
{
    const glm::dvec3 d = glm::normalize(glm::dvec3(w));
    const double x = glm::dot(d, m_g.x), y = glm::dot(d, m_g.y), z = glm::dot(d, m_g.n);
    const double xi = (y * y + z * z) / (1.0 + x); // 1 - x without cancellation
    const int i = int(std::floor((xi - m_xi0) / (m_xi1 - m_xi0) * m_n));
    const int j = int(std::floor((y + m_yMax) / (2.0 * m_yMax) * m_n));
    return i < 0 || i >= m_n || j < 0 || j >= m_n ? -1 : j * m_n + i;
}

std::vector<double> ProjectedCapDomain::expectedCounts(long samples) const
{
    std::vector<double> mass(std::size_t(m_n) * m_n, 0.0);
    constexpr int sub = 64;
    const double dxi = (m_xi1 - m_xi0) / (m_n * sub), dy = 2.0 * m_yMax / m_n;
    double total = 0.0;
    for (int i = 0; i < m_n * sub; ++i)
    {
        const Chord c = chordAt(m_xi0 + (i + 0.5) * dxi);
        if (!(c.outer > c.inner))
            continue;
        for (int j = 0; j < m_n; ++j)
        {
            const double y0 = -m_yMax + j * dy, y1 = y0 + dy;
            const auto overlap = [&](double a, double b) { return std::max(0.0, std::min(b, y1) - std::max(a, y0)); };
            const double length = overlap(c.inner, c.outer) + overlap(-c.outer, -c.inner);
            mass[std::size_t(j) * m_n + std::size_t(i / sub)] += length * dxi;
            total += length * dxi;
        }
    }
    for (double& m : mass)
        m *= double(samples) / total;
    return mass;
}
} // namespace rt::test
