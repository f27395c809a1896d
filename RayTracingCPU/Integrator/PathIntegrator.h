// The path tracer of the CPU engine: one camera path, iterative (no recursion, no allocation).
// Four estimators share the loop (Shared/HostDevice.h Estimator):
//  - BsdfOnly (books 1-2): every bounce follows the material's sampled direction; the weight is the albedo.
//  - Mixture (book 3, §9-12): at diffuse and isotropic vertices, with probability 1/2 sample the BSDF, else
//    pick one light of the scene's list uniformly and sample a direction towards it; weight the direction by
//    f cos / (1/2 p_bsdf + 1/2 mean_j p_light_j): the balance-heuristic one-sample MIS of the two strategies,
//    without shadow rays. Specular vertices follow their single direction.
//  - Nee / NeeMis (Veach 1997 §9.2; pbrt-v4 PathIntegrator): at diffuse and isotropic vertices a shadow ray
//    to a point of one selected emitter (next-event estimation), then the BSDF direction continues the path.
//    Emission a BSDF ray finds after such a vertex counts 0 (Nee: NEE already did) or with the power
//    heuristic's weight against NEE's pdf of the same direction (NeeMis); NEE's own sample gets the
//    complementary weight. After specular vertices and from the camera, emission counts in full.
// Russian roulette (Shared/RussianRoulette.h) may end any path from its third segment: drawn after scattering,
// it ends the path at once (NEE estimators, pbrt-v4) or after the next hit's emission (rouletteAfterNextHit).
// The loop is a template on PathCode: the general instance reads the estimator from PathOptions and handles
// media and every texture kind; the others are compiled for one estimator and without media or non-solid
// textures, for scenes that have none (Integrator/PathVariants.h picks one per render, issue 11). Every
// instance draws the same random numbers in the same order, so they render the same image bit for bit.
// The GLSL twin of this loop is Shaders/Integrator.glsl; what they compute per vertex (warps, light
// samplers, selection, MIS weights, roulette) is shared code in Common/Shared.
#pragma once

#include <cstdint>

#include "Integrator/Background.h"
#include "Math/RayOffset.h"
#include "Render/RenderSettings.h"
#include "Sampling/LightSampling.h"
#include "Scene/CpuScene.h"
#include "Shared/DiffuseScattering.h"
#include "Shared/LightSelection.h"
#include "Shared/Mis.h"
#include "Shared/RussianRoulette.h"
#include "Shared/SpecularScattering.h"
#include "Textures/TextureEval.h"

// The path loop compiled as one function, with the traversal, the packet tests, the samplers and the random
// numbers inlined into it (GCC's and Clang's flatten): 1.08x on book 3's final scene on one core, 1.05-1.12x on
// the catalogue, the same images bit for bit (docs/PERFORMANCE.md §1). Elsewhere the compiler decides.
#if defined(__GNUC__)
#define RT_FLATTEN [[gnu::flatten]]
#else
#define RT_FLATTEN
#endif

