// The path tracer of the CPU engine: one camera path, iterative (no recursion, no allocation).
// Two estimators share the loop (shared/spec and RTTROYL):
//  - BsdfOnly (books 1-2): every bounce follows the material's sampled direction; the weight is the albedo.
//  - Mixture (book 3, §9-12): at diffuse and isotropic vertices, with probability 1/2 sample the BSDF, else
//    pick one light of the scene's list uniformly and sample a direction towards it; weight the direction by
//    f cos / (1/2 p_bsdf + 1/2 mean_j p_light_j): the balance-heuristic one-sample MIS of the two strategies,
//    without shadow rays. Specular vertices follow their single direction.
// The GLSL twin is Shaders/RayGen.rgen + Shaders/Integrator.glsl.
#pragma once

#include <cstdint>

#include "Integrator/Background.h"
#include "Materials/Dielectric.h"
#include "Materials/Isotropic.h"
#include "Materials/Lambertian.h"
#include "Materials/Metal.h"
#include "Math/RayOffset.h"
#include "Render/RenderSettings.h"
#include "Sampling/LightSampling.h"
#include "Scene/CpuScene.h"
#include "Textures/TextureEval.h"

namespace rt::cpu
{
struct PathOptions
{
    int depth = 50; // ray segments traced at most
    Estimator estimator = Estimator::Mixture;
    bool unidirectionalLight = true;
};

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

/// Incident radiance along `ray` (linear RGB). `segments` is incremented per ray traced.
inline vec3 tracePath(const CpuScene& cs, const PathOptions& options, Ray ray, Rng& rng, std::uint64_t& segments)
{
    const Scene& scene = cs.source();
    const bool mixture = options.estimator == Estimator::Mixture && !scene.lights.empty();
    vec3 radiance(0.0f);
    vec3 throughput(1.0f);
    const TraceRay::Needs needs = cs.rayNeeds();
    for (int segment = 0; segment < options.depth; ++segment)
    {
        const TraceRay r(ray, needs);
        HitRecord hit;
        ++segments;
        if (!cs.intersect(r, 0.0f, kInfinity, hit, rng))
        {
            radiance += throughput * backgroundRadiance(scene.background, ray.direction);
            break;
        }
        const SurfaceInteraction si = cs.interaction(r, hit);
        const MaterialData& mat = scene.materials[si.material];
        const bool frontFace = si.medium || glm::dot(ray.direction, si.n) < 0.0f;
        const vec3 ns = frontFace ? si.n : -si.n;

        if (mat.emissionTexture != kNoIndex && (frontFace || !options.unidirectionalLight))
            radiance += throughput * evalTexture(scene, mat.emissionTexture, si.uv, si.p);
        if (segment + 1 == options.depth)
            break; // RTIOW's depth: the next segment would return black

        vec3 wi;
        switch (mat.type)
        {
        case MaterialType::DiffuseLight: return radiance;
        case MaterialType::Metal:
        {
            const vec2 u(rng.nextFloat(), rng.nextFloat());
            if (!scatterMetal(ray.direction, ns, mat.fuzz, u, wi))
                return radiance;
            throughput *= evalTexture(scene, mat.albedoTexture, si.uv, si.p);
            break;
        }
        case MaterialType::Dielectric:
            wi = scatterDielectric(ray.direction, ns, frontFace ? 1.0f / mat.ior : mat.ior, rng.nextFloat());
            break;
        case MaterialType::Lambertian:
        case MaterialType::Isotropic:
        {
            const bool phase = mat.type == MaterialType::Isotropic;
            const vec3 albedo = evalTexture(scene, mat.albedoTexture, si.uv, si.p);
            if (!mixture)
            {
                const vec2 u(rng.nextFloat(), rng.nextFloat());
                wi = phase ? sampleIsotropic(u) : sampleLambertian(ns, u);
                throughput *= albedo;
                break;
            }
            const float choice = rng.nextFloat();
            const vec2 u(rng.nextFloat(), rng.nextFloat());
            std::size_t sampled = std::size_t(-1);
            float sampledPdf = 0.0f;
            if (choice < 0.5f)
                wi = phase ? sampleIsotropic(u) : sampleLambertian(ns, u);
            else
            {
                const auto n = static_cast<float>(scene.lights.size());
                sampled = static_cast<std::size_t>(minf((2.0f * choice - 1.0f) * n, n - 1.0f)); // the choice's bits
                LightSample ls;
                if (!sampleLight(scene.lights[sampled], si.p, u, ls))
                    return radiance;
                wi = ls.wi;
                sampledPdf = ls.pdf;
            }
            const float scatteringPdf = phase ? isotropicPdf() : lambertianPdf(ns, wi);
            const float pdf = mixturePdf(scene, si.p, wi, scatteringPdf, sampled, sampledPdf);
            if (!(scatteringPdf > 0.0f) || !(pdf > 0.0f))
                return radiance;
            throughput *= albedo * (scatteringPdf / pdf);
            break;
        }
        }
        const vec3 origin = si.medium ? si.p : offsetRayOrigin(si.p, glm::dot(wi, si.n) > 0.0f ? si.n : -si.n, si.offsetScale);
        ray = Ray{origin, wi, ray.time};
    }
    return radiance;
}
} // namespace rt::cpu
