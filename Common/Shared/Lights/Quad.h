// Quad lights for NEE (both engines, Shared/ShaderLang.h; conventions in Shared/Lights/LightSample.h): a
// rectangle of at least kMinSphericalRectangle sr by its spherical rectangle (Ureña, Fajardo & King 2013, "An
// Area-Preserving Parametrization for Spherical Rectangles", EGSR), uniform over the solid angle (SolidAngle) or
// warped first by a bilinear fit of the receiver's cosine (Projected: Hart et al. 2020, "Practical Product
// Sampling by Fitting and Composing Warps", EGSR; pbrt-v4 §6.5.4); every other quad and Area by book 3's area
// sampler (Lights/Planar.h). Each sampler's pdf is beside it.
#ifndef RT_SHARED_LIGHTS_QUAD_H
#define RT_SHARED_LIGHTS_QUAD_H

#include "Shared/HostDevice.h"
#include "Shared/Lights/LightSample.h"
#include "Shared/Lights/Planar.h"
#include "Shared/ShaderLang.h"
#include "Shared/SphericalRectangle.h"
#include "Shared/Warps.h"

RT_SHADER_NAMESPACE_BEGIN

/// Below this solid angle (sr) a rectangle is sampled by area: the float sum of four angles minus 2 pi
/// carries an absolute error near 5e-7 sr, 5e-5 of the density here, and a light this small looks the same
/// to both strategies.
RT_CONST(float, kMinSphericalRectangle, 1e-2f)

/// A quad whose edges are orthogonal (to float precision): what spherical-rectangle sampling needs. The cosine
/// of the edges' angle over its squared sine, |p1 . p2| |dualU| |dualV| (|dualU| = 1 / (|p1| sin), LightData),
/// within 1e-5: the light's stored lengths instead of two square roots at every shading point.
RT_FN bool isRectangle(RT_IN(LightData) light)
{
    return RT_LIGHT_IS(light.shape, Quad) &&
           abs(dot(light.p1, light.p2)) * light.dualULength * light.dualVLength <= 1e-5f;
}

/// The rectangle light as seen from p: its edge directions from the lengths LightData keeps (a rectangle's
/// dualU is p1 / |p1|^2, so p1 |dualU| is p1's direction and p1 . that direction its length) and its unit normal,
/// which is their cross product: no square root or division per shading point beyond the rectangle's own.
RT_FN SphericalRectangle lightSphericalRectangle(RT_IN(LightData) light, vec3 p)
{
    const vec3 x = light.p1 * light.dualULength;
    const vec3 y = light.p2 * light.dualVLength;
    return makeSphericalRectangleInFrame(p, light.p0, x, y, light.normal, dot(light.p1, x), dot(light.p2, y));
}

/// The cosine to the receiver normal n at the rectangle's four corners, seen from r.o, floored at 0.01 (a
/// corner below the horizon still gets samples near it, where the cosine rises): (w00, w10, w01, w11), the
/// weights of the bilinear warp that makes spherical-rectangle samples follow the cosine (pbrt-v4 §6.5.4,
/// after Hart et al. 2020, "Practical Product Sampling by Fitting and Composing Warps").
RT_FN vec4 rectangleCosineWeights(RT_IN(SphericalRectangle) r, vec3 n)
{
    // In the rectangle's frame the corner (xi, yj, z0) has n . corner = xi n.x + yj n.y + z0 n.z: three dot
    // products for the four corners, and no vector to build or normalise per corner.
    const float nx = dot(n, r.x);
    const float ny = dot(n, r.y);
    const float nz = r.z0 * dot(n, r.z);
    const float z2 = r.z0 * r.z0;
    const float x0n = r.x0 * nx, x1n = r.x1 * nx, y0n = r.y0 * ny, y1n = r.y1 * ny;
    const float x02 = r.x0 * r.x0 + z2, x12 = r.x1 * r.x1 + z2, y02 = r.y0 * r.y0, y12 = r.y1 * r.y1;
    const float w00 = max((x0n + y0n + nz) / sqrt(x02 + y02), 0.01f);
    const float w10 = max((x1n + y0n + nz) / sqrt(x12 + y02), 0.01f);
    const float w01 = max((x0n + y1n + nz) / sqrt(x02 + y12), 0.01f);
    const float w11 = max((x1n + y1n + nz) / sqrt(x12 + y12), 0.01f);
    return vec4(w00, w10, w01, w11);
}

