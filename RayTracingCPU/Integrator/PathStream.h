// Camera paths traced kLanes at a time in a scene of quads and spheres (CpuScene::tracesRayLanes): each step
// tests the lanes' rays together (Geometry/RayPackets.h: the rays in the lanes, each primitive once; over a BVH
// by masked packet traversal, Accel/Bvh4Lanes.h), then runs each path's vertex on its own (the shared vertex,
// as tracePath's loop body), and a lane whose path ends takes the next job. Over a BVH the vertices' shadow rays
// are then tested together too, each light added before its path's next vertex; in a scene of one leaf they
// stay scalar (docs/notebook/PERFORMANCE.md §25). Every path draws its own random stream in its own order, so
// each job's radiance is tracePath's, bit for bit (but where two primitives meet a ray at exactly the same t:
// Accel/Bvh4Lanes.h).
#pragma once

#include <bit>
#include <cstdint>
#include <new>
#include <span>

#include "Integrator/PathIntegrator.h"

namespace rt::cpu
{
namespace detail
{
/// tracePaths with the shadow rays in lanes (ShadowLanes, over a BVH) or traced one by one as each vertex
/// makes them (a scene of one leaf): two loops, as the second's bookkeeping cost the one-leaf scenes 3-9 %.
template <PathCode C, bool ShadowLanes>
RT_FLATTEN inline void traceLanes(const CpuScene& cs, const shader::RenderUniforms& uniforms,
                                  std::span<const PathJob> jobs, vec3* radiance, TraceCounts& counts)
{
    CpuShading<C> shading(cs, uniforms);
    shader::PathState paths[kLanes];
    std::uint32_t segmentOf[kLanes]; // the segment each lane's ray is
    int jobOf[kLanes]; // -1: the lane has no path
    RayLanes rays;
    const TraceRay::Needs needs = cs.rayNeeds();
    std::size_t next = 0;
    int active = 0;
    const auto start = [&](int lane) {
        for (; next < jobs.size(); ++next)
        {
            if (uniforms.depth == 0)
            {
                radiance[next] = vec3(0.0f);
                continue;
            }
            const PathJob& job = jobs[next];
            // Constructed in place (the prvalue's copy elided): assigned, the path was built field by field on
            // the stack and copied in 64-byte moves, which waited on those stores: a third of rtnw-earth's paths.
            ::new (static_cast<void*>(&paths[lane])) shader::PathState(
                shader::startPath(job.ray.origin, job.ray.direction, job.rng));
            segmentOf[lane] = 0;
            jobOf[lane] = static_cast<int>(next++);
            rays.set(lane, TraceRay(job.ray, needs));
            ++active;
            return;
        }
        jobOf[lane] = -1;
        rays.clear(lane);
    };
    for (int lane = 0; lane < kLanes; ++lane)
        start(lane);
    HitRecord hits[kLanes];
    if constexpr (!ShadowLanes)
    {
        while (active > 0)
        {
            RayHits nearest(kInfinity);
            cs.intersectOneLeaf(rays, 0.0f, nearest);
            nearest.store(hits);
            for (int lane = 0; lane < kLanes; ++lane)
            {
                const int job = jobOf[lane];
                if (job < 0)
                    continue;
                countPathRay(counts, segmentOf[lane]);
                shader::PathState& path = paths[lane];
                // The vertex ends the path at its last segment (depth - 1), so segmentOf stays below the depth.
                if (continuePath<C>(shading, cs, path, jobs[job], segmentOf[lane]++, hits[lane].prim != kNoIndex,
                                    hits[lane], counts))
                {
                    rays.set(lane, TraceRay(Ray{path.origin, path.direction, jobs[job].ray.time}, needs));
                    continue;
                }
                radiance[job] = path.radiance;
                --active;
                start(lane);
            }
        }
        return;
    }
    RayLanes shadowRays;
    alignas(32) float shadowDistance[kLanes];
    vec3 shadowLight[kLanes];
    while (active > 0)
    {
        RayHits nearest(kInfinity);
        cs.intersectTree(rays, 0.0f, nearest);
        nearest.store(hits);
        int shadowPending = 0, ended = 0;
        for (int lane = 0; lane < kLanes; ++lane)
        {
            const int job = jobOf[lane];
            if (job < 0)
                continue;
            countPathRay(counts, segmentOf[lane]);
            shader::PathState& path = paths[lane];
            const PathJob& pathJob = jobs[job];
            const shader::HitPayload payload =
                hitPayload(cs, Ray{path.origin, path.direction, pathJob.ray.time}, hits[lane].prim != kNoIndex, hits[lane]);
            shader::ShadowRay shadow{}; // its fields but pending are set only when pending, which GCC cannot follow
            const bool goesOn = shading.shadePathVertex(path, segmentOf[lane]++, payload, shadow, false);
            countLightSample(counts.lightSamples, shadow.lightSample);
            if (shadow.pending)
            {
                ++counts.rays.shadow;
                shadowRays.set(lane, TraceRay(Ray{shadow.origin, shadow.direction, pathJob.ray.time}, needs));
                shadowDistance[lane] = shadow.distance;
                shadowLight[lane] = shadow.contribution;
                shadowPending |= 1 << lane;
            }
            if (goesOn)
                rays.set(lane, TraceRay(Ray{path.origin, path.direction, pathJob.ray.time}, needs));
            else
                ended |= 1 << lane;
        }
        if (shadowPending)
        {
            for (int lane = 0; lane < kLanes; ++lane)
                if (!(shadowPending >> lane & 1))
                {
                    shadowRays.clear(lane);
                    shadowDistance[lane] = 0.0f;
                }
            const int visible = shadowPending & ~cs.occluded(shadowRays, 0.0f, Lanes::load(shadowDistance));
            for (int lane = 0; lane < kLanes; ++lane)
                if (visible >> lane & 1)
                    paths[lane].radiance += shadowLight[lane];
        }
        for (; ended; ended &= ended - 1)
        {
            const int lane = std::countr_zero(static_cast<unsigned>(ended));
            radiance[jobOf[lane]] = paths[lane].radiance;
            --active;
            start(lane);
        }
    }
}
} // namespace detail

/// Traces every job's path and writes job i's radiance (linear RGB) to radiance[i]. `counts` counts the rays
/// traced and NEE's light samples. Precondition: cs.tracesRayLanes(); C matches the scene and uniforms as tracePath's must.
template <PathCode C = PathCode{}>
inline void tracePaths(const CpuScene& cs, const shader::RenderUniforms& uniforms, std::span<const PathJob> jobs,
                       vec3* radiance, TraceCounts& counts)
{
    if (cs.bvh4().rootIsLeaf)
        detail::traceLanes<C, false>(cs, uniforms, jobs, radiance, counts);
    else
        detail::traceLanes<C, true>(cs, uniforms, jobs, radiance, counts);
}
} // namespace rt::cpu
