// Next-event estimation at a diffuse or isotropic vertex: the GLSL twin of estimateDirect in
// RayTracingCPU/Integrator/PathIntegrator.h, on the shared selection, light sampler and MIS weight, cut in two
// here: sampleDirect draws the light sample, the integrator traces its shadow ray (Rays.glsl) once the
// vertex is done with: the megakernel at the end of the vertex, the wavefront in a launch of its own.
// Needs the globals of Bindings.glsl.
#ifndef RT_DIRECT_LIGHTING_GLSL
#define RT_DIRECT_LIGHTING_GLSL

#include "Shared/Random.h"
#include "Shared/DiffuseScattering.h"
#include "Shared/LightSampling.h"
#include "Shared/LightSelection.h"
#include "Shared/Mis.h"
#include "Textures/Texture.glsl"

/// A light sample for next-event estimation seen from `origin`, where the vertex's rays leave (the hit point
/// offset to the side of the shading normal ns; the point itself in a medium): false when it contributes
/// nothing; else `contribution` = f cos Le / (pmf pdf) x the MIS weight, valid if the shadow ray (origin,
/// shadowDirection, shadowDistance) is unoccluded. The caller traces that ray once the vertex is done with
/// (Rays.glsl), so that little state lives across the trace. Draws three numbers: the selection, then
/// the point.
bool sampleDirect(vec3 origin, vec3 ns, bool phase, vec3 albedo, bool mis, inout Rng rng, out vec3 contribution,
                  out vec3 shadowDirection, out float shadowDistance)
{
    float pmf;
    vec3 receiver = phase ? vec3(0.0) : ns; // no horizon in a medium
    uint picked = selectLight(settingLightSelection(), nextFloat(rng), uniforms.emitterCount, origin, receiver,
                              uniforms.unidirectionalLight == 0u, pmf);
    vec2 u = nextFloat2(rng);
    contribution = vec3(0.0);
    shadowDirection = vec3(0.0);
    shadowDistance = 0.0;
    if (picked == kNoIndex)
        return false; // the light BVH proved that no emitter reaches this point
    LightSample ls;
    if (!sampleLight(lights[picked], settingLightSampler(), origin, receiver, u, ls))
        return false;
    float bsdfPdf = diffusePdf(phase, ns, ls.wi); // f cos = albedo bsdfPdf
    if (!(bsdfPdf > 0.0) || (uniforms.unidirectionalLight != 0u && dot(ls.wi, ls.normal) >= 0.0))
        return false;
    vec3 le = evaluateTexture(materials[lights[picked].material].emissionTexture, ls.uv, ls.point);
    if (!(max(le.x, max(le.y, le.z)) > 0.0))
        return false;
    float lightPdfTotal = pmf * ls.pdf;
    float weight = mis ? powerHeuristic(lightPdfTotal, bsdfPdf) : 1.0;
    contribution = albedo * le * (weight * bsdfPdf / lightPdfTotal);
    shadowDirection = ls.wi;
    // Stop short of the light's surface by a relative margin far above the rounding (as on the CPU).
    shadowDistance = ls.distance * (1.0 - 1e-4);
    return true;
}

#endif
