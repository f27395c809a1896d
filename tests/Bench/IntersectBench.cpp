// Closest-hit queries on book 3's final scene (one BVH leaf of quads and a sphere): one ray at a time against
// the primitive packets (Geometry/Packets.h) and kLanes rays at a time (Geometry/RayPackets.h), over the same
// rays. Reports nanoseconds per ray.
//   rt_bench --benchmark_filter=ClosestHit
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "Random/Pcg.h"
#include "Sampling/Warps.h"
#include "Engine/CpuScene.h"
#include "Scenes/Catalogue.h"

namespace
{
using namespace rt;
using namespace rt::cpu;

/// 4096 rays from points inside the box, in directions uniform over the sphere: what a path's bounces trace.
std::vector<TraceRay> raysInsideTheBox(const CpuScene& cs)
{
    Rng rng(11);
    std::vector<TraceRay> rays;
    for (int i = 0; i < 4096; ++i)
    {
        const vec3 o = vec3(1.0f) + 553.0f * vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat());
        rays.emplace_back(Ray{o, sampleUniformSphere(rng.next2D()), 0.0f}, cs.rayNeeds());
    }
    return rays;
}

/// arg 0: one ray at a time, 1: kLanes rays at a time.
void ClosestHit(benchmark::State& state)
{
    static const Scene scene = makeScene("rtrol-cornell-glass");
    static const CpuScene cs(scene);
    static const std::vector<TraceRay> rays = raysInsideTheBox(cs);
    const bool lanes = state.range(0) != 0;
    float sum = 0.0f;
    for (auto _ : state)
    {
        if (lanes)
            for (std::size_t first = 0; first < rays.size(); first += kLanes)
            {
                RayLanes r;
                for (int l = 0; l < kLanes; ++l)
                    r.set(l, rays[first + l]);
                RayHits nearest(kInfinity);
                cs.intersect(r, 0.0f, nearest);
                HitRecord hits[kLanes];
                nearest.store(hits);
                for (const HitRecord& h : hits)
                    sum += h.t;
            }
        else
            for (const TraceRay& r : rays)
            {
                HitRecord h{};
                cs.intersect(r, 0.0f, kInfinity, h, 0u);
                sum += h.t;
            }
    }
    benchmark::DoNotOptimize(sum);
    // Seconds per ray, printed with an SI prefix (11.1n: 11.1 ns).
    state.counters["s/ray"] = benchmark::Counter(double(rays.size()) * double(state.iterations()),
                                                 benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.SetLabel(lanes ? std::to_string(kLanes) + " rays at a time" : "one ray at a time");
}
BENCHMARK(ClosestHit)->Arg(0)->Arg(1);
} // namespace
