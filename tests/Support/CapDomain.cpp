#include "Support/CapDomain.h"

#include <algorithm>
#include <cmath>

namespace rt::test
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double kEdgeTolerance = 1e-4; // relative to the cap's extent in 1 - cos(theta)
} // namespace

CapDomain::CapDomain(const glm::dvec3& axis, double cosMin, int thetaCells, int phiCells)
    : m_axis(glm::normalize(axis)), m_cosMin(cosMin), m_thetaCells(thetaCells), m_phiCells(phiCells)
{
    const glm::dvec3 helper = std::fabs(m_axis.x) > 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    m_u = glm::normalize(glm::cross(helper, m_axis));
    m_v = glm::cross(m_axis, m_u);
}

glm::dvec3 CapDomain::toWorld(double cosTheta, double phi) const
{
    const double s = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    return s * std::cos(phi) * m_u + s * std::sin(phi) * m_v + cosTheta * m_axis;
}

int CapDomain::cell(const glm::dvec3& d) const
{
    // Rows are measured in 1 - cos(theta), taken from the sine near the axis: the cosine of a float direction
    // is quantised to 6e-8 near 1, coarser than the whole extent of a tiny cone. Lengths are divided out, so a
    // float direction a few ulps off unit length lands where its direction says.
    const double length2 = glm::dot(d, d);
    const double c = glm::dot(d, m_axis) / std::sqrt(length2);
    const glm::dvec3 x = glm::cross(d, m_axis);
    const double oneMinusCos = c > 0.0 ? glm::dot(x, x) / length2 / (1.0 + c) : 1.0 - c;
    const double extent = 1.0 - m_cosMin;
    // A sampler rounds its boundary samples by an ulp or so; Mitsuba's chi-square counts samples within 1e-4
    // of the domain's extent as inside, and so does this.
    if (oneMinusCos > extent * (1.0 + kEdgeTolerance))
        return -1;
    const int t = std::clamp(static_cast<int>((1.0 - oneMinusCos / extent) * m_thetaCells), 0, m_thetaCells - 1);
    double phi = std::atan2(glm::dot(d, m_v), glm::dot(d, m_u));
    if (phi < 0.0)
        phi += 2.0 * kPi;
    const int p = std::clamp(static_cast<int>(phi / (2.0 * kPi) * m_phiCells), 0, m_phiCells - 1);
    return t * m_phiCells + p;
}

std::vector<double> CapDomain::expectedCounts(const std::function<double(const glm::dvec3&)>& pdf, long samples,
                                              int subdivisions) const
{
    std::vector<double> counts(cellCount(), 0.0);
    const double dz = (1.0 - m_cosMin) / m_thetaCells, dphi = 2.0 * kPi / m_phiCells;
    const double subArea = (dz / subdivisions) * (dphi / subdivisions); // d(cos theta) d(phi) = steradians
    for (int t = 0; t < m_thetaCells; ++t)
        for (int p = 0; p < m_phiCells; ++p)
        {
            double integral = 0.0;
            for (int i = 0; i < subdivisions; ++i)
                for (int j = 0; j < subdivisions; ++j)
                    integral += pdf(toWorld(m_cosMin + dz * (t + (i + 0.5) / subdivisions),
                                            dphi * (p + (j + 0.5) / subdivisions)));
            counts[t * m_phiCells + p] = integral * subArea * double(samples);
        }
    return counts;
}

double CapDomain::integrate(const std::function<double(const glm::dvec3&)>& pdf, int subdivisions) const
{
    double total = 0.0;
    for (double c : expectedCounts(pdf, 1, subdivisions))
        total += c;
    return total;
}
} // namespace rt::test
