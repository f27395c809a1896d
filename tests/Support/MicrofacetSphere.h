// A rough sphere under a uniform white sky, seen through a camera so narrow (0.005 degrees, 10 units away)
// that every pixel sees the same point and normal: the image is a patch of one expected radiance, measured by
// its pixels' mean and standard error (Support/PixelStatistics.h), against the float64 integral of the BSDF
// (Support/MicrofacetReferences.h). The CPU and GPU engines render it (tests/Cpu/MicrofacetSphereTest.cpp,
// tests/Gpu/GpuMicrofacetTest.cpp).
//
// What the integral is: a convex conductor reflects every direction it scatters into the sky, once, so the
// patch's radiance is the sky's (1) times the directional reflectance R(theta_o) = the integral of f cos over
// wi, with the conductor's complex Fresnel term. A rough dielectric also refracts into the sphere; rendered at
// depth 2 (the camera ray and one more segment) only the reflected light reaches the sky, and the patch is
// R(theta_o) with the dielectric's Fresnel term.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "Image/Image.h"
#include "Scene/Scene.h"

namespace rt::test
{
struct MicrofacetSphereCase
{
    std::string name;
    bool conductor; // copper (Support's complex index) or glass of ior 1.5
    float alpha;
    double thetaDegrees; // between the patch's normal and the direction to the camera
};

/// Copper at alpha 0.05, 0.3, 0.8 and glass at 0.05 and 0.3, each at normal view and 60 degrees.
std::vector<MicrofacetSphereCase> microfacetSphereCases();

/// The scene: a unit sphere at the origin of the case's material, sky radiance 1, the camera on the patch.
Scene microfacetSphereScene(const MicrofacetSphereCase& c);

/// The depth at which the patch's radiance is the reference's: 8 for the conductor (one bounce suffices; the
/// rest checks that no path comes back), 2 for the dielectric.
int microfacetSphereDepth(const MicrofacetSphereCase& c);

/// Per RGB channel, the float64 reflectance R(theta_o) (see above).
glm::dvec3 microfacetSphereReference(const MicrofacetSphereCase& c);

/// Expects each channel's pixel mean within 4 standard errors plus 5e-4 of its reference (the patch's normals
/// spread by 1e-4 rad at 60 degrees; the float BSDF's rounding is below 1e-5).
void expectMicrofacetSphere(const Image& image, const MicrofacetSphereCase& c);
} // namespace rt::test
