// Sampling directions towards one light of the scene's world-space light list, and the solid-angle pdf of
// any direction under that strategy, written once for both engines (Shared/ShaderLang.h): the dispatch by shape to
// Shared/Lights/ (Sphere.h, Quad.h, Triangle.h, what quads and triangles share in Planar.h), where each shape's
// samplers sit beside their pdfs. Both are needed by the book-3 mixture (RTTROYL §9-12): the pdf of a direction
// must be evaluated for every light, whichever strategy produced the direction; and by NEE + MIS, for the
// emitter a BSDF ray hits. Two families: book 3's (sampleLight / lightPdf without a sampler: cones for spheres
// seen from outside, area otherwise), which the mixture uses, and NEE's, chosen by a LightSampler (HostDevice.h).
#ifndef RT_SHARED_LIGHT_SAMPLING_H
#define RT_SHARED_LIGHT_SAMPLING_H

#include "Shared/HostDevice.h"
#include "Shared/Lights/LightSample.h"
#include "Shared/Lights/Planar.h"
#include "Shared/Lights/ProjectedPolygon.h"
#include "Shared/Lights/Quad.h"
#include "Shared/Lights/Sphere.h"
#include "Shared/Lights/Triangle.h"
#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

/// Solid-angle pdf with which sampleLight(light, p, .) produces the unit direction `wi`; 0 if it cannot.
RT_FN float lightPdf(RT_IN(LightData) light, vec3 p, vec3 wi)
{
    if (RT_LIGHT_IS(light.shape, Sphere))
        return sphereLightPdf(light, p, wi);
    if (!RT_HAS_LIGHT_SHAPE(Quad) && !RT_HAS_LIGHT_SHAPE(Triangle))
        return 0.0f; // only spheres: the code below is dead
    return planarLightPdf(light, p, wi);
}

/// Samples a direction from p towards `light` with uniform-area (quad, triangle, sphere seen from inside) or
/// uniform-cone (sphere seen from outside) density. The pdf it returns is lightPdf(light, p, wi) itself, so
/// a sample and the pdf of its direction can never disagree: a direction that rounding puts outside the light
/// (p in the light's own plane, a cone sample on the silhouette) is dropped instead of being weighted by a pdf
/// the mixture's other terms cannot see (that mismatch biased a closed-box furnace by +0.7 %).
/// Returns false when no direction can be produced.
RT_FN bool sampleLight(RT_IN(LightData) light, vec3 p, vec2 u, RT_OUT(LightSample) ls)
{
    if (RT_LIGHT_IS(light.shape, Sphere))
        return sampleSphereLight(light, p, u, ls);
    if (RT_LIGHT_IS(light.shape, Quad) || RT_HAS_LIGHT_SHAPE(Triangle))
        return samplePlanarLight(light, p, u, ls);
    clearLightSample(light, ls);
    return false; // a shape the pipeline has no light of: never reached
}

/// Solid-angle pdf with which sampleLight(light, strategy, p, n, .) produces the unit direction wi; 0 if it
/// cannot (each shape's pdf says how it is computed).
RT_FN float lightPdf(RT_IN(LightData) light, RT_TAG(LightSampler) strategy, vec3 p, vec3 n, vec3 wi)
{
    // Polygons with a receiver by their exact projected solid angle (by area when too small, nothing wholly
    // below the horizon); without one, Quad.h and Triangle.h take projected-exact as solid angle, and Sphere.h
    // takes it as projected (exact for spheres already). The strategy is not reassigned here: that made
    // spirv-opt (SPIRV-Tools 2023.1, glslc -O) crash on the megakernel.
    if (strategy == RT_ENUM(LightSampler, ProjectedExact) && !RT_LIGHT_IS(light.shape, Sphere) && dot(n, n) > 0.0f)
    {
        const ProjectedPolygon g = makeProjectedPolygon(light, p, n);
        if (g.count == 0u) // wholly below the horizon
            return 0.0f;
        return projectedPolygonApplies(g) ? projectedPolygonPdf(light, g, p, n, wi) : planarLightPdf(light, p, wi);
    }
    if (RT_LIGHT_IS(light.shape, Sphere))
        return sphereLightPdf(light, strategy, p, n, wi);
    if (RT_LIGHT_IS(light.shape, Quad))
        return quadLightPdf(light, strategy, p, n, wi);
    if (RT_HAS_LIGHT_SHAPE(Triangle))
        return triangleLightPdf(light, strategy, p, n, wi);
    return 0.0f;
}

/// Samples a point of `light` for NEE from p (receiver normal n, or 0 in a medium) with the density
/// lightPdf(light, strategy, p, n, .) reports (the sample's pdf is that density of its direction); ls.outcome
/// says whether a fallback sampler made it and whether it was declined (Lights/LightSample.h).
RT_FN bool sampleLight(RT_IN(LightData) light, RT_TAG(LightSampler) strategy, vec3 p, vec3 n, vec2 u,
                       RT_OUT(LightSample) ls)
{
    RT_DCHECK(u.x >= 0.0f && u.x < 1.0f && u.y >= 0.0f && u.y < 1.0f);
    if (strategy == RT_ENUM(LightSampler, ProjectedExact) && !RT_LIGHT_IS(light.shape, Sphere) && dot(n, n) > 0.0f)
    {
        const ProjectedPolygon g = makeProjectedPolygon(light, p, n);
        if (g.count == 0u) // wholly below the horizon: nothing to sample, as a sphere's cap there
        {
            clearLightSample(light, ls);
            return false;
        }
        if (projectedPolygonApplies(g))
            return sampleProjectedPolygonLight(light, g, p, n, u, ls);
        const bool sampled = samplePlanarLight(light, p, u, ls);
        ls.outcome |= kLightSampleFallback;
        return sampled;
    }
    if (RT_LIGHT_IS(light.shape, Sphere))
        return sampleSphereLight(light, strategy, p, n, u, ls);
    if (RT_LIGHT_IS(light.shape, Quad))
        return sampleQuadLight(light, strategy, p, n, u, ls);
    if (RT_HAS_LIGHT_SHAPE(Triangle))
        return sampleTriangleLight(light, strategy, p, n, u, ls);
    clearLightSample(light, ls);
    return false;
}

RT_SHADER_NAMESPACE_END

#endif
