// Directions cut into cells for chi-square tests of BSDF samplers whose lobes may be 1e-3 rad wide and may
// meet the horizon (tests/Common/MicrofacetTest.cpp).
//
// LobeDomain: on each side of the plane z = 0 at most one cap: rows about the cap's axis (a lobe's centre),
// columns of phi about it, and only the directions on its side. Rows are uniform in log(1 + s / s0),
// s = 1 - cos(angle to the axis): a lobe of angular width w (s0 = w^2 / 2) is resolved however narrow, and a
// broad one about the same axis with it, where cells of equal solid angle (CapDomain) would put a narrow lobe
// all in one. Expected counts come from Gauss-Legendre quadrature along radial lines cut where the density
// jumps or kinks (the horizon and the `creases`): exact to 1e-8 of the samples even for a lobe 1e-3 wide cut
// by the horizon, where the midpoint rule of CapDomain is off by 1e-4.
//
// WarpedDomain: cells over directions made of parts, each histogrammed through a map into its own LobeDomain.
// A microfacet lobe seen from grazing wo is a ridge a hundred times longer than wide over wi, but as round as
// D over its half vectors: each scattering mode is histogrammed over the microfacet normal that produces it,
// its expected counts the integral of the pdf over wi written over that normal with the map's Jacobian.
//
// One more cell takes every direction no cap or part holds, and every failed sample: its expectation is the
// samples the pdf leaves out.
#pragma once

#include <functional>
#include <vector>

#include <glm/glm.hpp>

namespace rt::test
{
/// The half of the sphere a cap covers: Upper is z >= 0, Lower is z < 0.
enum class Side
{
    Upper,
    Lower
};

struct LobeCap
{
    glm::dvec3 axis; // an axis with x = y = 0 is a pole: the cap is exactly its hemisphere
    double scale;    // s0 of the rows, about half the lobe's squared angular width; 0 for rows of equal area
    Side side;
    int rows = 40;
    int columns = 64;
};

/// Gauss-Legendre nodes and weights of order n on [0, 1].
void gaussLegendre(int n, std::vector<double>& x, std::vector<double>& w);

/// A function on the sphere whose zero set is where a density to integrate jumps or kinks.
using Crease = std::function<double(const glm::dvec3&)>;

class LobeDomain
{
public:
    /// The horizon (z = 0) is always a crease.
    explicit LobeDomain(std::vector<LobeCap> caps, std::vector<Crease> creases = {});

    int cellCount() const { return m_cellCount + 1; }
    /// The last cell: directions on a side without a cap; tests add their failed samples to it.
    int otherCell() const { return m_cellCount; }
    /// Cell of a direction (unit up to float rounding).
    int cell(const glm::dvec3& direction) const;
    /// Integral of f over each cell but the other one: Gauss-Legendre, subdivisions^2 nodes a cell, along
    /// radial lines cut at the creases' sign changes, and over parts of each column small enough that those
    /// cuts move by less than a quarter row between their ends.
    std::vector<double> cellIntegrals(const std::function<double(const glm::dvec3&)>& f,
                                      int subdivisions = 8) const;
    /// Expected counts of `samples` draws from a density per steradian; the other cell gets the rest of
    /// `samples` (0 if the cells already hold them all up to quadrature error).
    std::vector<double> expectedCounts(const std::function<double(const glm::dvec3&)>& pdf, long samples,
                                       int subdivisions = 8) const;
    double integrate(const std::function<double(const glm::dvec3&)>& f, int subdivisions = 8) const;

private:
    struct Cap
    {
        LobeCap spec;
        glm::dvec3 u, v;
        double extent;  // 1 - cos of the cap's radius: 1 for a pole's hemisphere, 2 for the whole sphere
        double tExtent; // mapped extent
        int firstCell;
    };

    double mapped(const Cap& cap, double s) const;
    /// s and ds/dT at the mapped coordinate T in [0, 1].
    void sAt(const Cap& cap, double T, double& s, double& dsdT) const;
    glm::dvec3 pointAt(const Cap& cap, const glm::dvec3& e, double T) const;
    /// The mapped coordinates T in (0, 1), ascending, where a crease changes sign along the radial line
    /// towards e (sampled at every row's ends, then bisected).
    void cuts(const Cap& cap, const glm::dvec3& e, std::vector<double>& roots) const;

    std::vector<Cap> m_caps;
    std::vector<Crease> m_creases; // the horizon's, then the caller's
    int m_cellCount = 0;
};

/// One part of a WarpedDomain.
struct WarpedPart
{
    LobeDomain cells;
    /// The point of `cells` a direction maps to; false for a direction of another part.
    std::function<bool(const glm::dvec3& direction, glm::dvec3& x)> toCells;
    /// The direction at a point of `cells` and |d omega_direction / d omega_x|; false where no direction of
    /// this part maps.
    std::function<bool(const glm::dvec3& x, glm::dvec3& direction, double& jacobian)> fromCells;
};

class WarpedDomain
{
public:
    explicit WarpedDomain(std::vector<WarpedPart> parts);

    int cellCount() const { return m_cellCount + 1; }
    int otherCell() const { return m_cellCount; }
    /// Cell of a direction: in the first part that takes it.
    int cell(const glm::dvec3& direction) const;
    /// Expected counts of `samples` draws from a density per steradian of direction.
    std::vector<double> expectedCounts(const std::function<double(const glm::dvec3&)>& pdf, long samples,
                                       int subdivisions = 8) const;
    /// Integral of f over the directions the parts take.
    double integrate(const std::function<double(const glm::dvec3&)>& f, int subdivisions = 8) const;

private:
    std::vector<double> cellIntegrals(const std::function<double(const glm::dvec3&)>& f,
                                      int subdivisions) const;

    std::vector<WarpedPart> m_parts;
    std::vector<int> m_firstCell;
    int m_cellCount = 0;
};
} // namespace rt::test
