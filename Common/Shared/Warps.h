// Warps from the unit square to the domains the renderers sample, written once for both engines (C++ and
// GLSL: Shared/ShaderLang.h). Each returns a point in the domain's local frame and has a matching pdf;
// densities are per unit solid angle (directions) or per unit area (points). Tested by chi-square in
// tests/Common/WarpsTest.cpp; the GPU's compilation of the same code against the CPU's in
// tests/Gpu/ShaderParityTest.cpp.
#ifndef RT_SHARED_WARPS_H
#define RT_SHARED_WARPS_H

#include "Shared/HostDevice.h"
#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

/// sin and cos of 2 pi u for u in [0, 1]. On the CPU: quadrant reduction, then Taylor polynomials on
/// [-pi/4, pi/4] (degree 7 and 8: absolute error below 4e-7), as libm's sincosf was a tenth of a diffuse
/// bounce. On the GPU: the hardware's sin and cos, one instruction each; the polynomial's quadrant switch
/// cost an H200 8 % of cornell-box-lights' time (docs/notebook/PERFORMANCE.md). Vulkan guarantees them to 2^-11
/// absolute only; the parity test bounds what the devices really do.
RT_FN void sinCos2Pi(float u, RT_OUT(float) s, RT_OUT(float) c)
{
#ifdef __cplusplus
    const float u4 = 4.0f * u;
    const float quadrant = roundEven(u4);
    const float t = (u4 - quadrant) * (kPi / 2.0f); // in [-pi/4, pi/4]
    const float t2 = t * t;
    const float st = t * (1.0f + t2 * (-1.0f / 6.0f + t2 * (1.0f / 120.0f + t2 * (-1.0f / 5040.0f))));
    const float ct = 1.0f + t2 * (-0.5f + t2 * (1.0f / 24.0f + t2 * (-1.0f / 720.0f + t2 * (1.0f / 40320.0f))));
    switch (int(quadrant) & 3)
    {
    case 0:
        s = st;
        c = ct;
        break;
    case 1:
        s = ct;
        c = -st;
        break;
    case 2:
        s = -st;
        c = -ct;
        break;
    default:
        s = -ct;
        c = st;
        break;
    }
#else
    const float phi = 2.0f * kPi * u;
    s = sin(phi);
    c = cos(phi);
#endif
}

/// Cosine-weighted direction about +z (Malley's method: uniform disk point lifted to the hemisphere).
/// pdf = cos(theta) / pi per steradian; 0 below the horizon.
RT_FN vec3 sampleCosineHemisphere(vec2 u)
{
    float sinPhi;
    float cosPhi;
    sinCos2Pi(u.x, sinPhi, cosPhi);
    const float r = sqrt(u.y);
    return vec3(r * cosPhi, r * sinPhi, sqrt(1.0f - u.y));
}

RT_FN float cosineHemispherePdf(float cosTheta) { return cosTheta > 0.0f ? cosTheta * kInvPi : 0.0f; }

/// Uniform direction on the unit sphere (Archimedes' hat-box). pdf = 1 / (4 pi) per steradian.
RT_FN vec3 sampleUniformSphere(vec2 u)
{
    const float z = 1.0f - 2.0f * u.x;
    const float r = safeSqrt(1.0f - z * z);
    float sinPhi;
    float cosPhi;
    sinCos2Pi(u.y, sinPhi, cosPhi);
    return vec3(r * cosPhi, r * sinPhi, z);
}

RT_FN float uniformSpherePdf() { return kInv4Pi; }

/// Uniform direction in the cone of half-angle theta_max about +z, given 1 - cos(theta_max) (> 0) computed
/// without cancellation by the caller: sin^2 / (1 + cos). Research notes §1.2: cos(theta) = 1 - u m,
/// sin^2(theta) = m (2 - m) with m = u (1 - cos(theta_max)), exact for tiny cones.
/// pdf = 1 / (2 pi (1 - cos(theta_max))) per steradian.
RT_FN vec3 sampleUniformCone(vec2 u, float oneMinusCosThetaMax)
{
    const float m = u.x * oneMinusCosThetaMax;
    const float cosTheta = 1.0f - m;
    const float sinTheta = safeSqrt(m * (2.0f - m));
    float sinPhi;
    float cosPhi;
    sinCos2Pi(u.y, sinPhi, cosPhi);
    return vec3(sinTheta * cosPhi, sinTheta * sinPhi, cosTheta);
}

