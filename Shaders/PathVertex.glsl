// One vertex of the path-tracing estimator: what happens between one traced segment and the next, written
// once for both GPU integrators, the megakernel (Integrator.glsl, a loop in RayGen.rgen) and the wavefront
// (Wavefront/Shade.comp, a kernel per segment). The twin of the CPU engine's loop body
// (RayTracingCPU/Integrator/PathIntegrator.h, which describes the four estimators): on a miss add the
// background; on a hit add the emission (front face only with unidirectional lights; MIS-weighted after a
// NEE vertex), stop on the last segment, else scatter: NEE and a diffuse direction at diffuse vertices with
// nee / nee-mis, else by the material (BSDF only, or the book-3 mixture over the light list); then Russian
// roulette (ending the path at once, or after the next hit's emission: rouletteAfterNextHit), and continue
// from an offset origin. No ray is traced here: NEE's shadow ray is handed back to the caller.
// Needs the globals of Bindings.glsl.
#ifndef RT_PATH_VERTEX_GLSL
#define RT_PATH_VERTEX_GLSL

#include "DirectLighting.glsl"
#include "Materials/Scatter.glsl"
#include "Payload.glsl"
#include "RayOffset.glsl"
#include "Shared/RussianRoulette.h"

/// What a path carries from one vertex to the next (the kWave* fields hold it between the wavefront's kernels).
struct PathState
{
    vec3 origin; // the ray to trace next
    vec3 direction;
    vec3 radiance; // gathered so far
    vec3 beta; // throughput
    // A roulette decided at the last vertex, applied once this segment's emission is gathered
    // (rouletteAfterNextHit): 0 ends the path, else the throughput is scaled by 1 / pendingSurvival.
    float pendingSurvival;
    // The origin of the current ray and its direction's BSDF pdf, for the MIS weight of the emission it finds
    // (pdf 0: count it in full), and the receiver normal there for the projected samplers (0 in a medium).
    vec3 previousPoint;
    vec3 previousNormal;
    float previousBsdfPdf;
    Rng rng;
};

/// NEE's shadow ray of a vertex: `contribution` counts when nothing lies between origin and origin +
/// distance direction.
struct ShadowRay
{
    bool pending;
    vec3 origin;
    vec3 direction;
    float distance;
    vec3 contribution;
};

/// A path about to trace its camera ray (origin, direction) with the numbers of `rng`.
PathState startPath(vec3 origin, vec3 direction, Rng rng)
{
    PathState path;
    path.origin = origin;
    path.direction = direction;
    path.radiance = vec3(0.0);
    path.beta = vec3(1.0);
    path.pendingSurvival = 1.0;
    path.previousPoint = vec3(0.0);
    path.previousNormal = vec3(0.0);
    path.previousBsdfPdf = 0.0;
    path.rng = rng;
    return path;
}

/// The vertex where segment `segment` of `path` (the ray path.origin, path.direction) found `payload`: adds
/// what it gathers to path.radiance and returns true when the path goes on, with path.origin and
/// path.direction its next ray. `shadow` is the vertex's shadow ray, pending also when the path ends here;
/// its contribution counts before the next vertex's.
bool shadePathVertex(inout PathState path, uint segment, HitPayload payload, out ShadowRay shadow)
{
    shadow.pending = false;
    shadow.origin = vec3(0.0);
    shadow.direction = vec3(0.0);
    shadow.distance = 0.0;
    shadow.contribution = vec3(0.0);
    bool nee = settingUsesNee() && uniforms.emitterCount > 0u;
    bool mis = settingEstimator() == Estimator_NeeMis;
    bool lateRoulette = rouletteAfterNextHit(settingEstimator());
    if (payload.material == kNoIndex)
    {
        path.radiance += path.beta * payload.background;
        return false;
    }
    MaterialData m = materials[payload.material];
    bool medium = kHasMedia && (payload.flags & kHitMedium) != 0u;
    float offsetScale = payload.offsetScale;
    SurfaceHit hit;
    hit.position = payload.position;
    hit.normal = payload.normal;
    hit.frontFace = medium || dot(path.direction, payload.normal) < 0.0;
    hit.shadingNormal = hit.frontFace ? payload.normal : -payload.normal;
    hit.uv = payload.uv;
    hit.incoming = path.direction;

    if (m.emissionTexture != kNoIndex && (uniforms.unidirectionalLight == 0u || hit.frontFace))
    {
        float weight = 1.0;
        uint light = path.previousBsdfPdf > 0.0 && payload.lightSlot != kNoIndex ? primitiveLights[payload.lightSlot]
                                                                                 : kNoIndex;
        if (light != kNoIndex)
            weight = mis ? powerHeuristic(path.previousBsdfPdf,
                                          lightSelectionPmf(settingLightSelection(), light, uniforms.emitterCount,
                                                            path.previousPoint, path.previousNormal,
                                                            uniforms.unidirectionalLight == 0u) *
                                              lightPdf(lights[light], settingLightSampler(), path.previousPoint,
                                                       path.previousNormal, normalize(path.direction)))
                         : 0.0;
        path.radiance += path.beta * evaluateTexture(m.emissionTexture, hit.uv, hit.position) * weight;
    }
    if (segment + 1u == uniforms.depth || path.pendingSurvival == 0.0)
        return false;
    if (path.pendingSurvival < 1.0)
    {
        path.beta /= path.pendingSurvival;
        path.pendingSurvival = 1.0;
    }

    path.previousBsdfPdf = 0.0;
    vec3 direction;
    bool phase = kHasIsotropic && m.type == MaterialType_Isotropic;
    bool diffuse = (kHasLambertian && m.type == MaterialType_Lambertian) || phase;
    if (nee && diffuse)
    {
        vec3 albedo = evaluateTexture(m.albedoTexture, hit.uv, hit.position);
        // The BSDF ray leaves from this origin too (below): sampleDiffuse keeps to the side of ns.
        shadow.origin = medium ? hit.position : offsetRayOrigin(hit.position, hit.shadingNormal, offsetScale);
        shadow.pending = sampleDirect(shadow.origin, hit.shadingNormal, phase, albedo, mis, path.rng,
                                      shadow.contribution, shadow.direction, shadow.distance);
        shadow.contribution *= path.beta;
        direction = sampleDiffuse(phase, hit.shadingNormal, nextFloat2(path.rng));
        path.beta *= albedo;
        path.previousBsdfPdf = diffusePdf(phase, hit.shadingNormal, direction);
        path.previousNormal = phase ? vec3(0.0) : hit.shadingNormal;
    }
    else
    {
        ScatterSample s;
        if (!scatter(m, hit, path.rng, s))
            return false;
        path.beta *= s.weight;
        direction = s.direction;
    }
    bool survives = true;
    if (uniforms.russianRoulette != 0u)
    {
        float survival = rouletteSurvival(path.beta, segment);
        if (survival < 1.0)
        {
            survives = nextFloat(path.rng) < survival;
            if (lateRoulette)
            {
                path.pendingSurvival = survives ? survival : 0.0;
                survives = true; // it ends after the next hit, above
            }
            else
                path.beta /= survival;
        }
    }
    path.origin = medium ? hit.position
                         : offsetRayOrigin(hit.position, dot(direction, hit.normal) > 0.0 ? hit.normal : -hit.normal,
                                           offsetScale);
    path.direction = direction;
    path.previousPoint = path.origin;
    return survives;
}

#endif