/// NEE's solid-angle pdf of wi from p with receiver normal n (0 in a medium) by `strategy`: over a rectangle of
/// at least kMinSphericalRectangle sr whose setup resolves it (sphericalRectangleResolved), 1 / S (SolidAngle, or
/// no receiver), or the bilinear cosine warp's density at the direction's u (the inverse of the spherical map) over
/// 1 / S (Projected); else the area density.
RT_FN float quadLightPdf(RT_IN(LightData) light, RT_TAG(LightSampler) strategy, vec3 p, vec3 n, vec3 wi)
{
    if (strategy != RT_ENUM(LightSampler, Area) && isRectangle(light))
    {
        const SphericalRectangle r = lightSphericalRectangle(light, p);
        if (r.solidAngle >= kMinSphericalRectangle && sphericalRectangleResolved(r))
        {
            const float t = planarHit(light, p, wi);
            if (t < 0.0f)
                return 0.0f;
            if (strategy == RT_ENUM(LightSampler, SolidAngle) || !(dot(n, n) > 0.0f))
                return 1.0f / r.solidAngle;
            const vec3 y = t * wi;
            const vec2 uv = invertSphericalRectangle(r, dot(y, r.x), dot(y, r.y));
            const vec4 w = rectangleCosineWeights(r, n);
            return bilinearPdf(uv, w.x, w.y, w.z, w.w) / r.solidAngle;
        }
    }
    return planarLightPdf(light, p, wi);
}

/// NEE's sample from p by `strategy`, with the density quadLightPdf reports; marked kLightSampleFallback where a
/// strategy other than Area samples by area.
RT_FN bool sampleQuadLight(RT_IN(LightData) light, RT_TAG(LightSampler) strategy, vec3 p, vec3 n, vec2 u,
                           RT_OUT(LightSample) ls)
{
    if (strategy != RT_ENUM(LightSampler, Area) && isRectangle(light))
    {
        const SphericalRectangle r = lightSphericalRectangle(light, p);
        if (r.solidAngle >= kMinSphericalRectangle && sphericalRectangleResolved(r))
        {
            // Projected warps u toward the receiver's cosine first; SolidAngle (or no receiver) takes u as is.
            const bool warp = strategy == RT_ENUM(LightSampler, Projected) && dot(n, n) > 0.0f;
            const vec4 w = warp ? rectangleCosineWeights(r, n) : vec4(1.0f);
            const vec2 warped = warp ? sampleBilinear(u, w.x, w.y, w.z, w.w) : u;
            ls.point = sampleSphericalRectangle(r, warped);
            ls.normal = light.normal;
            ls.outcome = 0u;
            const vec3 planar = ls.point - light.p0;
            ls.uv = vec2(dot(planar, light.dualU), dot(planar, light.dualV));
            const vec3 toPoint = ls.point - p;
            ls.distance = length(toPoint);
            ls.wi = toPoint / ls.distance;
            // The density of the construction at its own (u, v) (the warp's, 1 without it) over 1 / S; 0 where
            // rounding put the direction off the rectangle, as quadLightPdf finds it.
            const float warpPdf = warp ? bilinearPdf(warped, w.x, w.y, w.z, w.w) : 1.0f;
            ls.pdf = planarHit(light, p, ls.wi) > 0.0f ? warpPdf / r.solidAngle : 0.0f;
            return keepLightSample(ls);
        }
    }
    const bool sampled = samplePlanarLight(light, p, u, ls);
    if (strategy != RT_ENUM(LightSampler, Area))
        ls.outcome |= kLightSampleFallback;
    return sampled;
}

RT_SHADER_NAMESPACE_END

#endif