RT_FN float uniformConePdf(float oneMinusCosThetaMax) { return 1.0f / (2.0f * kPi * oneMinusCosThetaMax); }

/// Uniform point on a triangle as barycentrics (b0, b1); b2 = 1 - b0 - b1. Square-root parameterisation
/// (Turk, Graphics Gems I, 1990). pdf = 1 / area.
RT_FN vec2 sampleUniformTriangle(vec2 u)
{
    const float s = sqrt(u.x);
    return vec2(1.0f - s, u.y * s);
}

/// Uniform point on the unit disk, concentric map (Shirley & Chiu, "A Low Distortion Map Between Disk and
/// Square", JGT 2(3), 1997). pdf = 1 / pi per unit area.
RT_FN vec2 sampleUniformDiskConcentric(vec2 u)
{
    const vec2 o = 2.0f * u - vec2(1.0f);
    if (o.x == 0.0f && o.y == 0.0f)
        return vec2(0.0f);
    float r;
    float theta;
    if (abs(o.x) > abs(o.y))
    {
        r = o.x;
        theta = (kPi / 4.0f) * (o.y / o.x);
    }
    else
    {
        r = o.y;
        theta = (kPi / 2.0f) - (kPi / 4.0f) * (o.x / o.y);
    }
    return r * vec2(cos(theta), sin(theta));
}

/// The largest float below 1 (1 - 2^-24), where a sample of [0, 1) must stay after rounding.
RT_CONST(float, kOneMinusEpsilon, 0.99999994f)

/// x in [0, 1] with density proportional to the line from a (at 0) to b (at 1), a, b >= 0 not both 0: the
/// inverse of its cumulative (a x + (b - a) x^2 / 2) / ((a + b) / 2), written as u (a + b) / (a + sqrt(lerp(u,
/// a^2, b^2))) to stay exact when a = b (pbrt-v4 §A.4.2 derives the same form).
RT_FN float sampleLinear(float u, float a, float b)
{
    if (u == 0.0f && a == 0.0f)
        return 0.0f;
    const float x = u * (a + b) / (a + sqrt((1.0f - u) * a * a + u * b * b));
    return min(x, kOneMinusEpsilon);
}

/// A point of [0, 1]^2 with density proportional to the bilinear interpolation of the corner weights w00 (at
/// (0, 0)), w10, w01, w11: u from its marginal, then v given u (pbrt-v4's SampleBilinear takes v first; the
/// density is the same). The weights are >= 0 and not all 0.
RT_FN vec2 sampleBilinear(vec2 u, float w00, float w10, float w01, float w11)
{
    // x first: the spherical samplers that warp their u by this one start from u.x (a rectangle's sin and cos of
    // its cut, a triangle's area split), so their setup need not wait for v's square root and division.
    const float x = sampleLinear(u.x, w00 + w01, w10 + w11);
    const float v = sampleLinear(u.y, (1.0f - x) * w00 + x * w10, (1.0f - x) * w01 + x * w11);
    return vec2(x, v);
}

/// Density of sampleBilinear at p, per unit area of the square.
RT_FN float bilinearPdf(vec2 p, float w00, float w10, float w01, float w11)
{
    const float total = w00 + w10 + w01 + w11;
    if (!(total > 0.0f))
        return 1.0f;
    const float value = (1.0f - p.x) * (1.0f - p.y) * w00 + p.x * (1.0f - p.y) * w10 + (1.0f - p.x) * p.y * w01 +
                        p.x * p.y * w11;
    return 4.0f * value / total;
}

RT_SHADER_NAMESPACE_END

#endif
