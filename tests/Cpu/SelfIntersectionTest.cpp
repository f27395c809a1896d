// Rays leaving a surface from offsetRayOrigin (RTG ch. 6) must not hit the surface they leave, at any
// scale (research notes §3.3: a fixed 1e-4 offset failed a third of the time at scale 1e4).
#include <gtest/gtest.h>

#include <cmath>

#include "Math/RayOffset.h"
#include "Random/Pcg.h"
#include "Sampling/Warps.h"
#include "Engine/CpuScene.h"
#include "Scene/SceneBuilder.h"

namespace rt::test
{
namespace
{
using namespace rt::cpu;

class SelfIntersection : public ::testing::TestWithParam<float>
{
};

/// Shoots rays at a shape, then from each hit a ray into the hemisphere of the side it arrived from
/// (reflection) and one into the other side (transmission). Neither may hit the same primitive again at a
/// distance below `scale * 1e-3`, which only a self-hit produces for these convex or flat shapes.
int selfHits(const Scene& scene, float scale)
{
    const CpuScene cs(scene);
    Rng rng(99);
    int bad = 0;
    for (int i = 0; i < 20000; ++i)
    {
        const vec3 from = 3.0f * scale * sampleUniformSphere({rng.nextFloat(), rng.nextFloat()});
        const vec3 target = 0.3f * scale * vec3(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f);
        const TraceRay r(Ray{from, target - from, 0.0f}, cs.rayNeeds());
        HitRecord hit;
        if (!cs.intersect(r, 0.0f, kInfinity, hit, 0u))
            continue;
        const SurfaceInteraction si = cs.interaction(r, hit);
        const vec3 toward = glm::dot(r.direction, si.n) < 0.0f ? si.n : -si.n;
        for (const float side : {1.0f, -1.0f})
        {
            vec3 d = sampleUniformSphere({rng.nextFloat(), rng.nextFloat()});
            if (glm::dot(d, side * toward) < 0.0f)
                d = -d;
            const vec3 origin = offsetRayOrigin(si.p, glm::dot(d, si.n) > 0.0f ? si.n : -si.n, si.offsetScale);
            HitRecord again;
            if (cs.intersect(TraceRay(Ray{origin, d, 0.0f}, cs.rayNeeds()), 0.0f, kInfinity, again, 0u) &&
                again.prim == hit.prim && again.t < 1e-3f * scale)
                ++bad;
        }
    }
    return bad;
}

TEST_P(SelfIntersection, SphereAtAnyScale)
{
    const float scale = GetParam();
    SceneBuilder b("sphere");
    b.sphere(b.world(), vec3(0.1f * scale, -0.2f * scale, 0.05f * scale), scale, b.lambertian(vec3(0.5f)));
    EXPECT_EQ(selfHits(b.finish(), scale), 0);
}

TEST_P(SelfIntersection, QuadAtAnyScale)
{
    const float scale = GetParam();
    SceneBuilder b("quad");
    b.quad(b.world(), scale * vec3(-1.0f, 0.1f, -1.0f), scale * vec3(2.0f, 0.3f, 0.0f), scale * vec3(0.0f, 0.2f, 2.0f),
           b.lambertian(vec3(0.5f)));
    EXPECT_EQ(selfHits(b.finish(), scale), 0);
}

TEST_P(SelfIntersection, TriangleAtAnyScale)
{
    const float scale = GetParam();
    SceneBuilder b("triangle");
    MeshData m;
    m.name = "tri";
    m.positions = {scale * vec3(-1.0f, -0.3f, -1.0f), scale * vec3(1.5f, 0.2f, -0.5f), scale * vec3(0.0f, 0.4f, 1.5f)};
    m.indices = {0, 1, 2};
    b.mesh(b.world(), b.addMesh(std::move(m)), b.lambertian(vec3(0.5f)));
    EXPECT_EQ(selfHits(b.finish(), scale), 0);
}

INSTANTIATE_TEST_SUITE_P(Scales, SelfIntersection, ::testing::Values(1e-2f, 1.0f, 1e2f, 1e4f),
                         [](const auto& param) { return "Scale" + std::to_string(param.index); });
} // namespace
} // namespace rt::test
