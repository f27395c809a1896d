// Next-event estimation at a diffuse, isotropic or glossy vertex (Veach 1997 §9.2; pbrt-v4 PathIntegrator), written
// once for both engines: a host's shading scope (Shading/README.md). One emitter selected (uniformly, by power
// or by the light BVH: Shared/LightSelection.h), one point on it (Shared/LightSampling.h), and the shadow ray
// handed back to the caller, which traces it once the vertex is done with (on the GPU little state then lives
// across the trace; the wavefront traces it in a launch of its own).
#ifndef RT_SHADING_DIRECT_LIGHTING_H
#define RT_SHADING_DIRECT_LIGHTING_H

#include "Shared/Bsdf/MicrofacetBsdf.h"
#include "Shared/DiffuseScattering.h"
#include "Shared/HostDevice.h"
#include "Shared/LightSampling.h"
#include "Shared/LightSelection.h"
#include "Shared/Mis.h"
#include "Shared/PathState.h"
#include "Shared/RayOffset.h"
#include "Shared/Shading/Textures.h"

/// Probability with which NEE at `origin` (receiver normal `receiver`, 0 in a medium) selects `light`.
RT_FN float selectionPmf(uint light, vec3 origin, vec3 receiver)
{
    return lightSelectionPmf(RT_PASS(lightAlias) RT_PASS(lightBvh) RT_PASS(lightBvhLeaves) settingLightSelection(),
                             light, uniforms.emitterCount, origin, receiver, uniforms.unidirectionalLight == 0u);
}

/// A light sample for next-event estimation seen from `origin`, where the vertex's rays leave (the hit point
/// offset to the side of the unit shading normal ns, the rays of both strategies leaving from there too, so both
/// see one geometry and their MIS weights sum to 1 for every direction; the point itself in a medium and at
/// glass, which transmits), with the horizon of `receiver` (ns; 0 in a medium and at glass). The BSDF is the
/// diffuse lobe of `albedo` (`phase`: the isotropic phase function) about ns, or, when `microfacet`, `b` seen
/// from the unit direction wo. False (shadow not pending) when it contributes nothing (the light BVH proved
/// that no emitter reaches origin; the point faces away or lies where the BSDF is 0; it emits nothing towards
/// origin); else shadow.contribution = f cos Le / (pmf pdf) x the MIS weight (nee-mis: the power heuristic
/// against the BSDF strategy's pdf of the same direction; nee: 1), valid if the shadow ray is unoccluded.
/// Takes the vertex's numbers uSelect for the selection and u for the point; shadow.lightSample says how the
/// light sample was made, whatever the result (Shared/PathState.h). One function for both kinds of lobe: the
/// megakernel inlines the light samplers once (two call sites made NEE 2.4-4.2x slower on the H100,
/// docs/notebook §10).
RT_FN bool sampleDirect(vec3 origin, vec3 receiver, vec3 ns, bool phase, vec3 albedo, bool microfacet,
                        RT_IN(MicrofacetBsdf) b, vec3 wo, float uSelect, vec2 u, RT_OUT(ShadowRay) shadow)
{
    shadow.pending = false;
    shadow.origin = origin;
    shadow.direction = vec3(0.0f);
    shadow.distance = 0.0f;
    shadow.contribution = vec3(0.0f);
    shadow.lightSample = 0u;
    float pmf;
    const uint picked = selectLight(RT_PASS(lightAlias) RT_PASS(lightBvh) settingLightSelection(), uSelect,
                                    uniforms.emitterCount, origin, receiver, uniforms.unidirectionalLight == 0u, pmf);
    if (picked == kNoIndex)
        return false;
    LightSample ls;
    const bool sampled = sampleLight(lights[picked], settingLightSampler(), origin, receiver, u, ls);
    shadow.lightSample = kLightSampleDrawn | ls.outcome;
    if (!sampled)
        return false;
    float bsdfPdf;
    vec3 f = vec3(0.0f); // f |cos theta_i| of a microfacet BSDF; a diffuse lobe's is albedo x bsdfPdf
    if (microfacet)
        f = evalMicrofacetBsdf(b, wo, ls.wi, bsdfPdf);
    else
        bsdfPdf = diffusePdf(phase, ns, ls.wi);
    const bool scatters = microfacet ? max(f.x, max(f.y, f.z)) > 0.0f : bsdfPdf > 0.0f;
    if (!scatters || (uniforms.unidirectionalLight != 0u && dot(ls.wi, ls.normal) >= 0.0f))
        return false;
    const vec3 le = evaluateTexture(materials[lights[picked].material].emissionTexture, ls.uv, ls.point);
    if (!(max(le.x, max(le.y, le.z)) > 0.0f))
        return false;
    const float lightPdfTotal = pmf * ls.pdf;
    const float weight = weighsNeeByMis(settingEstimator()) ? powerHeuristic(lightPdfTotal, bsdfPdf) : 1.0f;
    shadow.pending = true;
    shadow.direction = ls.wi;
    // The shadow ray stops short of the light's surface by a relative margin far above the rounding of the
    // sampled point and of the light's intersection test.
    shadow.distance = ls.distance * (1.0f - 1e-4f);
    shadow.contribution = microfacet ? f * le * (weight / lightPdfTotal) : albedo * le * (weight * bsdfPdf / lightPdfTotal);
    return true;
}

/// Starts the pending shadow ray of a vertex on glass, whose light sample was taken from the hit point itself
/// (`position`), off the surface to the side its direction leaves on (`normal`: the unit geometric normal;
/// `scale`: offsetRayOrigin's), and shortens it by what the move advanced it along its direction, so that it
/// still stops short of the light. Without the shortening the ray overshot its margin where the offset (256 ulps
/// of each coordinate: 0.03 units at 1,000) exceeded 1e-4 of the distance, hit the light it was aimed at and
/// counted as blocked: NEE alone lost 7 % of a glass sphere's light on glossy-cornell, and half of it where
/// the sphere lay past 1,024 units from the origin.
RT_FN void leaveGlass(RT_INOUT(ShadowRay) shadow, vec3 position, vec3 normal, float scale)
{
    const vec3 from = offsetRayOrigin(position, dot(shadow.direction, normal) > 0.0f ? normal : -normal, scale);
    shadow.distance -= dot(from - position, shadow.direction);
    shadow.origin = from;
}

#endif
