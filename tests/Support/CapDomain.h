// A spherical cap (all directions within an angle of an axis) cut into cells equal in solid angle: rows of
// cos(theta) about the axis times columns of phi. With cosMin = -1 it is the whole sphere. Chi-square tests
// of direction samplers histogram over it; a small light gets a cap just around it so its cells are not
// swamped by empty ones.
#pragma once

#include <functional>
#include <vector>

#include <glm/glm.hpp>

namespace rt::test
{
class CapDomain
{
public:
    CapDomain(const glm::dvec3& axis, double cosMin, int thetaCells, int phiCells);

    int cellCount() const { return m_thetaCells * m_phiCells; }
    /// Cell of a direction (unit up to float rounding), or -1 outside the cap. Directions outside by less than
    /// 1e-4 of the cap's extent in 1 - cos(theta) (a sampler's rounding at its edge) count in the edge row.
    int cell(const glm::dvec3& direction) const;
    /// Expected counts for `samples` draws from a density per steradian (midpoint rule, subdivisions^2
    /// points per cell).
    std::vector<double> expectedCounts(const std::function<double(const glm::dvec3&)>& pdf, long samples,
                                       int subdivisions = 8) const;
    /// Integral of the density over the cap.
    double integrate(const std::function<double(const glm::dvec3&)>& pdf, int subdivisions = 8) const;

private:
    glm::dvec3 toWorld(double cosTheta, double phi) const;

    glm::dvec3 m_axis, m_u, m_v;
    double m_cosMin;
    int m_thetaCells, m_phiCells;
};
} // namespace rt::test
