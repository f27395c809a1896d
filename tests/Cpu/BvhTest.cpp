// The BVH (4-wide, packet leaves) must find exactly the hits a brute-force loop over every primitive finds.
#include <gtest/gtest.h>

#include <cmath>

#include "Random/Pcg.h"
#include "Sampling/Warps.h"
#include "Engine/CpuScene.h"
#include "Scene/SceneBuilder.h"

namespace rt::test
{
namespace
{
using namespace rt::cpu;

/// Spheres (some moving), quads, a mesh, and an instanced group rotated and scaled: every kind of
/// primitive the BVH stores except media (which draw random numbers).
Scene randomScene(std::uint32_t seed)
{
    SceneRandom rnd(seed);
    SceneBuilder b("bvh-test");
    const std::uint32_t mat = b.lambertian(vec3(0.5f));
    const std::uint32_t w = b.world();
    const auto point = [&](float extent) {
        const float x = rnd.uniform(-extent, extent);
        const float y = rnd.uniform(-extent, extent);
        const float z = rnd.uniform(-extent, extent);
        return vec3(x, y, z);
    };
    for (int i = 0; i < 300; ++i)
    {
        const vec3 c = point(10.0f);
        const float r = rnd.uniform(0.05f, 1.0f);
        if (i % 5 == 0)
            b.movingSphere(w, c, c + point(0.5f), r, mat);
        else
            b.sphere(w, c, r, mat);
    }
    for (int i = 0; i < 300; ++i)
        b.quad(w, point(10.0f), point(1.5f), point(1.5f), mat);
    MeshData mesh;
    mesh.name = "soup";
    for (int i = 0; i < 600; ++i)
    {
        const vec3 c = point(10.0f);
        for (int k = 0; k < 3; ++k)
            mesh.positions.push_back(c + point(1.0f));
        mesh.indices.insert(mesh.indices.end(), {3u * i, 3u * i + 1, 3u * i + 2});
    }
    b.mesh(w, b.addMesh(std::move(mesh)), mat);
    const std::uint32_t g = b.group("instanced");
    for (int i = 0; i < 50; ++i)
        b.sphere(g, point(3.0f), 0.4f, mat);
    b.box(g, vec3(-1.0f), vec3(1.0f), mat);
    b.instance(g, Transform::translate({4.0f, 1.0f, -2.0f}) * Transform::rotateY(33.0f) * Transform::scale(vec3(1.7f)));
    return b.finish();
}

HitRecord bruteForce(const CpuScene& s, const TraceRay& r)
{
    HitRecord hit{kInfinity, kNoIndex, 0.0f, 0.0f};
    for (std::size_t i = 0; i < s.spheres().size(); ++i)
        intersectSphere(s.spheres()[i], r, 0.0f, hit, PrimRef::make(PrimType::Sphere, std::uint32_t(i)).bits);
    for (std::size_t i = 0; i < s.quads().size(); ++i)
        intersectQuad(s.quads()[i], r, 0.0f, hit, PrimRef::make(PrimType::Quad, std::uint32_t(i)).bits);
    for (std::size_t i = 0; i < s.triangles().size(); ++i)
        intersectTriangle(s.triangles()[i], r, 0.0f, hit, PrimRef::make(PrimType::Triangle, std::uint32_t(i)).bits);
    return hit;
}

TEST(Bvh, HitsEqualBruteForceOnAMillionRandomRays)
{
    const Scene scene = randomScene(11);
    const CpuScene cs(scene);
    ASSERT_GT(cs.bvh4().nodes.size(), 10u);
    Rng rng(12345);
    int misses = 0, hits = 0, mismatches = 0;
    constexpr int kRays = 1'000'000;
    for (int i = 0; i < kRays; ++i)
    {
        const vec3 o(rng.nextFloat() * 30.0f - 15.0f, rng.nextFloat() * 30.0f - 15.0f, rng.nextFloat() * 30.0f - 15.0f);
        const vec2 u(rng.nextFloat(), rng.nextFloat());
        const float length = 0.1f + 3.0f * rng.nextFloat(); // unnormalised directions too
        const TraceRay r(Ray{o, length * sampleUniformSphere(u), rng.nextFloat()}, {true, false});
        HitRecord viaBvh;
        const bool found = cs.intersect(r, 0.0f, kInfinity, viaBvh, 0u);
        const HitRecord expected = bruteForce(cs, r);
        if (found != (expected.prim != kNoIndex))
        {
            ++mismatches;
            continue;
        }
        if (!found)
        {
            ++misses;
            continue;
        }
        ++hits;
        // Packet and scalar tests share their arithmetic except a division by the triangle determinant
        // (a reciprocal multiply in the scalar test): t may differ in the last bits.
        const bool sameT = std::fabs(viaBvh.t - expected.t) <= 1e-5f * expected.t;
        if (!sameT || (viaBvh.prim != expected.prim && viaBvh.t != expected.t))
            ++mismatches;
    }
    EXPECT_EQ(mismatches, 0) << hits << " hits, " << misses << " misses";
    EXPECT_GT(hits, kRays / 10);
    EXPECT_GT(misses, kRays / 10);
}

TEST(Bvh, SplitsOnEveryAxis)
{
    // The thesis' BVH never split along z when x was the longest axis: a row of spheres along z, spread
    // wider along x, must still be separated along z.
    SceneBuilder b("bvh-axis");
    const std::uint32_t w = b.world();
    const std::uint32_t mat = b.lambertian(vec3(0.5f));
    for (int i = 0; i < 64; ++i)
        b.sphere(w, {float(i % 2) * 100.0f, 0.0f, float(i / 2) * 3.0f}, 1.0f, mat);
    const Scene scene = b.finish();
    const CpuScene cs(scene);
    bool zSplit = false;
    for (const BvhNode& n : cs.bvh().nodes)
        zSplit |= n.count == 0 && n.axis == 2;
    EXPECT_TRUE(zSplit);
}
} // namespace
} // namespace rt::test
