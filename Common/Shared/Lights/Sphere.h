// Sphere lights, sampled and evaluated for both engines (Shared/ShaderLang.h; conventions in
// Shared/Lights/LightSample.h): book 3's sampler (the cone of directions from outside, RTTROYL §12; the whole
// surface from inside) and NEE's by LightSampler: Area (the whole surface), SolidAngle (the cone), Projected
// (the receiver's cosine over what its horizon leaves of the cap: Ureña & Georgiev 2018, Shared/Lights/
// ProjectedCap.h). Each sampler's pdf is beside it.
#ifndef RT_SHARED_LIGHTS_SPHERE_H
#define RT_SHARED_LIGHTS_SPHERE_H

#include "Shared/HostDevice.h"
#include "Shared/Lights/LightSample.h"
#include "Shared/Lights/ProjectedCap.h"
#include "Shared/Onb.h"
#include "Shared/ShaderLang.h"
#include "Shared/Warps.h"

RT_SHADER_NAMESPACE_BEGIN

/// Sphere seen from p: true if p is outside (cone sampling applies), with 1 - cos(theta_max), cos(theta_max)
/// and the unit axis towards the centre.
RT_FN bool sphereCone(RT_IN(LightData) s, vec3 p, RT_OUT(float) oneMinusCos, RT_OUT(float) cosThetaMax,
                      RT_OUT(vec3) axis)
{
    const vec3 toCenter = s.p0 - p;
    const float d2 = lengthSquared(toCenter);
    const float r2 = s.radius * s.radius;
    oneMinusCos = 0.0f;
    cosThetaMax = 1.0f;
    axis = vec3(0.0f, 0.0f, 1.0f);
    if (d2 <= r2 * 1.00001f)
        return false;
    const float sin2 = r2 / d2;
    cosThetaMax = safeSqrt(1.0f - sin2);
    oneMinusCos = sin2 / (1.0f + cosThetaMax); // = 1 - cos without cancellation (research notes §1.2)
    axis = toCenter / sqrt(d2);
    return true;
}

/// lightPdf of a sphere seen from outside, from sphereCone's cone: uniform over the cone, 0 outside it.
RT_FN float conePdf(float oneMinusCos, vec3 axis, vec3 wi)
{
    // In the cone iff the chord |wi - axis| = sqrt(2 (1 - cos)) is at most the cone's: unlike a float cosine,
    // which moves in steps of 6e-8 near 1 (coarser than a small cone's 1 - cos), the chord keeps its precision
    // at every size. The slack is the rounding of a float unit direction (4 ulps of 1 = 4 / 2^24).
    const bool inside = length(wi - axis) <= sqrt(2.0f * oneMinusCos) + 4.0f / 16777216.0f;
    return inside ? uniformConePdf(oneMinusCos) : 0.0f;
}

/// Near root of the ray p + t wi against a sphere that p is outside of, for wi inside the sphere's cone (a
/// silhouette direction that rounding puts just outside it gets the closest approach instead).
RT_FN float sphereEntryDistance(RT_IN(LightData) s, vec3 p, vec3 wi)
{
    const vec3 f = s.p0 - p;
    const float b = dot(f, wi);
    const vec3 l = f - b * wi; // closest approach (Hearn & Baker discriminant, RTG ch. 7)
    return b - safeSqrt(s.radius * s.radius - lengthSquared(l));
}

/// Far root of the ray p + t wi against a sphere that contains p (t > 0 always exists).
RT_FN float sphereExitDistance(RT_IN(LightData) s, vec3 p, vec3 wi)
{
    const vec3 f = p - s.p0;
    const float b = dot(f, wi);
    const vec3 l = f - b * wi; // closest approach (Hearn & Baker discriminant, RTG ch. 7)
    const float disc = s.radius * s.radius - lengthSquared(l);
    return -b + safeSqrt(disc);
}

/// Near root of the ray p + t wi against a sphere that p is outside of, or -1 when the ray misses it.
RT_FN float sphereNearHit(RT_IN(LightData) s, vec3 p, vec3 wi)
{
    const vec3 f = s.p0 - p;
    const float b = dot(f, wi);
    const float disc = s.radius * s.radius - lengthSquared(f - b * wi);
    if (!(disc >= 0.0f) || b <= 0.0f)
        return -1.0f;
    return b - sqrt(disc);
}

/// Book 3's solid-angle pdf of the unit direction wi from p: uniform over the cone from outside, the area density
/// of the far point wi reaches from inside.
RT_FN float sphereLightPdf(RT_IN(LightData) light, vec3 p, vec3 wi)
{
    float oneMinusCos;
    float cosThetaMax;
    vec3 axis;
    if (sphereCone(light, p, oneMinusCos, cosThetaMax, axis))
        return conePdf(oneMinusCos, axis, wi);
    const float t = sphereExitDistance(light, p, wi);
    if (!(t > 0.0f))
        return 0.0f;
    const vec3 n = (p + t * wi - light.p0) / light.radius;
    const float area = 4.0f * kPi * light.radius * light.radius;
    return areaToSolidAngle(t * t, abs(dot(n, wi)), area);
}

