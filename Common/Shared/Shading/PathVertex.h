// One vertex of the path-tracing estimator, written once for both engines: a host's shading scope
// (Shading/README.md). The CPU's path loops (RayTracingCPU/Integrator/PathIntegrator.h) and both GPU
// integrators, the megakernel (Shaders/Integrator.glsl) and the wavefront (Shaders/Wavefront/Shade.comp), run
// it between one traced segment and the next. Four estimators share it (HostDevice.h Estimator):
//  - bsdf (books 1-2): every bounce follows the material's sampled direction; the weight is the albedo.
//  - mixture (book 3, §9-12): at diffuse and isotropic vertices book 3's one-sample mix of the BSDF and light
//    sampling, without shadow rays (Shading/Scatter.h). Specular vertices follow their single direction.
//  - nee / nee-mis (Veach 1997 §9.2; pbrt-v4 PathIntegrator): at diffuse and isotropic vertices a shadow ray to
//    a point of one selected emitter (Shading/DirectLighting.h), then the BSDF direction continues the path.
//    Emission a BSDF ray finds after such a vertex counts 0 (nee: NEE already did) or with the power
//    heuristic's weight against NEE's pdf of the same direction (nee-mis); NEE's own sample gets the
//    complementary weight. After specular vertices and from the camera, emission counts in full.
//  - restir-di (Bitterli et al. 2020): at a camera path's first vertex where NEE would run, the host adds the
//    direct light its reservoirs chose (Shading/Restir.h) and calls this vertex with `directResampled`: no NEE
//    here, and emission the next BSDF ray finds counts 0, as after nee's vertices. Later vertices are nee-mis's.
// Russian roulette (Shared/RussianRoulette.h) may end any path from its third segment: drawn after scattering,
// it ends the path at once (NEE estimators, pbrt-v4) or after the next hit's emission (rouletteAfterNextHit).
// No ray is traced here: the next segment's ray and NEE's shadow ray are handed back to the caller.
#ifndef RT_SHADING_PATH_VERTEX_H
#define RT_SHADING_PATH_VERTEX_H

#include "Shared/Estimator.h"
#include "Shared/HostDevice.h"
#include "Shared/PathState.h"
#include "Shared/Random.h"
#include "Shared/RayOffset.h"
#include "Shared/RussianRoulette.h"
#include "Shared/Shading/Background.h"
#include "Shared/Shading/DirectLighting.h"
#include "Shared/Shading/Scatter.h"
#include "Shared/Shading/Textures.h"

