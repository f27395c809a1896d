// Sampling directions towards one light of the scene's world-space light list, and the solid-angle pdf of
// any direction under that strategy. Both are needed by the book-3 mixture (RTTROYL §9-12): the pdf of a
// direction must be evaluated for every light, whichever strategy produced the direction.
// The GLSL twin is Shaders/Sampling/LightSampling.glsl.
//
// Conventions: `p` is the shading point (world space), `wi` a unit direction leaving p, pdfs are per unit
// solid angle at p. A pdf is 0 for a direction that cannot be produced (misses the light), never a guess.
#pragma once

#include "Math/Math.h"
#include "Math/Onb.h"
#include "Math/PlaneDuals.h"
#include "Sampling/Warps.h"
#include "Shared/HostDevice.h"

namespace rt
{
using shader::LightData;
using shader::LightShape;

struct LightSample
{
    vec3 wi{0.0f}; // unit direction from p towards the sampled point
    float pdf = 0.0f; // per unit solid angle
    float distance = 0.0f; // from p to the sampled point on the light
};

namespace detail
{
/// Area-measure pdf 1/area turned into solid angle at distance `dist` with |cos| at the light.
inline float areaToSolidAngle(float dist2, float cosLight, float area)
{
    return cosLight > 0.0f ? dist2 / (cosLight * area) : 0.0f;
}

/// Sphere seen from p: true if p is outside (cone sampling applies), with 1 - cos(theta_max) and cos(theta_max).
inline bool sphereCone(const LightData& s, const vec3& p, float& oneMinusCos, float& cosThetaMax, vec3& axis)
{
    const vec3 toCenter = s.p0 - p;
    const float d2 = lengthSquared(toCenter);
    const float r2 = s.radius * s.radius;
    if (d2 <= r2 * 1.00001f)
        return false;
    const float sin2 = r2 / d2;
    cosThetaMax = safeSqrt(1.0f - sin2);
    oneMinusCos = sin2 / (1.0f + cosThetaMax); // = 1 - cos without cancellation (research notes §1.2)
    axis = toCenter / std::sqrt(d2);
    return true;
}

/// lightPdf of a sphere seen from outside, from sphereCone's cone: uniform over the cone, 0 outside it.
inline float conePdf(float oneMinusCos, const vec3& axis, const vec3& wi)
{
    // In the cone iff the chord |wi - axis| = sqrt(2 (1 - cos)) is at most the cone's: unlike a float cosine,
    // which moves in steps of 6e-8 near 1 (coarser than a small cone's 1 - cos), the chord keeps its precision
    // at every size. The slack is the rounding of a float unit direction (4 ulps of 1).
    const bool inside = glm::length(wi - axis) <= std::sqrt(2.0f * oneMinusCos) + 4.0f * 0x1p-24f;
    return inside ? uniformConePdf(oneMinusCos) : 0.0f;
}
/// Far root of the ray p + t wi against a sphere that contains p (t > 0 always exists).
inline float sphereExitDistance(const LightData& s, const vec3& p, const vec3& wi)
{
    const vec3 f = p - s.p0;
    const float b = glm::dot(f, wi);
    const vec3 l = f - b * wi; // closest approach (Hearn & Baker discriminant, RTG ch. 7)
    const float disc = s.radius * s.radius - lengthSquared(l);
    return -b + safeSqrt(disc);
}

/// Parametric hit of the ray p + t wi with the parallelogram / triangle of `light`; returns t or -1.
inline float planarHit(const LightData& light, const vec3& p, const vec3& wi)
{
    const float denom = glm::dot(light.normal, wi);
    if (std::fabs(denom) < 1e-9f)
        return -1.0f;
    const float t = glm::dot(light.normal, light.p0 - p) / denom;
    if (!(t > 0.0f))
        return -1.0f;
    const vec3 planar = p + t * wi - light.p0;
    const float alpha = glm::dot(planar, light.dualU);
    const float beta = glm::dot(planar, light.dualV);
    // A few ulps of slack: a sample on the light's edge (u = 1) must find its own pdf after rounding
    // (sampleLight takes its pdf from here), and the border it adds has no measure worth a bias.
    constexpr float lo = -1e-6f, hi = 1.0f + 1e-6f;
    if (light.shape == LightShape::Quad)
        return (alpha >= lo && alpha <= hi && beta >= lo && beta <= hi) ? t : -1.0f;
    return (alpha >= lo && beta >= lo && alpha + beta <= hi) ? t : -1.0f;
}
} // namespace detail

/// A quad light: the parallelogram q + a u + b v (a, b in [0, 1]), front along u x v.
inline LightData makeQuadLight(const vec3& q, const vec3& u, const vec3& v, std::uint32_t material)
{
    LightData l{};
    l.shape = LightShape::Quad;
    l.material = material;
    l.p0 = q;
    l.p1 = u;
    l.p2 = v;
    const vec3 n = glm::cross(u, v);
    l.area = glm::length(n);
    l.normal = n / l.area;
    const PlaneDuals duals = planeDuals(u, v);
    l.dualU = duals.ua;
    l.dualV = duals.vb;
    return l;
}

/// A triangle light with vertices a, b, c (front along (b - a) x (c - a)).
inline LightData makeTriangleLight(const vec3& a, const vec3& b, const vec3& c, std::uint32_t material)
{
    LightData l = makeQuadLight(a, b - a, c - a, material);
    l.shape = LightShape::Triangle;
    l.area *= 0.5f;
    return l;
}

/// A sphere light (or sampling target with material kNoIndex).
inline LightData makeSphereLight(const vec3& center, float radius, std::uint32_t material)
{
    LightData l{};
    l.shape = LightShape::Sphere;
    l.material = material;
    l.p0 = center;
    l.radius = radius;
    l.area = 4.0f * kPi * radius * radius;
    return l;
}

/// Solid-angle pdf with which sampleLight(light, p, .) produces the unit direction `wi`; 0 if it cannot.
inline float lightPdf(const LightData& light, const vec3& p, const vec3& wi)
{
    if (light.shape == LightShape::Sphere)
    {
        float oneMinusCos, cosThetaMax;
        vec3 axis;
        if (detail::sphereCone(light, p, oneMinusCos, cosThetaMax, axis))
            return detail::conePdf(oneMinusCos, axis, wi);
        const float t = detail::sphereExitDistance(light, p, wi);
        if (!(t > 0.0f))
            return 0.0f;
        const vec3 n = (p + t * wi - light.p0) / light.radius;
        const float area = 4.0f * kPi * light.radius * light.radius;
        return detail::areaToSolidAngle(t * t, std::fabs(glm::dot(n, wi)), area);
    }
    const float t = detail::planarHit(light, p, wi);
    if (t < 0.0f)
        return 0.0f;
    return detail::areaToSolidAngle(t * t, std::fabs(glm::dot(light.normal, wi)), light.area);
}
/// Samples a direction from p towards `light` with uniform-area (quad, triangle, sphere seen from inside) or
/// uniform-cone (sphere seen from outside) density. The pdf it returns is lightPdf(light, p, wi) itself, so
/// a sample and the pdf of its direction can never disagree: a direction that rounding puts outside the light
/// (p in the light's own plane, a cone sample on the silhouette) is dropped instead of being weighted by a pdf
/// the mixture's other terms cannot see (that mismatch biased a closed-box furnace by +0.7 %).
/// Returns false when no direction can be produced.
inline bool sampleLight(const LightData& light, const vec3& p, const vec2& u, LightSample& out)
{
    vec3 y;
    if (light.shape == LightShape::Sphere)
    {
        float oneMinusCos, cosThetaMax;
        vec3 axis;
        if (detail::sphereCone(light, p, oneMinusCos, cosThetaMax, axis))
        {
            out.wi = Onb(axis).toWorld(sampleUniformCone(u, oneMinusCos));
            out.distance = glm::length(light.p0 - p) - light.radius; // lower bound; the mixture needs no more
            out.pdf = detail::conePdf(oneMinusCos, axis, out.wi); // = lightPdf(light, p, out.wi), cone reused
            return out.pdf > 0.0f;
        }
        y = light.p0 + light.radius * sampleUniformSphere(u);
    }
    else if (light.shape == LightShape::Quad)
        y = light.p0 + u.x * light.p1 + u.y * light.p2;
    else
    {
        const vec2 b = sampleUniformTriangle(u);
        y = light.p0 + b.x * light.p1 + b.y * light.p2; // p1, p2 are edges from p0
    }
    const vec3 w = y - p;
    const float dist2 = lengthSquared(w);
    if (!(dist2 > 0.0f))
        return false;
    out.distance = std::sqrt(dist2);
    out.wi = w / out.distance;
    out.pdf = lightPdf(light, p, out.wi);
    return out.pdf > 0.0f;
}

} // namespace rt
