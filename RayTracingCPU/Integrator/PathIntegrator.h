// The path loop of the CPU engine: one camera path, iterative (no recursion, no allocation). Between two traced
// segments a path runs the path vertex that both engines share (Shared/Shading/PathVertex.h, which describes the
// estimators), compiled into CpuShading; the loop traces its rays: the next segment and, after a vertex that
// sampled a light, NEE's shadow ray. The loop is a template on PathCode: the general instance reads the
// estimator from the uniforms and handles media and every texture kind; the others are compiled for one
// estimator and without media or non-solid textures, for scenes that have none (Integrator/PathVariants.h picks
// one per render, issue 11). Every instance draws the same random numbers in the same order, so they render
// the same image bit for bit. The GPU's loops are Shaders/Integrator.glsl (megakernel) and Shaders/Wavefront/.
#pragma once

#include <cstdint>
#include <span>

#include "Integrator/CpuShading.h"
#include "Integrator/TraceCounts.h"
#include "Render/RenderSettings.h"
#include "Engine/CpuScene.h"
#include "Shared/Medium.h"

// The path loop compiled as one function, with the traversal, the packet tests, the samplers and the random
// numbers inlined into it (GCC's and Clang's flatten): 1.08x on book 3's final scene on one core, 1.05-1.12x on
// the catalogue, the same images bit for bit (docs/notebook/PERFORMANCE.md §1). Elsewhere the compiler decides.
#if defined(__GNUC__)
#define RT_FLATTEN [[gnu::flatten]]
#else
#define RT_FLATTEN
#endif

namespace rt::cpu
{
/// One camera sample to trace: its camera ray (whose time every ray of the path keeps) and random stream.
struct PathJob
{
    Ray ray;
    shader::Rng rng{0u};
    std::uint32_t mediumSeed = 0; // mediumPathSeed of the render's seed and the sample's pixel (Shared/Medium.h)
};

/// Camera sample `sampleIndex` of pixel (x, y) (Shared/Shading/Camera.h): its ray and its stream; its medium seed
/// where the scene has `media`.
RT_FLATTEN inline PathJob cameraJob(CpuShading<PathCode{}>& shading, bool media, std::uint32_t x, std::uint32_t y,
                                    std::uint32_t sampleIndex)
{
    const uvec2 pixel(x, y);
    shader::Rng rng = shading.rngForCameraSample(pixel, sampleIndex);
    const shader::CameraSample cs = shading.drawCameraSample(rng, pixel, sampleIndex);
    vec3 origin, direction;
    shading.generateRay(cs, origin, direction);
    return {Ray{origin, direction, cs.time}, rng, media ? shader::mediumPathSeed(shading.cameraSampleSeed(sampleIndex), pixel) : 0u};
}

/// Counts the path ray of segment `segment`: its camera ray (0) or an extension ray (without a branch).
inline void countPathRay(TraceCounts& counts, std::uint32_t segment)
{
    counts.rays.camera += segment == 0;
    counts.rays.extension += segment != 0;
}

/// The hit of `ray` (`found` false: it left the scene) as the shared vertex reads it.
inline shader::HitPayload hitPayload(const CpuScene& cs, const Ray& ray, bool found, const HitRecord& hit)
{
    shader::HitPayload payload{};
    payload.material = kNoIndex;
    if (found)
    {
        const SurfaceInteraction si = cs.interaction(ray, hit);
        payload.position = si.p;
        payload.material = si.material;
        payload.normal = si.n;
        payload.flags = si.medium ? shader::kHitMedium : 0u;
        payload.uv = si.uv;
        payload.offsetScale = si.offsetScale;
        payload.lightSlot = si.light;
    }
    return payload;
}

/// What the path does at `payload`, the hit of its ray: the shared vertex (`directResampled`: restir-di's
/// resampled vertex, Shared/Shading/PathVertex.h), then its shadow ray if it sampled a light. Returns false when
/// the path ends (path.radiance is then its estimate). `counts` counts the shadow ray it traces and NEE's light
/// sample.
template <PathCode C>
inline bool continuePath(CpuShading<C>& shading, const CpuScene& cs, shader::PathState& path, const PathJob& job,
                         std::uint32_t segment, const shader::HitPayload& payload, bool directResampled,
                         TraceCounts& counts)
{
    shader::ShadowRay shadow{}; // its fields but pending are set only when pending, which GCC cannot follow
    const bool goesOn = shading.shadePathVertex(path, segment, payload, shadow, directResampled);
    countLightSample(counts.lightSamples, shadow.lightSample);
    if (shadow.pending)
    {
        ++counts.rays.shadow;
        if (!cs.occluded(TraceRay(Ray{shadow.origin, shadow.direction, job.ray.time}, cs.rayNeeds()), 0.0f, shadow.distance,
                         job.mediumSeed))
            path.radiance += shadow.contribution;
    }
    return goesOn;
}

/// continuePath at the hit of the path's ray (`found` false: the ray left the scene), no vertex resampled.
template <PathCode C>
inline bool continuePath(CpuShading<C>& shading, const CpuScene& cs, shader::PathState& path, const PathJob& job,
                         std::uint32_t segment, bool found, const HitRecord& hit, TraceCounts& counts)
{
    return continuePath<C>(shading, cs, path, job, segment,
                           hitPayload(cs, Ray{path.origin, path.direction, job.ray.time}, found, hit), false, counts);
}

/// Traces the path of `job` to its end and returns its radiance (linear RGB). `counts` counts what it traces.
template <PathCode C>
inline vec3 tracePath(CpuShading<C>& shading, const CpuScene& cs, const PathJob& job, TraceCounts& counts)
{
    shader::PathState path = shader::startPath(job.ray.origin, job.ray.direction, job.rng);
    const TraceRay::Needs needs = cs.rayNeeds();
    for (std::uint32_t segment = 0; segment < shading.uniforms.depth; ++segment)
    {
        HitRecord hit{};
        countPathRay(counts, segment);
        const bool found = cs.intersect(TraceRay(Ray{path.origin, path.direction, job.ray.time}, needs), 0.0f, kInfinity,
                                        hit, job.mediumSeed);
        if (!continuePath<C>(shading, cs, path, job, segment, found, hit, counts))
            break;
    }
    return path.radiance;
}

/// Traces every job's path, one after the other, and writes job i's radiance (linear RGB) to radiance[i].
/// `counts` counts the rays traced and NEE's light samples. An instance other than the general one must
/// match the scene and the uniforms (Integrator/PathVariants.h).
template <PathCode C = PathCode{}>
RT_FLATTEN inline void traceJobs(const CpuScene& cs, const shader::RenderUniforms& uniforms, std::span<const PathJob> jobs,
                                 vec3* radiance, TraceCounts& counts)
{
    CpuShading<C> shading(cs, uniforms);
    for (std::size_t i = 0; i < jobs.size(); ++i)
        radiance[i] = tracePath(shading, cs, jobs[i], counts);
}
} // namespace rt::cpu
