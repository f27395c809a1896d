// Paths traced kLanes at a time (Integrator/PathStream.h, Geometry/RayPackets.h, Accel/Bvh4Lanes.h) against one
// at a time: the rays of a lane must find the hits and blockers each finds alone, and a job's path the radiance
// tracePath gives it, bit for bit, whatever the number of jobs and the depth, in a scene of one leaf and over a
// BVH. A lane that mixed up two paths' random streams, a hit recorded from the wrong lane or primitive order, a
// box skipped by a lane that enters it, a shadow ray's light added to the wrong path or a path ended early would
// differ here.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "Integrator/PathStream.h"
#include "Integrator/PathVariants.h"
#include "Random/Pcg.h"
#include "Render/RenderUniforms.h"
#include "Sampling/Warps.h"
#include "Engine/CpuScene.h"
#include "Scene/SceneBuilder.h"
#include "Scene/SceneFeatures.h"
#include "Scenes/Catalogue.h"

namespace rt::test
{
namespace
{
using namespace rt::cpu;

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool sameBits(const vec3& a, const vec3& b) { return sameBits(a.x, b.x) && sameBits(a.y, b.y) && sameBits(a.z, b.z); }

/// One leaf with every case of the lane tests: a moving sphere (time lanes), a radius-1e5 ground whose
/// quadratic cancels near its surface (the exact c), a tilted quad and two spheres of equal radius.
Scene oneLeafOfEveryCase()
{
    SceneBuilder b("lanes");
    const std::uint32_t w = b.world();
    const std::uint32_t m = b.lambertian(vec3(0.5f));
    b.sphere(w, vec3(0.0f, -1e5f, 0.0f), 1e5f, m);
    b.movingSphere(w, vec3(-1.0f, 1.0f, 0.0f), vec3(-1.0f, 1.5f, 0.0f), 0.5f, m);
    b.sphere(w, vec3(1.0f, 1.0f, 0.0f), 0.5f, m);
    b.sphere(w, vec3(1.0f, 1.0f, 2.0f), 0.5f, m);
    b.quad(w, vec3(-2.0f, 0.0f, -2.0f), vec3(4.0f, 0.0f, 0.0f), vec3(0.0f, 3.0f, -1.0f), m);
    b.quad(w, vec3(-2.0f, 0.5f, 3.0f), vec3(4.0f, 0.0f, 0.0f), vec3(0.0f, 0.0f, -0.5f), b.diffuseLight(vec3(4.0f)));
    return b.finish();
}

/// `count` rays from points spread over `lo`..`hi` in every direction, some leaving surfaces (origin on the
/// ground's top), at times in [0, 1).
std::vector<Ray> spreadRays(const vec3& lo, const vec3& hi, int count)
{
    Rng rng(5);
    std::vector<Ray> rays;
    for (int i = 0; i < count; ++i)
    {
        vec3 o = lo + (hi - lo) * vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat());
        if (i % 4 == 0)
            o.y = 1e-3f * rng.nextFloat(); // just above the huge sphere, where its c cancels
        rays.push_back(Ray{o, sampleUniformSphere(rng.next2D()) * (0.5f + rng.nextFloat()), rng.nextFloat()});
    }
    return rays;
}

void expectLanesFindTheScalarHits(const CpuScene& cs, const std::vector<Ray>& rays, const char* name)
{
    ASSERT_TRUE(cs.tracesRayLanes()) << name;
    int hits = 0;
    for (std::size_t first = 0; first + kLanes <= rays.size(); first += kLanes)
    {
        RayLanes lanes;
        for (int l = 0; l < kLanes; ++l)
            lanes.set(l, TraceRay(rays[first + l], cs.rayNeeds()));
        RayHits nearest(kInfinity);
        cs.intersect(lanes, 0.0f, nearest);
        HitRecord fromLanes[kLanes];
        nearest.store(fromLanes);
        for (int l = 0; l < kLanes; ++l)
        {
            HitRecord alone{};
            const bool found = cs.intersect(TraceRay(rays[first + l], cs.rayNeeds()), 0.0f, kInfinity, alone, 0u);
            const HitRecord& h = fromLanes[l];
            ASSERT_EQ(h.prim, found ? alone.prim : kNoIndex) << name << ", ray " << first + l;
            if (!found)
                continue;
            ++hits;
            ASSERT_TRUE(sameBits(h.t, alone.t) && sameBits(h.b1, alone.b1) && sameBits(h.b2, alone.b2))
                << name << ", ray " << first + l << ": t " << h.t << " against " << alone.t;
        }
    }
    EXPECT_GT(hits, int(rays.size()) / 4) << name; // the rays do meet the scene
}

TEST(RayLanes, EveryLaneFindsTheHitItsRayFindsAlone)
{
    const Scene lanes = oneLeafOfEveryCase();
    expectLanesFindTheScalarHits(CpuScene(lanes), spreadRays(vec3(-3.0f, 0.0f, -3.0f), vec3(3.0f, 3.0f, 3.0f), 8000),
                                 "every case");
    const Scene glass = placedScene("rtrol-cornell-glass"); // the rays are in the scene's own coordinates
    expectLanesFindTheScalarHits(CpuScene(glass), spreadRays(vec3(1.0f), vec3(554.0f), 8000), "rtrol-cornell-glass");
    const Scene closeup = placedScene("rect-light-closeup");
    expectLanesFindTheScalarHits(CpuScene(closeup), spreadRays(vec3(-5.0f), vec3(5.0f), 8000), "rect-light-closeup");
}

TEST(RayLanes, OverABvhEveryLaneFindsTheHitItsRayFindsAlone)
{
    // Rays from everywhere in every direction: the lanes part ways in the tree, so subtrees are traversed by
    // the packet and by single lanes alone.
    for (const char* id : {"rtrol-cornell-box", "cornell-box-lights", "rtrol-cornell-mirror"})
    {
        const CpuScene cs(placedScene(id));
        ASSERT_FALSE(cs.bvh4().rootIsLeaf) << id;
        expectLanesFindTheScalarHits(cs, spreadRays(vec3(1.0f), vec3(554.0f), 8000), id);
    }
    const CpuScene spheres(placedScene("rtow-final")); // 486 spheres, a deeper tree
    expectLanesFindTheScalarHits(spheres, spreadRays(vec3(-12.0f, 0.0f, -12.0f), vec3(12.0f, 3.0f, 12.0f), 8000),
                                 "rtow-final");
}

/// Each lane's shadow ray, to a distance of its own, blocked in lanes as occluded() finds it alone.
void expectLanesFindTheScalarBlockers(const CpuScene& cs, const std::vector<Ray>& rays, float maxDistance,
                                      const char* name)
{
    ASSERT_TRUE(cs.tracesRayLanes() && !cs.bvh4().rootIsLeaf) << name;
    Rng pick(11);
    int blocked = 0, tested = 0;
    for (std::size_t first = 0; first + kLanes <= rays.size(); first += kLanes)
    {
        RayLanes lanes;
        alignas(32) float distance[kLanes];
        const int present = static_cast<int>(pick.nextUint() & ((1u << kLanes) - 1)) | 1; // some lanes empty
        for (int l = 0; l < kLanes; ++l)
        {
            distance[l] = maxDistance * pick.nextFloat();
            if (present >> l & 1)
                lanes.set(l, TraceRay(rays[first + l], cs.rayNeeds()));
            else
                lanes.clear(l);
        }
        const int fromLanes = cs.occluded(lanes, 0.0f, Lanes::load(distance));
        ASSERT_EQ(fromLanes & ~present, 0) << name << ": an empty lane reported blocked";
        for (int l = 0; l < kLanes; ++l)
        {
            if (!(present >> l & 1))
                continue;
            const bool alone = cs.occluded(TraceRay(rays[first + l], cs.rayNeeds()), 0.0f, distance[l], 0u);
            ASSERT_EQ((fromLanes >> l & 1) != 0, alone) << name << ", ray " << first + l << " to " << distance[l];
            blocked += alone;
            ++tested;
        }
    }
    // Both answers are common: the comparison tests each.
    EXPECT_GT(blocked, tested / 10) << name;
    EXPECT_LT(blocked, tested - tested / 10) << name;
}

TEST(RayLanes, OverABvhEveryLaneIsBlockedAsItsRayAlone)
{
    for (const char* id : {"rtrol-cornell-box", "cornell-box-lights"})
        expectLanesFindTheScalarBlockers(CpuScene(placedScene(id)), spreadRays(vec3(1.0f), vec3(554.0f), 8000),
                                         400.0f, id);
    expectLanesFindTheScalarBlockers(CpuScene(placedScene("rtow-final")),
                                     spreadRays(vec3(-12.0f, 0.0f, -12.0f), vec3(12.0f, 3.0f, 12.0f), 8000), 8.0f,
                                     "rtow-final");
}

TEST(RayLanes, OnlyScenesOfFewQuadsAndSpheresTestRaysInLanes)
{
    EXPECT_TRUE(CpuScene(makeScene("rtrol-cornell-glass")).tracesRayLanes()); // one leaf
    EXPECT_TRUE(CpuScene(makeScene("cornell-box-lights")).tracesRayLanes()); // a BVH
    const Scene lamps = makeScene("lamp-room"); // quads and spheres, too many
    EXPECT_GT(CpuScene(lamps).primitiveCount(), CpuScene::kRayLanesPrimitivesAtMost);
    EXPECT_FALSE(CpuScene(lamps).tracesRayLanes());
    const Scene triangles = makeScene("cube-and-spheres"); // one leaf, with triangles
    EXPECT_FALSE(CpuScene(triangles).tracesRayLanes());
    const Scene smoke = makeScene("rtnw-cornell-smoke"); // one leaf, with a medium
    EXPECT_FALSE(CpuScene(smoke).tracesRayLanes());
}

/// Jobs of camera-like rays: from `eye` towards points of the box lo..hi.
std::vector<PathJob> jobsToward(const vec3& eye, const vec3& lo, const vec3& hi, int count)
{
    Rng pick(9);
    std::vector<PathJob> jobs;
    for (int i = 0; i < count; ++i)
    {
        const vec3 target = lo + (hi - lo) * vec3(pick.nextFloat(), pick.nextFloat(), pick.nextFloat());
        jobs.push_back({Ray{eye, target - eye, pick.nextFloat()}, Rng::forSample(3, std::uint32_t(i), 7)});
    }
    return jobs;
}

void expectTracePathsIsTracePath(const Scene& scene, Estimator estimator, std::vector<PathJob> jobs, int depth,
                                 const char* name)
{
    const CpuScene cs(scene);
    const PathVariant variant = choosePathVariant(featuresOf(scene), estimator, true, cs.tracesRayLanes());
    ASSERT_NE(variant.traceLanes, nullptr) << name;
    RenderSettings settings;
    settings.depth = depth;
    settings.estimator = estimator;
    const shader::RenderUniforms uniforms = makeUniforms(scene, scene.camera, settings, 64, 64);
    std::vector<vec3> radiance(jobs.size(), vec3(-1.0f));
    TraceCounts laneCounts;
    variant.traceLanes(cs, uniforms, jobs, radiance.data(), laneCounts);
    TraceCounts counts;
    bool light = false;
    for (std::size_t i = 0; i < jobs.size(); ++i)
    {
        vec3 alone;
        variant.trace(cs, uniforms, std::span<const PathJob>(&jobs[i], 1), &alone, counts);
        ASSERT_TRUE(sameBits(radiance[i], alone))
            << name << ", depth " << depth << ", " << jobs.size() << " jobs: job " << i << " (" << radiance[i].x
            << " against " << alone.x << ")";
        light |= maxComponent(alone) > 0.0f;
    }
    // The same rays of each kind: a path ray of each job per segment traced, a shadow ray per light sample; and
    // the same light samples.
    const RayCounts& rays = counts.rays;
    EXPECT_EQ(laneCounts.rays, rays) << name;
    EXPECT_EQ(laneCounts.lightSamples, counts.lightSamples) << name;
    EXPECT_EQ(rays.camera, depth > 0 ? jobs.size() : 0u) << name;
    if (depth > 1 && jobs.size() > 50)
    {
        EXPECT_GT(rays.extension, 0u) << name;
        EXPECT_EQ(rays.shadow > 0u, shader::usesNee(estimator)) << name << ": shadow rays are NEE's alone";
        EXPECT_EQ(counts.lightSamples.drawn >= rays.shadow && counts.lightSamples.drawn > 0u, shader::usesNee(estimator))
            << name << ": NEE's light samples, one per shadow ray at least";
    }
    if (depth > 1 && jobs.size() > 50)
    {
        EXPECT_TRUE(light) << name << ": no path found light, the comparison proves little";
    }
}

TEST(PathStream, EveryJobGetsTheRadianceOfItsPathTracedAlone)
{
    const Scene glass = makeScene("rtrol-cornell-glass"); // ray lanes, the mixture
    const Scene closeup = makeScene("rect-light-closeup"); // ray lanes, NEE + MIS with shadow rays
    const Scene lanes = oneLeafOfEveryCase();
    const Scene cornell = makeScene("rtrol-cornell-box"); // a BVH
    for (const int count : {1, kLanes - 1, kLanes + 1, 300})
        for (const int depth : {0, 1, 50})
        {
            expectTracePathsIsTracePath(glass, Estimator::Mixture,
                                        jobsToward(vec3(278.0f, 278.0f, -800.0f), vec3(0.0f), vec3(555.0f), count),
                                        depth, "rtrol-cornell-glass");
            expectTracePathsIsTracePath(closeup, Estimator::NeeMis,
                                        jobsToward(closeup.camera.lookFrom, vec3(-2.0f), vec3(2.0f), count), depth,
                                        "rect-light-closeup");
            // Over a BVH: shadow rays in lanes too.
            for (const Estimator e : {Estimator::Mixture, Estimator::Nee, Estimator::NeeMis})
                expectTracePathsIsTracePath(cornell, e,
                                            jobsToward(vec3(278.0f, 278.0f, -800.0f), vec3(0.0f), vec3(555.0f), count),
                                            depth, "rtrol-cornell-box");
            for (const Estimator e : {Estimator::BsdfOnly, Estimator::Mixture, Estimator::Nee})
                expectTracePathsIsTracePath(lanes, e,
                                            jobsToward(vec3(0.0f, 1.5f, 6.0f), vec3(-2.0f, 0.0f, -2.0f),
                                                       vec3(2.0f, 2.0f, 2.0f), count),
                                            depth, "every case");
        }
}
} // namespace
} // namespace rt::test
