// The configurations and histogram domains of the microfacet BSDFs' chi-square tests, shared by the C++
// compilation's tests (tests/Common/MicrofacetTest.cpp) and the GPU's (tests/Gpu/GpuMicrofacetTest.cpp),
// so that both compilations of Shared/Bsdf/ are held to the same cases over the same cells. Directions are in
// the local shading frame, z the macro-normal.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "Support/LobeDomain.h"

namespace rt::test
{
/// Copper's complex index of refraction eta + i k at red, green and blue (after Johnson & Christy 1972 and
/// Rakić 1995, rounded): the conductor of the tests that need one metal.
inline const glm::vec3 kCopperEta(0.200f, 0.924f, 1.102f);
inline const glm::vec3 kCopperK(3.912f, 2.452f, 2.142f);

/// The roughnesses every sampler is tested at: 0.001 (a mirror's lobe, a milliradian wide) to 1.
extern const std::vector<float> kMicrofacetAlphas;

/// Unit direction at polar angle theta (degrees) from +z and azimuth phi: float-rounded, so that the double
/// references see exactly the direction the headers get.
glm::dvec3 direction(double thetaDegrees, double phiDegrees = 30.0);

struct DistributionCase
{
    std::string name;
    float alphaX, alphaY;
    glm::dvec3 wo;
};

/// Every roughness at normal incidence and grazing (thetaDegrees grazingPeaked for alpha <= 0.01, else
/// grazingBroad), and an anisotropic pair (0.05, 0.4) seen off its axes.
std::vector<DistributionCase> distributionCases(double grazingPeaked, double grazingBroad);
/// The conductor's: grazing at 85 degrees where the lobe is narrow (its mirror direction stays 5 degrees
/// above the plane, 40 lobe widths at alpha 0.001), 89 degrees where it is broad and meets the plane.
std::vector<DistributionCase> conductorCases();
/// The conductor's isotropic ones (glTF has no anisotropy here).
std::vector<DistributionCase> gltfCases();

struct DielectricCase
{
    std::string name;
    float alpha, ior;
    glm::dvec3 wo;
};

/// Every roughness, ior 1.5 and 1 / 1.5, wo outside (z > 0) and inside, at normal and grazing incidence (85
/// degrees for narrow lobes, 89 for broad ones, as for the conductor).
std::vector<DielectricCase> dielectricCases();

/// Where the normals visible from wo (z > 0) gather: the bisector of wo and +z in the stretched configuration
/// (where they are a cap about wo), mapped back; +z at normal incidence.
glm::dvec3 visibleAxis(const glm::dvec3& wo, double ax, double ay);

/// Cells over microfacet normals x (z > 0) seen from woUp: log rows about the visible normals' axis, as wide
/// as D (s0 = alphaX alphaY / 2), and `creases` where the density over x jumps or kinks.
LobeDomain normalCells(const glm::dvec3& woUp, double ax, double ay, std::vector<Crease> creases);

/// The directions wi on wo's side, histogrammed over the normal x (z > 0) that reflects wo into them,
/// x = +-(wo + wi) / |wo + wi|, with d omega_i = 4 |wo.x| d omega_x (Walter 2007 eq. 14). Creases: where the
/// reflection meets the horizon and where x stops facing wo.
WarpedPart reflectionPart(const glm::dvec3& wo, double ax, double ay);
/// The conductor's domain: reflections only.
WarpedDomain reflectionDomain(const glm::dvec3& wo, double ax, double ay);
/// glTF's: over the half vector as the conductor's; the log rows resolve the narrow specular lobe near the axis
/// and the diffuse one, spread over all the normals that reflect wo above the horizon, together.
WarpedDomain gltfDomain(const DistributionCase& c);

/// The directions wi across the surface from wo, histogrammed over the microfacet normal x (z > 0) that
/// refracts wo into them: the generalised half vector of wo + eta' wi (Walter 2007 eq. 16), with d omega_i =
/// (wi.x + wo.x / eta')^2 / |wi.x| d omega_x (eq. 17). Creases: where the refraction meets the horizon, where
/// x stops facing wo, and where total reflection begins.
WarpedPart refractionPart(const glm::dvec3& wo, double alpha, double ior);
/// Reflections over their normals, refractions over theirs.
WarpedDomain dielectricDomain(const DielectricCase& c);
} // namespace rt::test
