// Triangle lights for NEE (both engines, Shared/ShaderLang.h; conventions in Shared/Lights/LightSample.h):
// between kMinSphericalTriangle and kMaxSphericalTriangle sr by Arvo's spherical triangle map (Arvo 1995,
// "Stratified Sampling of Spherical Triangles", SIGGRAPH; Shared/SphericalTriangle.h), uniform over the solid
// angle (SolidAngle) or warped first by a bilinear fit of the receiver's cosine at the vertices (Projected: Hart
// et al. 2020; pbrt-v4 §6.5.4); outside them and with Area by book 3's area sampler (Lights/Planar.h). Each
// sampler's pdf is beside it.
#ifndef RT_SHARED_LIGHTS_TRIANGLE_H
#define RT_SHARED_LIGHTS_TRIANGLE_H

#include "Shared/HostDevice.h"
#include "Shared/Lights/LightSample.h"
#include "Shared/Lights/Planar.h"
#include "Shared/ShaderLang.h"
#include "Shared/SphericalTriangle.h"
#include "Shared/Warps.h"

RT_SHADER_NAMESPACE_BEGIN

/// Triangles are sampled by solid angle (Arvo 1995) between these solid angles (sr), by area outside them
/// (pbrt-v4's bounds, §6.5.4): below, a light this small looks the same to both strategies, and float
/// trigonometry of sub-triangles this thin is where GPUs differ most (Vulkan bounds sin and cos to 2^-11
/// absolute only); above, the triangle fills nearly the whole hemisphere and Arvo's denominators approach 0.
RT_CONST(float, kMinSphericalTriangle, 3e-4f)
RT_CONST(float, kMaxSphericalTriangle, 6.22f)

/// A triangle seen from p within the spherical triangle sampler's bounds, set up in `t`.
RT_FN bool sphericalTriangleApplies(RT_IN(LightData) light, vec3 p, RT_OUT(SphericalTriangle) t)
{
    if (!RT_LIGHT_IS(light.shape, Triangle))
        return false;
    t = makeSphericalTriangle(p, light.p0, light.p1, light.p2);
    return t.solidAngle >= Real(kMinSphericalTriangle) && t.solidAngle <= Real(kMaxSphericalTriangle);
}

/// The bilinear cosine warp's corner weights for a spherical triangle (pbrt-v4 §6.5.4, after Hart et al.
/// 2020): the cosine to the receiver normal n of the vertex directions, floored at 0.01 as the rectangle's,
/// at the corners of u where Arvo's map puts them: (w00, w10, w01, w11) = (B, B, A, C), since u.y = 0 is
/// the vertex B for every u.x and u.y = 1 runs from A (u.x = 0) to C (u.x = 1). pbrt takes |cos| as its
/// normal may face either way; here n faces the side the receiver takes light from (NEE's BSDF is 0 on the
/// other), so a vertex below its horizon gets the floor, as in rectangleCosineWeights.
RT_FN vec4 triangleCosineWeights(RT_IN(SphericalTriangle) t, vec3 n)
{
    const RealVec3 normal = RealVec3(n);
    const float wa = float(max(dot(normal, t.a), 0.01));
    const float wb = float(max(dot(normal, t.b), 0.01));
    const float wc = float(max(dot(normal, t.c), 0.01));
    return vec4(wb, wb, wa, wc);
}

/// NEE's solid-angle pdf of wi from p with receiver normal n (0 in a medium) by `strategy`: within the spherical
/// sampler's bounds 1 / S (SolidAngle, or no receiver), or the bilinear cosine warp's density at the direction's
/// u (Arvo's map inverted) over 1 / S (Projected); else the area density.
RT_FN float triangleLightPdf(RT_IN(LightData) light, RT_TAG(LightSampler) strategy, vec3 p, vec3 n, vec3 wi)
{
    SphericalTriangle tri;
    if (strategy != RT_ENUM(LightSampler, Area) && sphericalTriangleApplies(light, p, tri))
    {
        if (planarHit(light, p, wi) < 0.0f)
            return 0.0f;
        if (strategy == RT_ENUM(LightSampler, SolidAngle) || !(dot(n, n) > 0.0f))
            return 1.0f / float(tri.solidAngle);
        const vec4 w = triangleCosineWeights(tri, n);
        const vec2 uv = invertSphericalTriangle(tri, RealVec3(wi));
        return bilinearPdf(uv, w.x, w.y, w.z, w.w) / float(tri.solidAngle);
    }
    return planarLightPdf(light, p, wi);
}

/// NEE's sample from p by `strategy`, with the density triangleLightPdf reports. The sampled direction becomes
/// the point where it meets the triangle, its barycentrics clamped onto it; marked kLightSampleFallback where a
/// strategy other than Area samples by area.
RT_FN bool sampleTriangleLight(RT_IN(LightData) light, RT_TAG(LightSampler) strategy, vec3 p, vec3 n, vec2 u,
                               RT_OUT(LightSample) ls)
{
    SphericalTriangle tri;
    if (strategy != RT_ENUM(LightSampler, Area) && sphericalTriangleApplies(light, p, tri))
    {
        // As for rectangles: Projected composes the cosine warp with Arvo's map, SolidAngle takes u as is.
        const bool warp = strategy == RT_ENUM(LightSampler, Projected) && dot(n, n) > 0.0f;
        const vec4 w = warp ? triangleCosineWeights(tri, n) : vec4(1.0f);
        const vec2 warped = warp ? sampleBilinear(u, w.x, w.y, w.z, w.w) : u;
        // The direction becomes a point on the triangle (barycentrics clamped), so the sample never misses.
        ls.uv = sphericalTrianglePoint(tri, sphericalTriangleDirection(tri, warped));
        ls.point = light.p0 + ls.uv.x * light.p1 + ls.uv.y * light.p2;
        ls.normal = light.normal;
        ls.outcome = 0u;
        const vec3 toPoint = ls.point - p;
        ls.distance = length(toPoint);
        ls.wi = toPoint / ls.distance;
        const float warpPdf = warp ? bilinearPdf(warped, w.x, w.y, w.z, w.w) : 1.0f;
        // planarHit's slack finds every such point again, so this 0 (the sample dropped, as triangleLightPdf
        // would drop its direction) is a guard the tests check is never taken.
        ls.pdf = planarHit(light, p, ls.wi) > 0.0f ? warpPdf / float(tri.solidAngle) : 0.0f;
        return keepLightSample(ls);
    }
    const bool sampled = samplePlanarLight(light, p, u, ls);
    if (strategy != RT_ENUM(LightSampler, Area))
        ls.outcome |= kLightSampleFallback;
    return sampled;
}

RT_SHADER_NAMESPACE_END

#endif
