// restir-di's per-sample math, written once for both engines: a host's shading scope (Shading/README.md). The
// estimator (Bitterli et al. 2020; the reservoirs in Shared/Restir.h): at a camera path's first vertex where NEE
// would run, direct light is estimated by one light point y chosen by resampling, with f(y) W, where f is the
// integrand in the area measure of y,
//     f(y) = f_s(wo, wi) |cos theta_i| Le(y, -wi) |cos theta_y| / |y - x|^2 V(x, y),
// and W the reservoir's unbiased contribution weight. The target function p-hat is the luminance of f without V.
// Candidates come from the render's light selection and sampler, so their area pdf is
// p(y) = pmf pdf_omega |cos theta_y| / |y - x|^2 and their resampling weight p-hat / p needs no distance.
// The engines' passes: candidates and temporal reuse, then spatial reuse and shading (RayTracingCPU/Integrator/
// RestirPasses.cpp on the CPU, Shaders/Restir/ on the GPU). A host provides
//   restirVisible(v, point, pixel, sampleIndex): whether the shadow ray restirShadowRay(v, point) reaches the
//     point, traced as camera sample `sampleIndex` of `pixel` traces its rays (its shutter time, its medium seed);
// and, for combineReservoirs, the inputs of the combination in progress:
//   restirInputReservoir(i), restirInputVertex(i) (i >= 1), restirInputPixel(i), restirInputSample(i).
#ifndef RT_SHADING_RESTIR_H
#define RT_SHADING_RESTIR_H

#include "Shared/Bsdf/MicrofacetBsdf.h"
#include "Shared/DiffuseScattering.h"
#include "Shared/HostDevice.h"
#include "Shared/LightSampling.h"
#include "Shared/LightSelection.h"
#include "Shared/PathState.h"
#include "Shared/PreciseMath.h"
#include "Shared/Random.h"
#include "Shared/RayOffset.h"
#include "Shared/Restir.h"
#include "Shared/Shading/DirectLighting.h"
#include "Shared/Shading/Scatter.h"
#include "Shared/Shading/Textures.h"

/// Whether the path vertex would run NEE at `hit`, reached by segment `segment` of `path`: the vertex whose
/// direct light restir-di resamples (the first such of a camera path). shadePathVertex's own conditions.
RT_FN bool resamplesDirectAt(RT_IN(HitPayload) hit, uint segment, RT_IN(PathState) path)
{
    if (hit.material == kNoIndex || uniforms.emitterCount == 0u || segment + 1u >= uniforms.depth ||
        path.pendingSurvival == 0.0f)
        return false;
    const RT_TAG(MaterialType) type = materials[hit.material].type;
    return (kHasLambertian && type == RT_ENUM(MaterialType, Lambertian)) ||
           (kHasIsotropic && type == RT_ENUM(MaterialType, Isotropic)) || isMicrofacet(type);
}

/// The shading point of `s` as NEE sees it at that vertex (Shading/PathVertex.h, Shading/DirectLighting.h).
RT_FN RestirVertex restirVertexOf(RT_IN(RestirSurface) s)
{
    RestirVertex v;
    v.valid = s.hit.material != kNoIndex;
    v.phase = false;
    v.microfacet = false;
    v.transmits = false;
    v.position = s.hit.position;
    v.normal = s.hit.normal;
    v.offsetScale = s.hit.offsetScale;
    v.origin = s.hit.position;
    v.receiver = vec3(0.0f);
    v.ns = s.hit.normal;
    v.albedo = vec3(0.0f);
    v.wo = vec3(0.0f);
    if (!v.valid)
        return v;
    const MaterialData m = materials[s.hit.material];
    const bool medium = kHasMedia && (s.hit.flags & kHitMedium) != 0u;
    SurfaceHit surface;
    surface.position = s.hit.position;
    surface.normal = s.hit.normal;
    surface.frontFace = medium || dot(s.incoming, s.hit.normal) < 0.0f;
    surface.shadingNormal = surface.frontFace ? s.hit.normal : -s.hit.normal;
    surface.uv = s.hit.uv;
    surface.incoming = s.incoming;
    v.phase = kHasIsotropic && m.type == RT_ENUM(MaterialType, Isotropic);
    v.microfacet = isMicrofacet(m.type);
    v.transmits = v.microfacet && m.type == RT_ENUM(MaterialType, RoughDielectric);
    v.ns = surface.shadingNormal;
    v.origin = medium || v.transmits ? surface.position
                                     : offsetRayOrigin(surface.position, surface.shadingNormal, s.hit.offsetScale);
    v.receiver = v.phase || v.transmits ? vec3(0.0f) : surface.shadingNormal;
    if (v.microfacet)
    {
        v.bsdf = microfacetBsdfAt(m, surface);
        v.wo = -normalize(s.incoming);
    }
    else
        v.albedo = evaluateTexture(m.albedoTexture, surface.uv, surface.position);
    return v;
}