/// Book 3's sample: a direction uniform over the cone from outside (its pdf the cone's, a silhouette sample
/// that rounding puts outside dropped), a point uniform over the surface from inside.
RT_FN bool sampleSphereLight(RT_IN(LightData) light, vec3 p, vec2 u, RT_OUT(LightSample) ls)
{
    RT_DCHECK(light.radius > 0.0f);
    clearLightSample(light, ls);
    float oneMinusCos;
    float cosThetaMax;
    vec3 axis;
    if (sphereCone(light, p, oneMinusCos, cosThetaMax, axis))
    {
        ls.wi = onbToWorld(onbFromNormal(axis), sampleUniformCone(u, oneMinusCos));
        ls.pdf = conePdf(oneMinusCos, axis, ls.wi); // = sphereLightPdf(light, p, ls.wi), cone reused
        ls.distance = sphereEntryDistance(light, p, ls.wi);
        ls.normal = normalize(p + ls.distance * ls.wi - light.p0);
        ls.point = light.p0 + light.radius * ls.normal; // re-projected, as the engines' sphere hits are
        return keepLightSample(ls);
    }
    ls.normal = sampleUniformSphere(u);
    ls.point = light.p0 + light.radius * ls.normal;
    if (!lightSampleDirection(p, ls))
        return false;
    ls.pdf = sphereLightPdf(light, p, ls.wi);
    return keepLightSample(ls);
}

/// NEE's solid-angle pdf of wi from p with receiver normal n (0 in a medium) by `strategy`: Projected, cos / F
/// over what the horizon of n leaves of the cap, F its projected solid angle (0 elsewhere; book 3's from
/// inside the sphere or in a medium); Area, the area density of the point wi reaches first (the near side)
/// from outside; else book 3's.
RT_FN float sphereLightPdf(RT_IN(LightData) light, RT_TAG(LightSampler) strategy, vec3 p, vec3 n, vec3 wi)
{
    if (strategy == RT_ENUM(LightSampler, Projected) || strategy == RT_ENUM(LightSampler, ProjectedExact))
    {
        ProjectedCap cap;
        const uint kind = projectedCap(light, p, n, cap);
        if (kind == kCapBelow)
            return 0.0f;
        if (kind != kCapNotApplicable)
        {
            float oneMinusCos;
            float cosThetaMax;
            vec3 axis;
            sphereCone(light, p, oneMinusCos, cosThetaMax, axis);
            const float cosine = dot(n, wi);
            return conePdf(oneMinusCos, axis, wi) > 0.0f && cosine > 0.0f ? cosine / cap.area : 0.0f;
        }
    }
    if (strategy == RT_ENUM(LightSampler, Area) && lengthSquared(p - light.p0) > light.radius * light.radius)
    {
        const float t = sphereNearHit(light, p, wi);
        if (!(t > 0.0f))
            return 0.0f;
        const vec3 sphereNormal = (p + t * wi - light.p0) / light.radius;
        return areaToSolidAngle(t * t, abs(dot(sphereNormal, wi)), light.area);
    }
    return sphereLightPdf(light, p, wi);
}

/// NEE's sample from p by `strategy`, with the density sphereLightPdf(light, strategy, p, n, .) reports.
/// Projected: uniform over the projected visible cap (sampleProjectedCap), density cos / F; false, a sample of
/// zero contribution, for a cap wholly below the horizon. Area from outside: the whole surface; a point on the
/// far side faces away from p and returns false, likewise.
RT_FN bool sampleSphereLight(RT_IN(LightData) light, RT_TAG(LightSampler) strategy, vec3 p, vec3 n, vec2 u,
                             RT_OUT(LightSample) ls)
{
    if (strategy == RT_ENUM(LightSampler, Projected) || strategy == RT_ENUM(LightSampler, ProjectedExact))
    {
        ProjectedCap cap;
        const uint kind = projectedCap(light, p, n, cap);
        if (kind != kCapNotApplicable)
        {
            clearLightSample(light, ls);
            if (kind == kCapBelow)
                return false;
            ls.wi = sampleProjectedCap(cap, n, u);
            ls.distance = sphereEntryDistance(light, p, ls.wi);
            ls.normal = normalize(p + ls.distance * ls.wi - light.p0);
            ls.point = light.p0 + light.radius * ls.normal;
            // cos / F, the density of the construction: a rim sample that rounding moved a few ulps out of the
            // cone (where the pdf's chord test says 0: 3 in 1e6 for a cap of 1e-3 rad) keeps it rather than
            // being dropped; the two differ only on that rim, a set of no measure.
            ls.pdf = max(dot(n, ls.wi), 0.0f) / cap.area;
            return keepLightSample(ls);
        }
    }
    if (strategy == RT_ENUM(LightSampler, Area) && lengthSquared(p - light.p0) > light.radius * light.radius)
    {
        ls.uv = vec2(0.0f);
        ls.outcome = 0u; // a point on the far side, pdf 0, is a sample of no contribution, not one declined
        ls.normal = sampleUniformSphere(u);
        ls.point = light.p0 + light.radius * ls.normal;
        const vec3 w = ls.point - p;
        ls.distance = length(w);
        ls.wi = w / ls.distance;
        const float cosLight = -dot(ls.normal, ls.wi);
        ls.pdf = cosLight > 0.0f ? areaToSolidAngle(ls.distance * ls.distance, cosLight, light.area) : 0.0f;
        return ls.pdf > 0.0f;
    }
    return sampleSphereLight(light, p, u, ls);
}

RT_SHADER_NAMESPACE_END

#endif
