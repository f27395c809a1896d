// Directions towards one light of the scene's world-space light list and the solid-angle pdf of any
// direction under that strategy: the twins of Common/Sampling/LightSampling.h (RTTROYL §9-12).
// p is the shading point (world space), wi a unit direction leaving p; a pdf is 0 for a direction the
// strategy cannot produce.
#ifndef RT_LIGHT_SAMPLING_GLSL
#define RT_LIGHT_SAMPLING_GLSL

#include "Shared/HostDevice.h"
#include "Math/Constants.glsl"
#include "Math/Onb.glsl"
#include "Shared/Warps.h"

struct LightSample
{
    vec3 wi; // unit direction from p towards the sampled point
    float pdf; // per unit solid angle
    float distance; // from p to the sampled point (a lower bound for cone-sampled spheres)
};

/// Area-measure pdf 1/area turned into solid angle at squared distance dist2 with |cos| at the light.
float areaToSolidAngle(float dist2, float cosLight, float area)
{
    return cosLight > 0.0 ? dist2 / (cosLight * area) : 0.0;
}

/// Sphere seen from p: true if p is outside (cone sampling applies), with 1 - cos(theta_max) and cos(theta_max).
bool sphereCone(LightData s, vec3 p, out float oneMinusCos, out float cosThetaMax, out vec3 axis)
{
    vec3 toCenter = s.p0 - p;
    float d2 = lengthSquared(toCenter);
    float r2 = s.radius * s.radius;
    oneMinusCos = 0.0;
    cosThetaMax = 1.0;
    axis = vec3(0.0, 0.0, 1.0);
    if (d2 <= r2 * 1.00001)
        return false;
    float sin2 = r2 / d2;
    cosThetaMax = safeSqrt(1.0 - sin2);
    oneMinusCos = sin2 / (1.0 + cosThetaMax); // = 1 - cos without cancellation
    axis = toCenter / sqrt(d2);
    return true;
}

/// Far root of p + t wi against a sphere that contains p (Hearn & Baker discriminant, RTG ch. 7).
float sphereExitDistance(LightData s, vec3 p, vec3 wi)
{
    vec3 f = p - s.p0;
    float b = dot(f, wi);
    vec3 l = f - b * wi;
    float disc = s.radius * s.radius - lengthSquared(l);
    return -b + safeSqrt(disc);
}

/// Parametric hit of p + t wi with the parallelogram / triangle of `light`; t or -1.
float planarHit(LightData light, vec3 p, vec3 wi)
{
    float denom = dot(light.normal, wi);
    if (abs(denom) < 1e-9)
        return -1.0;
    float t = dot(light.normal, light.p0 - p) / denom;
    if (!(t > 0.0))
        return -1.0;
    vec3 planar = p + t * wi - light.p0;
    float alpha = dot(planar, light.dualU);
    float beta = dot(planar, light.dualV);
    // A few ulps of slack, as in Common: a sample on the light's edge must find its own pdf after rounding.
    const float lo = -1e-6, hi = 1.0 + 1e-6;
    if (light.shape == LightShape_Quad)
        return (alpha >= lo && alpha <= hi && beta >= lo && beta <= hi) ? t : -1.0;
    return (alpha >= lo && beta >= lo && alpha + beta <= hi) ? t : -1.0;
}

/// lightPdf of a sphere seen from outside, from sphereCone's cone: uniform over the cone, 0 outside it.
float conePdf(float oneMinusCos, vec3 axis, vec3 wi)
{
    // In the cone iff the chord |wi - axis| = sqrt(2 (1 - cos)) is at most the cone's: a float cosine moves in
    // steps of 6e-8 near 1, coarser than a small cone's 1 - cos; the chord keeps its precision. The slack is
    // the rounding of a float unit direction (4 ulps of 1).
    bool inside = length(wi - axis) <= sqrt(2.0 * oneMinusCos) + 4.0 / 16777216.0;
    return inside ? uniformConePdf(oneMinusCos) : 0.0;
}

/// Solid-angle pdf with which sampleLight(light, p, .) produces the unit direction wi; 0 if it cannot.
float lightPdf(LightData light, vec3 p, vec3 wi)
{
    if (light.shape == LightShape_Sphere)
    {
        float oneMinusCos;
        float cosThetaMax;
        vec3 axis;
        if (sphereCone(light, p, oneMinusCos, cosThetaMax, axis))
            return conePdf(oneMinusCos, axis, wi);
        float t = sphereExitDistance(light, p, wi);
        if (!(t > 0.0))
            return 0.0;
        vec3 n = (p + t * wi - light.p0) / light.radius;
        float area = 4.0 * kPi * light.radius * light.radius;
        return areaToSolidAngle(t * t, abs(dot(n, wi)), area);
    }
    float t = planarHit(light, p, wi);
    if (t < 0.0)
        return 0.0;
    return areaToSolidAngle(t * t, abs(dot(light.normal, wi)), light.area);
}

/// Samples a direction from p towards `light`: uniform cone for a sphere seen from outside, uniform area
/// otherwise. The pdf is lightPdf(light, p, wi) itself, so a sample and the pdf of its direction never
/// disagree: a direction that rounding puts outside the light is dropped. False when no direction results.
bool sampleLight(LightData light, vec3 p, vec2 u, out LightSample ls)
{
    ls.wi = vec3(0.0);
    ls.pdf = 0.0;
    ls.distance = 0.0;
    vec3 y;
    if (light.shape == LightShape_Sphere)
    {
        float oneMinusCos;
        float cosThetaMax;
        vec3 axis;
        if (sphereCone(light, p, oneMinusCos, cosThetaMax, axis))
        {
            ls.wi = onbToWorld(onbFromNormal(axis), sampleUniformCone(u, oneMinusCos));
            ls.distance = length(light.p0 - p) - light.radius; // a lower bound; the mixture needs no more
            ls.pdf = conePdf(oneMinusCos, axis, ls.wi); // = lightPdf(light, p, ls.wi), cone reused
            return ls.pdf > 0.0;
        }
        y = light.p0 + light.radius * sampleUniformSphere(u);
    }
    else if (light.shape == LightShape_Quad)
        y = light.p0 + u.x * light.p1 + u.y * light.p2;
    else
    {
        vec2 b = sampleUniformTriangle(u);
        y = light.p0 + b.x * light.p1 + b.y * light.p2; // p1, p2 are edges from p0
    }
    vec3 w = y - p;
    float dist2 = lengthSquared(w);
    if (!(dist2 > 0.0))
        return false;
    ls.distance = sqrt(dist2);
    ls.wi = w / ls.distance;
    ls.pdf = lightPdf(light, p, ls.wi);
    return ls.pdf > 0.0;
}

#endif
