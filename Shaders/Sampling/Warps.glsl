// Warps from the unit square to the domains the renderer samples: the twins of Common/Sampling/Warps.h,
// function by function. Directions in the domain's local frame; pdfs per steradian or per unit area.
#ifndef RT_WARPS_GLSL
#define RT_WARPS_GLSL

#include "Math/Constants.glsl"

/// Cosine-weighted direction about +z (Malley's method). pdf = cos(theta) / pi.
vec3 sampleCosineHemisphere(vec2 u)
{
    float phi = 2.0 * kPi * u.x;
    float r = sqrt(u.y);
    return vec3(r * cos(phi), r * sin(phi), sqrt(1.0 - u.y));
}

float cosineHemispherePdf(float cosTheta)
{
    return cosTheta > 0.0 ? cosTheta * kInvPi : 0.0;
}

/// Uniform direction on the unit sphere (Archimedes' hat-box). pdf = 1 / (4 pi).
vec3 sampleUniformSphere(vec2 u)
{
    float z = 1.0 - 2.0 * u.x;
    float r = safeSqrt(1.0 - z * z);
    float phi = 2.0 * kPi * u.y;
    return vec3(r * cos(phi), r * sin(phi), z);
}

float uniformSpherePdf()
{
    return kInv4Pi;
}

/// Uniform direction in the cone about +z with 1 - cos(theta_max) given without cancellation
/// (research notes §1.2). pdf = 1 / (2 pi (1 - cos(theta_max))).
vec3 sampleUniformCone(vec2 u, float oneMinusCosThetaMax)
{
    float m = u.x * oneMinusCosThetaMax;
    float cosTheta = 1.0 - m;
    float sinTheta = safeSqrt(m * (2.0 - m));
    float phi = 2.0 * kPi * u.y;
    return vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

float uniformConePdf(float oneMinusCosThetaMax)
{
    return 1.0 / (2.0 * kPi * oneMinusCosThetaMax);
}

/// Uniform point on a triangle as barycentrics (b0, b1) (Turk, Graphics Gems I, 1990). pdf = 1 / area.
vec2 sampleUniformTriangle(vec2 u)
{
    float s = sqrt(u.x);
    return vec2(1.0 - s, u.y * s);
}

/// Uniform point on the unit disk, concentric map (Shirley & Chiu, JGT 2(3), 1997). pdf = 1 / pi.
vec2 sampleUniformDiskConcentric(vec2 u)
{
    vec2 o = 2.0 * u - vec2(1.0);
    if (o.x == 0.0 && o.y == 0.0)
        return vec2(0.0);
    float r;
    float theta;
    if (abs(o.x) > abs(o.y))
    {
        r = o.x;
        theta = (kPi / 4.0) * (o.y / o.x);
    }
    else
    {
        r = o.y;
        theta = (kPi / 2.0) - (kPi / 4.0) * (o.x / o.y);
    }
    return r * vec2(cos(theta), sin(theta));
}

#endif
