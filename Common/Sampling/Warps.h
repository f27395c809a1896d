// Warps from the unit square to the domains the renderers sample. Each returns a point in the domain's local
// frame and has a matching pdf; densities are per unit solid angle (directions) or per unit area (points).
// The GLSL twins are in Shaders/Sampling/Warps.glsl. Tested by chi-square in tests/Common/WarpsTest.cpp.
#pragma once

#include <cmath>

#include "Math/Math.h"

namespace rt
{
/// sin and cos of 2 pi u for u in [0, 1]: quadrant reduction, then Taylor polynomials on [-pi/4, pi/4]
/// (degree 7 and 8: absolute error below 4e-7). Sampling needs no more, and libm's sincosf was a tenth of a
/// diffuse bounce. The GLSL twins call the hardware sin/cos.
inline void sinCos2Pi(float u, float& s, float& c)
{
    const float u4 = 4.0f * u;
    const float quadrant = std::nearbyint(u4);
    const float t = (u4 - quadrant) * (kPi / 2.0f); // in [-pi/4, pi/4]
    const float t2 = t * t;
    const float st = t * (1.0f + t2 * (-1.0f / 6.0f + t2 * (1.0f / 120.0f + t2 * (-1.0f / 5040.0f))));
    const float ct = 1.0f + t2 * (-0.5f + t2 * (1.0f / 24.0f + t2 * (-1.0f / 720.0f + t2 * (1.0f / 40320.0f))));
    switch (static_cast<int>(quadrant) & 3)
    {
    case 0: s = st, c = ct; break;
    case 1: s = ct, c = -st; break;
    case 2: s = -st, c = -ct; break;
    default: s = -ct, c = st; break;
    }
}

/// Cosine-weighted direction about +z (Malley's method: uniform disk point lifted to the hemisphere).
/// pdf = cos(theta) / pi per steradian; 0 below the horizon.
inline vec3 sampleCosineHemisphere(const vec2& u)
{
    float sinPhi, cosPhi;
    sinCos2Pi(u.x, sinPhi, cosPhi);
    const float r = std::sqrt(u.y);
    return {r * cosPhi, r * sinPhi, std::sqrt(1.0f - u.y)};
}
inline float cosineHemispherePdf(float cosTheta) { return cosTheta > 0.0f ? cosTheta * kInvPi : 0.0f; }

/// Uniform direction on the unit sphere (Archimedes' hat-box). pdf = 1 / (4 pi) per steradian.
inline vec3 sampleUniformSphere(const vec2& u)
{
    const float z = 1.0f - 2.0f * u.x;
    const float r = safeSqrt(1.0f - z * z);
    float sinPhi, cosPhi;
    sinCos2Pi(u.y, sinPhi, cosPhi);
    return {r * cosPhi, r * sinPhi, z};
}
inline constexpr float uniformSpherePdf() { return kInv4Pi; }

/// Uniform direction in the cone of half-angle theta_max about +z, given 1 - cos(theta_max) (> 0) computed
/// without cancellation by the caller: sin^2 / (1 + cos). Research notes §1.2: cos(theta) = 1 - u m,
/// sin^2(theta) = m (2 - m) with m = u (1 - cos(theta_max)), exact for tiny cones.
/// pdf = 1 / (2 pi (1 - cos(theta_max))) per steradian.
inline vec3 sampleUniformCone(const vec2& u, float oneMinusCosThetaMax)
{
    const float m = u.x * oneMinusCosThetaMax;
    const float cosTheta = 1.0f - m;
    const float sinTheta = safeSqrt(m * (2.0f - m));
    float sinPhi, cosPhi;
    sinCos2Pi(u.y, sinPhi, cosPhi);
    return {sinTheta * cosPhi, sinTheta * sinPhi, cosTheta};
}
inline float uniformConePdf(float oneMinusCosThetaMax) { return 1.0f / (2.0f * kPi * oneMinusCosThetaMax); }

/// Uniform point on a triangle as barycentrics (b0, b1); b2 = 1 - b0 - b1. Square-root parameterisation
/// (Turk, Graphics Gems I, 1990). pdf = 1 / area.
inline vec2 sampleUniformTriangle(const vec2& u)
{
    const float s = std::sqrt(u.x);
    return {1.0f - s, u.y * s};
}

/// Uniform point on the unit disk, concentric map (Shirley & Chiu, "A Low Distortion Map Between Disk and
/// Square", JGT 2(3), 1997). pdf = 1 / pi per unit area.
inline vec2 sampleUniformDiskConcentric(const vec2& u)
{
    const vec2 o = 2.0f * u - vec2(1.0f);
    if (o.x == 0.0f && o.y == 0.0f)
        return vec2(0.0f);
    float r, theta;
    if (std::fabs(o.x) > std::fabs(o.y))
    {
        r = o.x;
        theta = (kPi / 4.0f) * (o.y / o.x);
    }
    else
    {
        r = o.y;
        theta = (kPi / 2.0f) - (kPi / 4.0f) * (o.x / o.y);
    }
    return r * vec2(std::cos(theta), std::sin(theta));
}
} // namespace rt
