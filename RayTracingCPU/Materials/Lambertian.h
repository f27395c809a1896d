#pragma once

#include "Math/Onb.h"
#include "Sampling/Warps.h"

namespace rt::cpu
{
/// Ideal diffuse reflection about the shading normal `ns` (facing the incoming ray): cosine-weighted
/// direction (RTTROYL §8). Its pdf equals the scattering pdf cos/pi, so the weight is the albedo.
inline vec3 sampleLambertian(const vec3& ns, const vec2& u) { return Onb(ns).toWorld(sampleCosineHemisphere(u)); }

/// Scattering pdf of a Lambertian surface per steradian (RTTROYL's scattering_pdf): cos(theta)/pi, 0 below.
inline float lambertianPdf(const vec3& ns, const vec3& wi) { return cosineHemispherePdf(glm::dot(ns, wi)); }
} // namespace rt::cpu