/// f(y) without visibility (the header's integrand, linear RGB, per unit area at y) of point `point` on light
/// `light` seen from `v`: 0 where the light faces away (one-sided emitters), the BSDF is 0 or nothing is emitted.
/// Its luminance is restir-di's target function.
RT_FN vec3 restirIntegrand(RT_IN(RestirVertex) v, uint light, vec3 point)
{
    if (!v.valid || light == kNoIndex)
        return vec3(0.0f);
    const LightData l = lights[light];
    const vec3 d = point - v.origin;
    const float dist2 = dot(d, d);
    if (!(dist2 > 0.0f))
        return vec3(0.0f);
    const vec3 wi = d / sqrt(dist2);
    const vec3 ny = RT_LIGHT_IS(l.shape, Sphere) ? normalize(point - l.p0) : l.normal;
    const float cosLight = -dot(ny, wi);
    if (uniforms.unidirectionalLight != 0u ? !(cosLight > 0.0f) : cosLight == 0.0f)
        return vec3(0.0f);
    vec3 f;
    if (v.microfacet)
    {
        float bsdfPdf;
        f = evalMicrofacetBsdf(v.bsdf, v.wo, wi, bsdfPdf);
    }
    else
        f = v.albedo * diffusePdf(v.phase, v.ns, wi); // the lobe's f |cos| is albedo x its pdf
    if (!(max(f.x, max(f.y, f.z)) > 0.0f))
        return vec3(0.0f);
    // The light's surface coordinates as its samplers report them (Lights/LightSample.h): (a, b) on quads,
    // barycentrics on triangles (both through the plane's duals), 0 on spheres.
    const vec3 planar = point - l.p0;
    const vec2 uvLight = RT_LIGHT_IS(l.shape, Sphere) ? vec2(0.0f) : vec2(dot(planar, l.dualU), dot(planar, l.dualV));
    const vec3 le = evaluateTexture(materials[l.material].emissionTexture, uvLight, point);
    return f * le * (abs(cosLight) / dist2);
}

/// One candidate of restir-di's initial resampling at `v` (Bitterli et al. 2020, Alg. 3's candidates): a light
/// selected with uSelect and a point on it sampled with u, as NEE does. Returns its resampling weight
/// p-hat(y) / p(y) (0 when it contributes nothing); `light`, `point` and `target` (p-hat(y)) describe it, and
/// `lightSample` how its light sample was made for the stats, as NEE's ShadowRay::lightSample (0: no light picked).
RT_FN float restirCandidate(RT_IN(RestirVertex) v, float uSelect, vec2 u, RT_OUT(uint) light, RT_OUT(vec3) point,
                            RT_OUT(float) target, RT_OUT(uint) lightSample)
{
    light = kNoIndex;
    point = vec3(0.0f);
    target = 0.0f;
    lightSample = 0u;
    float pmf;
    const uint picked = selectLight(RT_PASS(lightAlias) RT_PASS(lightBvh) settingLightSelection(), uSelect,
                                    uniforms.emitterCount, v.origin, v.receiver, uniforms.unidirectionalLight == 0u, pmf);
    if (picked == kNoIndex)
        return 0.0f;
    LightSample ls;
    const bool sampled = sampleLight(lights[picked], settingLightSampler(), v.origin, v.receiver, u, ls);
    lightSample = kLightSampleDrawn | ls.outcome;
    if (!sampled)
        return 0.0f;
    const float cosLight = abs(dot(ls.normal, ls.wi));
    const float areaPdf = pmf * ls.pdf * cosLight / (ls.distance * ls.distance);
    if (!(areaPdf > 0.0f))
        return 0.0f;
    light = picked;
    point = ls.point;
    target = luminance(restirIntegrand(v, picked, ls.point));
    return target / areaPdf;
}

/// The shadow ray from `v` to `point` (NEE's: Shading/PathVertex.h, Shading/DirectLighting.h); pending, its
/// contribution 0 (the caller knows what it weighs).
RT_FN ShadowRay restirShadowRay(RT_IN(RestirVertex) v, vec3 point)
{
    ShadowRay shadow;
    shadow.pending = true;
    shadow.contribution = vec3(0.0f);
    shadow.lightSample = 0u; // counted as its candidate was (restirCandidate)
    const vec3 d = point - v.origin;
    const float distance = length(d);
    shadow.direction = distance > 0.0f ? d / distance : v.ns;
    shadow.distance = distance * (1.0f - 1e-4f);
    shadow.origin = v.origin;
    if (v.transmits)
        leaveGlass(shadow, v.position, v.normal, v.offsetScale);
    return shadow;
}