/// The vertex where segment `segment` (0: the camera ray) of `path`, the ray (path.origin, path.direction),
/// found `hit` (material kNoIndex: it left the scene): adds the emission or background it finds to path.radiance, scatters, and returns true when the path goes on, with path.origin and
/// path.direction its next ray. `shadow` is the vertex's shadow ray, pending also when the path ends here; its
/// contribution counts (if unoccluded) before the next vertex's. `directResampled`: the host estimates this
/// vertex's direct light by resampling (restir-di; only where resamplesDirectAt holds): no NEE here.
RT_FN bool shadePathVertex(RT_INOUT(PathState) path, uint segment, RT_IN(HitPayload) hit, RT_OUT(ShadowRay) shadow,
                           bool directResampled)
{
    // Every field set on entry (Shading/Scatter.h says why); the caller reads them only when pending.
    shadow.pending = false;
    shadow.origin = vec3(0.0f);
    shadow.direction = vec3(0.0f);
    shadow.distance = 0.0f;
    shadow.contribution = vec3(0.0f);
    shadow.lightSample = 0u;
    if (hit.material == kNoIndex)
    {
        path.radiance += path.beta * background(path.direction);
        return false;
    }
    const bool nee = usesNee(settingEstimator()) && uniforms.emitterCount > 0u;
    const MaterialData m = materials[hit.material];
    const bool medium = kHasMedia && (hit.flags & kHitMedium) != 0u;
    SurfaceHit surface;
    surface.position = hit.position;
    surface.normal = hit.normal;
    surface.frontFace = medium || dot(path.direction, hit.normal) < 0.0f;
    surface.shadingNormal = surface.frontFace ? hit.normal : -hit.normal;
    surface.uv = hit.uv;
    surface.incoming = path.direction;

    if (m.emissionTexture != kNoIndex && (uniforms.unidirectionalLight == 0u || surface.frontFace))
    {
        float weight = 1.0f;
        const uint light = path.previousBsdfPdf != 0.0f ? emitterOfSlot(hit.lightSlot) : kNoIndex;
        if (light != kNoIndex) // after a NEE vertex: the direction is the BSDF's unit sample
            weight = weighsNeeByMis(settingEstimator()) && path.previousBsdfPdf > 0.0f
                         ? powerHeuristic(path.previousBsdfPdf,
                                          selectionPmf(light, path.previousPoint, path.previousNormal) *
                                              lightPdf(lights[light], settingLightSampler(), path.previousPoint,
                                                       path.previousNormal, path.direction))
                         : 0.0f;
        path.radiance += path.beta * evaluateTexture(m.emissionTexture, surface.uv, surface.position) * weight;
    }
    if (segment + 1u == uniforms.depth || path.pendingSurvival == 0.0f)
        return false; // RTIOW's depth: the next segment would return black
    if (path.pendingSurvival < 1.0f)
    {
        path.beta /= path.pendingSurvival;
        path.pendingSurvival = 1.0f;
    }

    path.previousBsdfPdf = 0.0f;
    vec3 direction;
    const bool phase = kHasIsotropic && m.type == RT_ENUM(MaterialType, Isotropic);
    const bool diffuse = (kHasLambertian && m.type == RT_ENUM(MaterialType, Lambertian)) || phase;
    const bool microfacet = isMicrofacet(m.type);
    if ((nee && diffuse) || microfacet)
    {
        // NEE's three numbers (where it runs) and the direction's two (and a glossy lobe's choice), drawn in that
        // order before any of them is used: independent draws that a CPU overlaps (a Sobol draw is a chain of
        // about 60 cycles). One call of each microfacet function for NEE's vertices and BSDF sampling's alike:
        // a copy per estimator doubled lavapipe's compile of the general pipeline.
        float uSelect = 0.0f;
        vec2 uLight = vec2(0.0f);
        if (nee)
        {
            uSelect = nextFloat(path.rng);
            uLight = nextFloat2(path.rng);
        }
        const vec2 u = nextFloat2(path.rng);
        const float uLobe = microfacet ? nextFloat(path.rng) : 0.0f;
        const vec3 albedo = microfacet ? vec3(0.0f) : evaluateTexture(m.albedoTexture, surface.uv, surface.position);
        MicrofacetBsdf bsdf; // read only when microfacet: a diffuse vertex builds none
        if (microfacet)
            bsdf = microfacetBsdfAt(m, surface);
        const vec3 wo = microfacet ? -normalize(path.direction) : vec3(0.0f); // read by glossy lobes only
        if (nee && !directResampled)
        {
            // Glass transmits: its light samples see no horizon and leave from the hit point itself, as in a
            // medium. The BSDF ray leaves from this origin too (below): sampleDiffuse and a reflecting BSDF keep
            // to ns's side.
            const bool transmits = microfacet && m.type == RT_ENUM(MaterialType, RoughDielectric);
            const vec3 origin = medium || transmits
                                    ? surface.position
                                    : offsetRayOrigin(surface.position, surface.shadingNormal, hit.offsetScale);
            const vec3 receiver = phase || transmits ? vec3(0.0f) : surface.shadingNormal;
            if (sampleDirect(origin, receiver, surface.shadingNormal, phase, albedo, microfacet, bsdf, wo, uSelect,
                             uLight, shadow))
            {
                shadow.contribution *= path.beta;
                if (transmits)
                    leaveGlass(shadow, surface.position, hit.normal, hit.offsetScale);
            }
            path.previousNormal = receiver;
        }
        if (microfacet)
        {
            BsdfSample s;
            if (!sampleMicrofacetBsdf(bsdf, wo, uLobe, u, s))
                return false;
            direction = s.wi;
            path.beta *= s.weight;
            if (nee)
                path.previousBsdfPdf = s.pdf;
        }
        else
        {
            direction = sampleDiffuse(phase, surface.shadingNormal, u);
            path.beta *= albedo;
            path.previousBsdfPdf = diffusePdf(phase, surface.shadingNormal, direction);
        }
        if (directResampled)
            path.previousBsdfPdf = -path.previousBsdfPdf;
    }
    else
    {
        ScatterSample s;
        if (!scatter(m, surface, path.rng, s))
            return false;
        path.beta *= s.weight;
        direction = s.direction;
    }
    bool survives = true;
    const float survival = rouletteSurvival(path.beta, segment, uniforms.russianRoulette);
    if (survival < 1.0f)
    {
        survives = nextFloat(path.rng) < survival;
        if (rouletteAfterNextHit(settingEstimator()))
        {
            path.pendingSurvival = survives ? survival : 0.0f;
            survives = true; // it ends after the next hit, above
        }
        else if (survives)
            path.beta /= survival;
    }
    path.origin = medium ? surface.position
                         : offsetRayOrigin(surface.position, dot(direction, hit.normal) > 0.0f ? hit.normal : -hit.normal,
                                           hit.offsetScale);
    path.direction = direction;
    path.previousPoint = kHasRoughDielectric && m.type == RT_ENUM(MaterialType, RoughDielectric) ? surface.position
                                                                                             : path.origin;
    return survives;
}

#endif
