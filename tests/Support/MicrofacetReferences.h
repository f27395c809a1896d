// Double-precision references of the microfacet model, written from the papers, never from Shared/'s headers:
// the tests of those headers (tests/Common/MicrofacetTest.cpp) and of the renders through them
// (tests/Cpu/MicrofacetSphereTest.cpp) measure against these. Directions in the local shading frame, z the
// macro-normal, unit.
#pragma once

#include <complex>
#include <functional>

#include <glm/glm.hpp>

namespace rt::test
{
/// Smith's Lambda for GGX (Heitz 2014 §5): (-1 + sqrt(1 + alpha^2 tan^2)) / 2, alpha^2 along w's azimuth.
double lambdaRef(const glm::dvec3& w, double ax, double ay);
/// Smith's masking 1 / (1 + Lambda(w)).
double g1Ref(const glm::dvec3& w, double ax, double ay);
/// Height-correlated masking-shadowing (Heitz 2014 §6): 1 / (1 + Lambda(wo) + Lambda(wi)).
double g2Ref(const glm::dvec3& wo, const glm::dvec3& wi, double ax, double ay);

/// Unpolarised Fresnel reflectance from the complex index n = eta + i k of the far side relative to the near
/// one (Born & Wolf §1.5.2, §14.2): r_s and r_p from n cos(theta_t) = sqrt(n^2 - sin^2(theta_i)), whose
/// principal root has Re, Im >= 0 (a wave decaying into the conductor; the evanescent one under total
/// reflection).
double fresnelRef(double cosI, std::complex<double> n);

/// Directional reflectance of an isotropic GGX microfacet reflection at cos(theta_o) = mu: the integral over
/// wi above the surface of D(h) G2(wo, wi) F(wo.h) / (4 mu_o mu_i) * mu_i (Walter et al. 2007 eq. 20), taken
/// over the half vector h (d omega_i = 4 (wo.h) d omega_h) with theta_h = atan(alpha tan(beta)), so that
/// Gauss-Legendre nodes (1024^2) in beta follow D's peak at every alpha: 1e-7 absolute from alpha 0.001 to 1.
double ggxReflectanceRef(double mu, double alpha, const std::function<double(double cosOH)>& fresnel);
/// ggxReflectanceRef with F = 1: the single-scattering albedo E(mu, alpha) of the white-furnace tests.
double ggxAlbedoRef(double mu, double alpha);
} // namespace rt::test