/// p-hat_v(y) V_v(y): the target of point `point` on light `light` at vertex v if v sees it (a shadow ray traced as
/// camera sample `sampleIndex` of `pixel`, whose path found v: the host's restirVisible), else 0. Pairwise MIS and
/// the combinations' resampling weights read targets with visibility: a point occluded where it would be reused
/// is never chosen there, and never weighs on the points that are (docs/RESTIR.md).
RT_FN float visibleTarget(RT_IN(RestirVertex) v, uint light, vec3 point, uvec2 pixel, uint sampleIndex)
{
    const float target = luminance(restirIntegrand(v, light, point));
    return target > 0.0f && restirVisible(v, point, pixel, sampleIndex) ? target : 0.0f;
}

/// Combines the host's inputs [0, n) at vertex q, input 0's (the canonical input, q = its vertex), with `rng`:
/// with pairwise MIS and targets that include visibility (2 (n - 1) shadow rays at most: Shared/Restir.h,
/// docs/RESTIR.md), or, when uniforms.restirBiased, Bitterli et al. 2020's Alg. 4 (weights M p-hat_q W, W
/// normalised by the inputs' summed M, the chosen point then tested for visibility at q). Every input draws one
/// number, in order. Temporal reuse is the case n = 2 (Alg. 5 with its pixel's last reservoir), spatial reuse
/// n = 1 + the neighbours kept.
RT_FN Reservoir combineReservoirs(RT_IN(RestirVertex) q, int n, RT_INOUT(Rng) rng)
{
    RestirCombination c = beginCombination();
    const Reservoir own = restirInputReservoir(0);
    if (uniforms.restirBiased != 0u)
    {
        offerInput(c, own, own.target, own.count, 0, nextFloat(rng));
        for (int i = 1; i < n; ++i)
        {
            const Reservoir r = restirInputReservoir(i);
            const float target = r.weight > 0.0f ? luminance(restirIntegrand(q, r.light, r.point)) : r.target;
            offerInput(c, r, target, r.count, i, nextFloat(rng));
        }
        Reservoir combined = finishCombination(c, c.result.count);
        if (c.chosen > 0 && !restirVisible(q, combined.point, restirInputPixel(0), restirInputSample(0)))
            combined.weight = 0.0f;
        return combined;
    }
    const float k = float(n - 1);
    float canonicalMis = 0.0f;
    if (own.weight > 0.0f)
    {
        canonicalMis = n == 1 ? 1.0f : 0.0f;
        for (int i = 1; i < n; ++i)
            canonicalMis += pairwiseCanonicalTerm(k, own.count, own.target, restirInputReservoir(i).count,
                                                  visibleTarget(restirInputVertex(i), own.light, own.point,
                                                                restirInputPixel(i), restirInputSample(i)));
    }
    offerInput(c, own, own.target, canonicalMis, 0, nextFloat(rng));
    for (int i = 1; i < n; ++i)
    {
        const Reservoir r = restirInputReservoir(i);
        float targetHere = 0.0f;
        float mis = 0.0f;
        if (r.weight > 0.0f)
        {
            targetHere = visibleTarget(q, r.light, r.point, restirInputPixel(0), restirInputSample(0));
            mis = pairwiseNeighbourMis(k, r.count, r.target, own.count, targetHere);
        }
        offerInput(c, r, targetHere, mis, i, nextFloat(rng));
    }
    return finishCombination(c, 1.0f);
}

/// Whether a neighbour's vertex b may be reused at vertex a (Bitterli et al. 2020, §6): both exist, their shading
/// normals within 25 degrees and their camera-path lengths within 10 %. A heuristic for variance only: the
/// unbiased combination stays unbiased whatever it keeps.
RT_FN bool restirSimilar(RT_IN(RestirSurface) a, RT_IN(RestirVertex) va, RT_IN(RestirSurface) b, RT_IN(RestirVertex) vb)
{
    return va.valid && vb.valid && abs(b.depth - a.depth) <= 0.1f * a.depth && dot(va.ns, vb.ns) >= kRestirMinNormalCos;
}

/// The pixel a spatial neighbour is drawn at, uniformly in the disk of radius uniforms.restirRadius about `pixel`,
/// from u in [0, 1)^2; false when it falls outside the width x height image or on the pixel itself.
RT_FN bool restirNeighbour(uvec2 pixel, vec2 u, uint width, uint height, RT_OUT(uvec2) neighbour)
{
    const float radius = float(uniforms.restirRadius) * sqrt(u.x);
    const float angle = 2.0f * kPi * u.y;
    const int x = int(pixel.x) + int(floor(radius * preciseCos(angle) + 0.5f));
    const int y = int(pixel.y) + int(floor(radius * preciseSin(angle) + 0.5f));
    const bool inside = x >= 0 && y >= 0 && x < int(width) && y < int(height);
    neighbour = inside ? uvec2(uint(x), uint(y)) : pixel;
    return inside && (x != int(pixel.x) || y != int(pixel.y));
}

#endif