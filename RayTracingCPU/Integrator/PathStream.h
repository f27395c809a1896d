// Camera paths traced kLanes at a time in a scene that is one BVH leaf of quads and spheres
// (CpuScene::tracesRayLanes): each step tests the lanes' rays together (Geometry/RayPackets.h: the rays in the
// lanes, each primitive once), then continues each path on its own with tracePath's loop body (continuePath),
// and a lane whose path ends takes the next job. Shadow rays stay scalar. Every path draws its own random
// stream in its own order, so each job's radiance is tracePath's, bit for bit.
#pragma once

#include <cstdint>
#include <span>

#include "Integrator/PathIntegrator.h"

namespace rt::cpu
{
/// One camera sample to trace: its first ray and its random stream (drawn from as the path goes).
struct PathJob
{
    Ray ray;
    Rng rng{0u};
};

/// Traces every job's path and writes job i's radiance (linear RGB) to radiance[i]. `segments` is incremented
/// per ray traced, shadow rays included. Precondition: cs.tracesRayLanes(); C matches the scene and options as
/// tracePath's must.
template <PathCode C = PathCode{}>
RT_FLATTEN inline void tracePaths(const CpuScene& cs, const PathOptions& options, std::span<PathJob> jobs,
                                  vec3* radiance, std::uint64_t& segments)
{
    PathState paths[kLanes];
    int jobOf[kLanes]; // -1: the lane has no path
    RayLanes rays;
    const TraceRay::Needs needs = cs.rayNeeds();
    std::size_t next = 0;
    int active = 0;
    const auto start = [&](int lane) {
        for (; next < jobs.size(); ++next)
        {
            if (options.depth <= 0)
            {
                radiance[next] = vec3(0.0f);
                continue;
            }
            paths[lane] = PathState{jobs[next].ray};
            jobOf[lane] = static_cast<int>(next++);
            rays.set(lane, TraceRay(paths[lane].ray, needs));
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
            ++segments;
            PathState& path = paths[lane];
            if (continuePath<C>(cs, options, path, hits[lane].prim != kNoIndex, hits[lane], jobs[job].rng, segments))
            {
                rays.set(lane, TraceRay(path.ray, needs));
                continue;
            }
            radiance[job] = path.radiance;
            --active;
            start(lane);
        }
    }
}
} // namespace rt::cpu
