// Camera paths traced kLanes at a time in a scene that is one BVH leaf of quads and spheres
// (CpuScene::tracesRayLanes): each step tests the lanes' rays together (Geometry/RayPackets.h: the rays in the
// lanes, each primitive once), then continues each path on its own with tracePath's loop body (continuePath),
// and a lane whose path ends takes the next job. Shadow rays stay scalar. Every path draws its own random
// stream in its own order, so each job's radiance is tracePath's, bit for bit.
#pragma once

#include <cstdint>
#include <new>
#include <span>

#include "Integrator/PathIntegrator.h"

namespace rt::cpu
{
/// Traces every job's path and writes job i's radiance (linear RGB) to radiance[i]. `counts` counts the rays
/// traced. Precondition: cs.tracesRayLanes(); C matches the scene and uniforms as
/// tracePath's must.
template <PathCode C = PathCode{}>
RT_FLATTEN inline void tracePaths(const CpuScene& cs, const shader::RenderUniforms& uniforms, std::span<const PathJob> jobs,
                                  vec3* radiance, RayCounts& counts)
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
    while (active > 0)
    {
        RayHits nearest(kInfinity);
        cs.intersect(rays, 0.0f, nearest);
        nearest.store(hits);
        for (int lane = 0; lane < kLanes; ++lane)
        {
            const int job = jobOf[lane];
            if (job < 0)
                continue;
            countPathRay(counts, segmentOf[lane]);
            shader::PathState& path = paths[lane];
            // The vertex ends the path at its last segment (depth - 1), so segmentOf stays below the depth.
            if (continuePath<C>(shading, cs, path, jobs[job], segmentOf[lane]++, hits[lane].prim != kNoIndex, hits[lane],
                                counts))
            {
                rays.set(lane, TraceRay(Ray{path.origin, path.direction, jobs[job].ray.time}, needs));
                continue;
            }
            radiance[job] = path.radiance;
            --active;
            start(lane);
        }
    }
}
} // namespace rt::cpu