namespace rt::cpu
{
struct PathOptions
{
    int depth = 50; // ray segments traced at most
    Estimator estimator = Estimator::NeeMis;
    LightSampler lightSampler = LightSampler::Projected; // NEE's
    LightSelection lightSelection = LightSelection::Bvh; // NEE's
    bool russianRoulette = true;
    bool unidirectionalLight = true;
};

/// What an instance of tracePath is compiled for. A structural type: it is the template's argument.
struct PathCode
{
    bool general = true; // the estimator from PathOptions at run time; media and every texture kind
    Estimator estimator = Estimator::NeeMis; // when !general
    bool media = true; // when !general: the scene has participating media (isotropic vertices, medium hits)
    bool textures = true; // when !general: a material reads a texture other than a solid colour
};

/// A material's texture at a hit: the solid colour itself when the instance has no other textures.
template <PathCode C>
inline vec3 texture(const Scene& scene, std::uint32_t index, const vec2& uv, const vec3& p)
{
    if constexpr (!C.general && !C.textures)
        return scene.textures[index].color0;
    else
        return evalTexture(scene, index, uv, p);
}

/// Solid-angle pdf of the book-3 mixture for direction wi leaving p, given the BSDF strategy's pdf. When wi
/// was sampled from light `known`, its pdf `knownPdf` (= lightPdf of that light) is reused, not recomputed.
inline float mixturePdf(const Scene& scene, const vec3& p, const vec3& wi, float bsdfPdf,
                        std::size_t known = std::size_t(-1), float knownPdf = 0.0f)
{
    float lights = 0.0f;
    for (std::size_t i = 0; i < scene.lights.size(); ++i)
        lights += i == known ? knownPdf : lightPdf(scene.lights[i], p, wi);
    return 0.5f * bsdfPdf + 0.5f * lights / static_cast<float>(scene.lights.size());
}

/// Probability that NEE at `origin` (receiver normal `receiver`, 0 in a medium) selects `light`.
inline float selectionPmf(const CpuScene& cs, const PathOptions& options, std::uint32_t light, const vec3& origin,
                          const vec3& receiver)
{
    return shader::lightSelectionPmf(cs.lightAlias(), cs.lightBvh(), cs.lightBvhLeaves(), options.lightSelection,
                                     light, cs.emitterCount(), origin, receiver, !options.unidirectionalLight);
}

/// Emitted radiance of the light sample `ls` towards its shading point: 0 from a light's back face when
/// emitters are one-sided.
template <PathCode C>
inline vec3 sampledEmission(const Scene& scene, const LightData& light, const LightSample& ls, bool unidirectional)
{
    if (unidirectional && glm::dot(ls.wi, ls.normal) >= 0.0f)
        return vec3(0.0f);
    return texture<C>(scene, scene.materials[light.material].emissionTexture, ls.uv, ls.point);
}

/// Next-event estimation at a diffuse or isotropic vertex: one emitter selected (uniformly, by power or by the
/// light BVH), one point on it, a shadow ray. `origin` is where the vertex's rays leave from (the hit point offset to the side of the
/// shading normal `ns`; the point itself in a medium): lights are sampled from there and the BSDF ray leaves
/// from there too, so both strategies see one geometry and their MIS weights sum to 1 for every direction
/// (sampled from the unoffset point, a sphere light's silhouette shifted between them: +0.05 % on a test).
/// Returns f cos Le / (pmf pdf) times the MIS weight (nee-mis: the power heuristic against the BSDF
/// strategy's pdf of the same direction; nee: 1), or 0 when the point is occluded or faces away. Takes the
/// vertex's first three numbers: uSelect for the selection, u for the point.
template <PathCode C>
inline vec3 estimateDirect(const CpuScene& cs, const PathOptions& options, const vec3& origin, const vec3& ns,
                           bool phase, const vec3& albedo, float time, float uSelect, vec2 u, Rng& rng,
                           std::uint64_t& segments)
{
    const Scene& scene = cs.source();
    const std::uint32_t emitters = cs.emitterCount();
    float pmf;
    const vec3 receiver = phase ? vec3(0.0f) : ns; // no horizon in a medium
    const std::uint32_t picked = shader::selectLight(cs.lightAlias(), cs.lightBvh(), options.lightSelection, uSelect,
                                                     emitters, origin, receiver, !options.unidirectionalLight, pmf);
    if (picked == kNoIndex)
        return vec3(0.0f); // the light BVH proved that no emitter reaches this point
    const LightData& light = scene.lights[picked];
    LightSample ls;
    if (!sampleLight(light, options.lightSampler, origin, receiver, u, ls))
        return vec3(0.0f);
    const float bsdfPdf = shader::diffusePdf(phase, ns, ls.wi); // f cos = albedo bsdfPdf
    if (!(bsdfPdf > 0.0f))
        return vec3(0.0f);
    const vec3 le = sampledEmission<C>(scene, light, ls, options.unidirectionalLight);
    if (maxComponent(le) <= 0.0f)
        return vec3(0.0f);
    const float lightPdfTotal = pmf * ls.pdf;
    const Estimator estimator = C.general ? options.estimator : C.estimator;
    const float weight = estimator == Estimator::NeeMis ? shader::powerHeuristic(lightPdfTotal, bsdfPdf) : 1.0f;
    ++segments;
    // The shadow ray stops short of the light's surface by a relative margin far above the rounding of the
    // sampled point and of the light's intersection test.
    if (cs.occluded(TraceRay(Ray{origin, ls.wi, time}, cs.rayNeeds()), 0.0f, ls.distance * (1.0f - 1e-4f), rng))
        return vec3(0.0f);
    return albedo * le * (weight * bsdfPdf / lightPdfTotal);
}

/// One camera path between two of its segments: what the loop carries from one ray to the next.
struct PathState
{
    Ray ray; // the segment to trace next
    vec3 radiance = vec3(0.0f); // gathered so far (linear RGB)
    vec3 throughput = vec3(1.0f);
    // The vertex the current ray left, for the MIS weight of the emission it finds: the ray's origin and the
    // BSDF strategy's solid-angle pdf of its direction; 0 when NEE did not run there (the camera, a specular
    // vertex), so the emission counts in full.
    vec3 previousPoint = vec3(0.0f);
    vec3 previousNormal = vec3(0.0f); // its receiver normal for the projected samplers (0 in a medium)
    float previousBsdfPdf = 0.0f;
    // A roulette decided at the last vertex, applied once this segment's emission is gathered
    // (rouletteAfterNextHit): 0 ends the path, else the throughput is scaled by 1 / pendingSurvival.
    float pendingSurvival = 1.0f;
    int segment = 0; // segments traced before path.ray
};

/// What the path does with the hit of its segment path.ray (`found` false: the ray left the scene): gathers
/// the emission there, scatters, and sets path.ray to the next segment. Returns false when the path ends
/// (path.radiance is then its estimate). `segments` counts the shadow rays it traces.
template <PathCode C>
inline bool continuePath(const CpuScene& cs, const PathOptions& options, PathState& path, bool found,
                         const HitRecord& hit, Rng& rng, std::uint64_t& segments)
{
    const Scene& scene = cs.source();
    const Estimator estimator = C.general ? options.estimator : C.estimator;
    const bool mixture = estimator == Estimator::Mixture && !scene.lights.empty();
    const bool nee = (estimator == Estimator::Nee || estimator == Estimator::NeeMis) && cs.emitterCount() > 0;
    const bool mis = estimator == Estimator::NeeMis;
    const bool rouletteAfterNextHit = shader::rouletteAfterNextHit(estimator);
    constexpr bool kMedia = C.general || C.media;
    const Ray ray = path.ray;
    vec3& throughput = path.throughput;
    if (!found)
    {
        path.radiance += throughput * backgroundRadiance(scene.background, ray.direction);
        return false;
    }
    const SurfaceInteraction si = cs.interaction(ray, hit);
    const MaterialData& mat = scene.materials[si.material];
    const bool inMedium = kMedia && si.medium;
    const bool frontFace = inMedium || glm::dot(ray.direction, si.n) < 0.0f;
    const vec3 ns = frontFace ? si.n : -si.n;

    if (mat.emissionTexture != kNoIndex && (frontFace || !options.unidirectionalLight))
    {
        float weight = 1.0f;
        if (path.previousBsdfPdf > 0.0f && si.light != kNoIndex)
            weight = mis ? shader::powerHeuristic(path.previousBsdfPdf,
                                                  selectionPmf(cs, options, si.light, path.previousPoint,
                                                               path.previousNormal) *
                                                      lightPdf(scene.lights[si.light], options.lightSampler,
                                                               path.previousPoint, path.previousNormal, ray.direction))
                         : 0.0f;
        path.radiance += throughput * texture<C>(scene, mat.emissionTexture, si.uv, si.p) * weight;
    }
    if (path.segment + 1 == options.depth)
        return false; // RTIOW's depth: the next segment would return black
    if (path.pendingSurvival == 0.0f)
        return false;
    if (path.pendingSurvival < 1.0f)
    {
        throughput /= path.pendingSurvival;
        path.pendingSurvival = 1.0f;
    }

    vec3 wi;
    path.previousBsdfPdf = 0.0f;
    switch (mat.type)
    {
    case MaterialType::DiffuseLight: return false;
    case MaterialType::Metal:
    {
        const vec2 u = rng.next2D();
        if (!shader::sampleFuzzyMirror(ray.direction, ns, mat.fuzz, u, wi))
            return false;
        throughput *= texture<C>(scene, mat.albedoTexture, si.uv, si.p);
        break;
    }
    case MaterialType::Dielectric:
        wi = shader::sampleDielectric(ray.direction, ns, frontFace ? 1.0f / mat.ior : mat.ior, mat.fresnel,
                                      rng.nextFloat());
        break;
    case MaterialType::Lambertian:
    case MaterialType::Isotropic:
    {
        const bool phase = kMedia && mat.type == MaterialType::Isotropic;
        const vec3 albedo = texture<C>(scene, mat.albedoTexture, si.uv, si.p);
        if (!mixture)
        {
            // NEE's three numbers and the direction's two, drawn in that order before any of them is used:
            // independent draws the CPU overlaps (a Sobol draw is a chain of about 60 cycles).
            const float uSelect = nee ? rng.nextFloat() : 0.0f;
            const vec2 uLight = nee ? rng.next2D() : vec2(0.0f);
            const vec2 u = rng.next2D();
            if (nee)
            {
                // The BSDF ray leaves from this origin too (below): sampleDiffuse keeps to the side of ns.
                const vec3 origin = inMedium ? si.p : offsetRayOrigin(si.p, ns, si.offsetScale);
                path.radiance += throughput * estimateDirect<C>(cs, options, origin, ns, phase, albedo, ray.time,
                                                                uSelect, uLight, rng, segments);
            }
            wi = shader::sampleDiffuse(phase, ns, u);
            throughput *= albedo;
            if (nee)
            {
                path.previousBsdfPdf = shader::diffusePdf(phase, ns, wi);
                path.previousNormal = phase ? vec3(0.0f) : ns;
            }
            break;
        }
        const float choice = rng.nextFloat();
        const vec2 u = rng.next2D();
        std::size_t sampled = std::size_t(-1);
        float sampledPdf = 0.0f;
        if (choice < 0.5f)
            wi = shader::sampleDiffuse(phase, ns, u);
        else
        {
            const auto n = static_cast<float>(scene.lights.size());
            sampled = static_cast<std::size_t>(minf((2.0f * choice - 1.0f) * n, n - 1.0f)); // the choice's bits
            LightSample ls;
            if (!sampleLight(scene.lights[sampled], si.p, u, ls))
                return false;
            wi = ls.wi;
            sampledPdf = ls.pdf;
        }
        const float scatteringPdf = shader::diffusePdf(phase, ns, wi);
        const float pdf = mixturePdf(scene, si.p, wi, scatteringPdf, sampled, sampledPdf);
        if (!(scatteringPdf > 0.0f) || !(pdf > 0.0f))
            return false;
        throughput *= albedo * (scatteringPdf / pdf);
        break;
    }
    }
    if (options.russianRoulette)
    {
        const float survival = shader::rouletteSurvival(throughput, static_cast<std::uint32_t>(path.segment));
        if (survival < 1.0f)
        {
            const bool survives = rng.nextFloat() < survival;
            if (rouletteAfterNextHit)
                path.pendingSurvival = survives ? survival : 0.0f;
            else if (!survives)
                return false;
            else
                throughput /= survival;
        }
    }
    const vec3 origin =
        inMedium ? si.p : offsetRayOrigin(si.p, glm::dot(wi, si.n) > 0.0f ? si.n : -si.n, si.offsetScale);
    path.ray = Ray{origin, wi, ray.time};
    path.previousPoint = origin;
    return ++path.segment < options.depth;
}

/// Incident radiance along `ray` (linear RGB). `segments` is incremented per ray traced, shadow rays included.
/// An instance other than the general one must match the scene and options (Integrator/PathVariants.h).
template <PathCode C = PathCode{}>
RT_FLATTEN inline vec3 tracePath(const CpuScene& cs, const PathOptions& options, Ray ray, Rng& rng, std::uint64_t& segments)
{
    PathState path{ray};
    if (options.depth <= 0)
        return path.radiance;
    const TraceRay::Needs needs = cs.rayNeeds();
    for (;;)
    {
        HitRecord hit{};
        ++segments;
        const bool found = cs.intersect(TraceRay(path.ray, needs), 0.0f, kInfinity, hit, rng);
        if (!continuePath<C>(cs, options, path, found, hit, rng, segments))
            return path.radiance;
    }
}
} // namespace rt::cpu
