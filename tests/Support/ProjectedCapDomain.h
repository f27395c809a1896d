// A sphere light's cap as a receiver sees it, in float64 and independent of Shared/Lights/ProjectedCap.h: its
// projected solid angle by quadrature over the cap, and a histogram domain over the region of the tangent
// plane the visible cap projects to, found from its definition. The chi-square tests of the projected cap
// sampler on the CPU (tests/Common/ProjectedCapTest.cpp) and on the GPU (tests/Gpu/GpuSamplerChiSquareTest.cpp)
// histogram over it.
#pragma once

#include <vector>

#include "Math/Math.h"
#include "Sampling/LightSampling.h"

namespace rt::test
{
/// The cap of a sphere light seen from p over the horizon of the unit normal n, in double: the angular
/// radius alpha and the centre's elevation beta, with the tangent-plane frame x (horizontal, towards the
/// centre), y = n x x.
struct CapGeometry
{
    glm::dvec3 axis, n, x, y;
    double sinAlpha, cosAlpha, sinBeta, cosBeta;
};

/// Precondition: p outside the sphere, the centre not straight above or below p along n.
CapGeometry capGeometry(const LightData& sphere, const vec3& p, const vec3& n);

/// Projected solid angle of the cap above the horizon (sr), by rings about the cap's axis: at angle t from it a
/// ring's cosine is sin(beta) cos(t) + cos(beta) sin(t) cos(phi), whose positive part integrates over phi in
/// closed form; Simpson's rule in t (20,000 intervals), split where the ring first meets the horizon
/// (t = |beta|), in a variable that removes the square-root kink there. Relative error below 1e-7.
double projectedSolidAngle(const CapGeometry& g);

/// n x n cells over the bounding box of the region the visible cap projects to in the tangent plane, in
/// (xi, y) with xi = 1 - x (a tiny cap's abscissae differ from 1 by less than 1e-4: xi keeps the precision
/// that x rounds away). The region from its definition: over abscissa x, the ordinates y of the unit disk whose
/// lift (x, y, sqrt(1 - x^2 - y^2)) lies within alpha of the axis. Expected counts integrate the region's
/// chords within each cell exactly in y and by 64 midpoints per cell in xi: a sampler uniform over the
/// projected region (density cos / F per unit solid angle) fills them.
class ProjectedCapDomain
{
public:
    explicit ProjectedCapDomain(const CapGeometry& g, int cells = 24);

    int cellCount() const { return m_n * m_n; }
    /// Cell of a sampled direction, -1 outside the box.
    int cell(const vec3& w) const;
    std::vector<double> expectedCounts(long samples) const;

private:
    struct Chord
    {
        double inner = 0.0, outer = -1.0; // |y| in [inner, outer]; empty when outer < inner
    };
    Chord chordAt(double xi) const;

    CapGeometry m_g;
    double m_xi0 = 2.0, m_xi1 = 0.0, m_yMax = 0.0;
    int m_n;
};
} // namespace rt::test
