// The path-tracing estimator of one camera sample, iterative (no recursion from hit shaders): the twin of
// the CPU engine's loop (RayTracingCPU/Integrator/PathIntegrator.h, which describes the four estimators).
// Per segment: trace; on a miss add the background; on a hit add the emission (front face only with
// unidirectional lights; MIS-weighted after a NEE vertex), stop on the last segment, else scatter: NEE and a
// diffuse direction at diffuse vertices with nee / nee-mis, else by the material (BSDF only, or the book-3
// mixture over the light list); then Russian roulette (ending the path at once, or after the next hit's
// emission: rouletteAfterNextHit), and continue from an offset origin.
// Needs the payloads `payload` (location kPayloadPath) and `shadowVisible` (kPayloadShadow) and the globals of
// Bindings.glsl.
#ifndef RT_INTEGRATOR_GLSL
#define RT_INTEGRATOR_GLSL

#include "DirectLighting.glsl"
#include "Materials/Scatter.glsl"
#include "Payload.glsl"
#include "RayOffset.glsl"
#include "Shared/RussianRoulette.h"

// Far enough for any scene, finite so that no driver sees an infinite interval.
const float kRayTMax = 3.0e38;

/// Radiance along the camera ray (origin, direction). A non-finite direction ends the path with NaN, so the
/// sample is counted like the CPU engine's instead of reaching traversal (undefined for NaN rays).
vec3 traceRadiance(vec3 origin, vec3 direction, inout Rng rng)
{
    bool nee = (settingEstimator() == Estimator_Nee || settingEstimator() == Estimator_NeeMis) &&
               uniforms.emitterCount > 0u;
    bool mis = settingEstimator() == Estimator_NeeMis;
    bool lateRoulette = rouletteAfterNextHit(settingEstimator());
    // A roulette decided at the last vertex, applied once this segment's emission is gathered
    // (rouletteAfterNextHit): 0 ends the path, else the throughput is scaled by 1 / pendingSurvival.
    float pendingSurvival = 1.0;
    vec3 radiance = vec3(0.0);
    vec3 beta = vec3(1.0);
    // The origin of the current ray and its direction's BSDF pdf, for the MIS weight of the emission it finds
    // (pdf 0: count it in full).
    vec3 previousPoint = vec3(0.0);
    vec3 previousNormal = vec3(0.0); // the receiver normal there, for the projected samplers (0 in a medium)
    float previousBsdfPdf = 0.0;
    for (uint segment = 0u; segment < uniforms.depth; ++segment)
    {
        if (!isFiniteVec(origin) || !isFiniteVec(direction))
            return vec3(uintBitsToFloat(0x7FC00000u)); // a quiet NaN
        traceRayEXT(tlas, gl_RayFlagsOpaqueEXT, 0xFF, 0, 1, kMissBackground, origin, 0.0, direction, kRayTMax,
                    int(kPayloadPath));
        if (payload.material == kNoIndex)
        {
            radiance += beta * payload.background;
            break;
        }
        MaterialData m = materials[payload.material];
        bool medium = kHasMedia && (payload.flags & kHitMedium) != 0u;
        float offsetScale = payload.offsetScale;
        SurfaceHit hit;
        hit.position = payload.position;
        hit.normal = payload.normal;
        hit.frontFace = medium || dot(direction, payload.normal) < 0.0;
        hit.shadingNormal = hit.frontFace ? payload.normal : -payload.normal;
        hit.uv = payload.uv;
        hit.incoming = direction;

        if (m.emissionTexture != kNoIndex && (uniforms.unidirectionalLight == 0u || hit.frontFace))
        {
            float weight = 1.0;
            uint light = previousBsdfPdf > 0.0 && payload.lightSlot != kNoIndex ? primitiveLights[payload.lightSlot]
                                                                                : kNoIndex;
            if (light != kNoIndex)
                weight = mis ? powerHeuristic(previousBsdfPdf, lightSelectionPmf(settingLightSelection(), light,
                                                                                 uniforms.emitterCount, previousPoint,
                                                                                 previousNormal,
                                                                                 uniforms.unidirectionalLight == 0u) *
                                                                   lightPdf(lights[light],
                                                                            settingLightSampler(), previousPoint,
                                                                            previousNormal, normalize(direction)))
                             : 0.0;
            radiance += beta * evaluateTexture(m.emissionTexture, hit.uv, hit.position) * weight;
        }
        if (segment + 1u == uniforms.depth || pendingSurvival == 0.0)
            break;
        if (pendingSurvival < 1.0)
        {
            beta /= pendingSurvival;
            pendingSurvival = 1.0;
        }

        previousBsdfPdf = 0.0;
        // NEE's shadow ray, traced at the end of the vertex: across that trace only the path's own state lives
        // (the hit, its material and the light sample are dead by then), which the GPU keeps in registers.
        bool shadowPending = false;
        vec3 shadowOrigin, shadowDirection, shadowContribution;
        float shadowDistance;
        bool phase = kHasIsotropic && m.type == MaterialType_Isotropic;
        bool diffuse = (kHasLambertian && m.type == MaterialType_Lambertian) || phase;
        if (nee && diffuse)
        {
            vec3 albedo = evaluateTexture(m.albedoTexture, hit.uv, hit.position);
            // The BSDF ray leaves from this origin too (below): sampleDiffuse keeps to the side of ns.
            shadowOrigin = medium ? hit.position : offsetRayOrigin(hit.position, hit.shadingNormal, offsetScale);
            shadowPending = sampleDirect(shadowOrigin, hit.shadingNormal, phase, albedo, mis, rng, shadowContribution,
                                         shadowDirection, shadowDistance);
            shadowContribution *= beta;
            direction = sampleDiffuse(phase, hit.shadingNormal, nextFloat2(rng));
            beta *= albedo;
            previousBsdfPdf = diffusePdf(phase, hit.shadingNormal, direction);
            previousNormal = phase ? vec3(0.0) : hit.shadingNormal;
        }
        else
        {
            ScatterSample s;
            if (!scatter(m, hit, rng, s))
                break;
            beta *= s.weight;
            direction = s.direction;
        }
        bool survives = true;
        if (uniforms.russianRoulette != 0u)
        {
            float survival = rouletteSurvival(beta, segment);
            if (survival < 1.0)
            {
                survives = nextFloat(rng) < survival;
                if (lateRoulette)
                {
                    pendingSurvival = survives ? survival : 0.0;
                    survives = true; // it ends after the next hit, above
                }
                else
                    beta /= survival;
            }
        }
        origin = medium ? hit.position
                        : offsetRayOrigin(hit.position, dot(direction, hit.normal) > 0.0 ? hit.normal : -hit.normal,
                                          offsetScale);
        previousPoint = origin;
        if (shadowPending && unoccluded(shadowOrigin, shadowDirection, shadowDistance))
            radiance += shadowContribution;
        if (!survives)
            break;
    }
    return radiance;
}

#endif
