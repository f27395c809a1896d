// Quad and triangle lights, what their samplers share (both engines, Shared/ShaderLang.h; conventions in
// Shared/Lights/LightSample.h): where a direction meets the light, and book 3's uniform-area sampler with its pdf
// (RTTNW §6, RTTROYL §12), which NEE's samplers fall back to (Lights/Quad.h, Lights/Triangle.h). One code for both
// shapes: the mixture evaluates it for every light at every vertex, where a GPU's threads disagree on the shape.
#ifndef RT_SHARED_LIGHTS_PLANAR_H
#define RT_SHARED_LIGHTS_PLANAR_H

#include "Shared/HostDevice.h"
#include "Shared/Lights/LightSample.h"
#include "Shared/ShaderLang.h"
#include "Shared/Warps.h"

RT_SHADER_NAMESPACE_BEGIN

/// Whether the edge coordinates (alpha, beta) lie on the quad ([0, 1]^2) or triangle (alpha, beta >= 0,
/// alpha + beta <= 1), give or take the slacks sa (alpha), sb (beta) and sab (alpha + beta, triangles).
/// Without branches: the mixture evaluates it for every light at every vertex, where a GPU's threads disagree.
RT_FN bool onPlanarLight(RT_TAG(LightShape) shape, float alpha, float beta, float sa, float sb, float sab)
{
    const bool quadInside = alpha <= 1.0f + sa && beta <= 1.0f + sb;
    const bool triangleInside = alpha + beta <= 1.0f + sab;
    return alpha >= -sa && beta >= -sb && (RT_LIGHT_IS(shape, Quad) ? quadInside : triangleInside);
}

/// Parametric hit of the ray p + t wi with the parallelogram / triangle of `light`; returns t or -1.
RT_FN float planarHit(RT_IN(LightData) light, vec3 p, vec3 wi)
{
    // Computed through to one select at the end, without early returns (4 % of book 3's mixture on the H100):
    // a direction along the plane (denom near 0) or away from it (t <= 0, or NaN) gives -1 there.
    const float denom = dot(light.normal, wi);
    const float height = dot(light.normal, light.p0 - p);
    const float t = height / denom;
    const bool ahead = abs(denom) >= 1e-9f && t > 0.0f;
    const vec3 planar = p + t * wi - light.p0;
    const float alpha = dot(planar, light.dualU);
    const float beta = dot(planar, light.dualV);
    // A sample on the light's edge must find its own pdf here after rounding (the samplers' pdfs are this
    // one's, or must agree with it). 1e-6 of slack covers a light seen from near by; a point sampled on the
    // edge of a sliver seen from afar comes back from its float direction a few ulps of the distances
    // involved away, more at grazing incidence (the ray slides along the plane by t / cos): 4 ulps of them,
    // turned into edge coordinates by the duals' lengths (1 / the light's heights, stored with the light). The
    // border added has no measure worth a bias: 2e-4 of a 3-unit sliver's height seen across a room. Each
    // slack is at least 1e-6, so this one test accepts whatever a tight test first would: a tight test and a
    // second one behind a branch cost the H100 9 % of book 3's mixture on cornell-box-lights.
    // t / |denom| from height, not from t: the slack need not wait for t's division.
    const float slack = 2.4e-7f * (height / (denom * abs(denom)) + length(p) + light.p0Length);
    const float slackAlpha = 1e-6f + slack * light.dualULength;
    const float slackBeta = 1e-6f + slack * light.dualVLength;
    const float slackSum = 1e-6f + slack * light.dualSumLength;
    return ahead && onPlanarLight(light.shape, alpha, beta, slackAlpha, slackBeta, slackSum) ? t : -1.0f;
}

/// Book 3's solid-angle pdf of the unit direction wi from p: the area density of the point wi reaches.
RT_FN float planarLightPdf(RT_IN(LightData) light, vec3 p, vec3 wi)
{
    const float t = planarHit(light, p, wi);
    if (t < 0.0f)
        return 0.0f;
    return areaToSolidAngle(t * t, abs(dot(light.normal, wi)), light.area);
}

/// Book 3's sample: a point uniform over the light's area (edge coordinates u of a quad, barycentrics of a
/// triangle), its pdf planarLightPdf of its direction, so a sample and its pdf never disagree: a direction that
/// rounding puts off the light (p in the light's own plane) is dropped.
RT_FN bool samplePlanarLight(RT_IN(LightData) light, vec3 p, vec2 u, RT_OUT(LightSample) ls)
{
    clearLightSample(light, ls);
    if (RT_LIGHT_IS(light.shape, Quad))
    {
        ls.uv = u;
        ls.point = light.p0 + u.x * light.p1 + u.y * light.p2;
    }
    else
    {
        ls.uv = sampleUniformTriangle(u);
        ls.point = light.p0 + ls.uv.x * light.p1 + ls.uv.y * light.p2; // p1, p2 are edges from p0
    }
    if (!lightSampleDirection(p, ls))
        return false;
    ls.pdf = planarLightPdf(light, p, ls.wi);
    return keepLightSample(ls);
}

RT_SHADER_NAMESPACE_END

#endif
