// Math/Onb.h and Math/RayOffset.h: the frame every warp is turned into world space with, and the offset
// that keeps a secondary ray off the surface it leaves.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <vector>

#include "Math/Onb.h"
#include "Math/RayOffset.h"
#include "Random/Pcg.h"
#include "Sampling/Warps.h"

namespace rt
{
namespace
{
/// Unit vectors: random ones, the axes, and the neighbourhood of -z where Duff et al.'s construction
/// switches branch (and where the original Frisvad basis broke down).
std::vector<vec3> testNormals()
{
    std::vector<vec3> normals = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0},
                                 glm::normalize(vec3(1e-4f, 0.0f, -1.0f)), glm::normalize(vec3(0.0f, -1e-7f, -1.0f)),
                                 glm::normalize(vec3(1e-7f, 1e-7f, 1.0f))};
    Rng rng(pcgHash(77));
    for (int i = 0; i < 10'000; ++i)
    {
        const float a = rng.nextFloat();
        const float b = rng.nextFloat();
        normals.push_back(sampleUniformSphere({a, b}));
    }
    return normals;
}

TEST(Onb, IsARightHandedOrthonormalFrameAroundTheNormal)
{
    // 1e-5: a few float roundings of unit-sized products; a basis 1e-3 off orthogonal would skew every warp.
    for (const vec3& n : testNormals())
    {
        const Onb f(n);
        EXPECT_EQ(f.w, n);
        EXPECT_NEAR(glm::length(f.u), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::length(f.v), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(f.u, f.v), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(f.u, n), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(f.v, n), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::distance(glm::cross(f.u, f.v), n), 0.0f, 1e-5f) << "left-handed";
        if (HasFailure())
            return;
    }
}

TEST(Onb, ToWorldMapsLocalZToTheNormal)
{
    for (const vec3& n : {vec3(0, 0, -1), glm::normalize(vec3(0.3f, -0.5f, 0.8f))})
    {
        const Onb f(n);
        EXPECT_NEAR(glm::distance(f.toWorld({0, 0, 1}), n), 0.0f, 1e-6f);
        const vec3 local = glm::normalize(vec3(0.2f, -0.4f, 0.7f));
        EXPECT_NEAR(glm::dot(f.toWorld(local), n), local.z, 1e-6f); // the local z is the cosine to n
        EXPECT_NEAR(glm::length(f.toWorld(local)), 1.0f, 1e-6f);
    }
}

TEST(RayOffset, MovesThePointToTheNormalsSide)
{
    // The offset point lies strictly on the side the normal points to (so a ray from it leaves the surface),
    // yet close: within max(1, offsetScale) / 16384 absolute or a relative 1e-4 of the point (256 ulps is 3e-5
    // relative).
    Rng rng(pcgHash(88));
    for (int i = 0; i < 100'000; ++i)
    {
        const float scale = std::pow(10.0f, -4.0f + 8.0f * rng.nextFloat()); // 1e-4 .. 1e4
        const float x = rng.nextFloat(), y = rng.nextFloat(), z = rng.nextFloat();
        const vec3 p = scale * (2.0f * vec3(x, y, z) - vec3(1.0f));
        const float a = rng.nextFloat(), b = rng.nextFloat();
        const vec3 n = sampleUniformSphere({a, b});
        const float offsetScale = i % 2 == 0 ? 1.0f : scale * 4.0f * rng.nextFloat();
        const vec3 q = offsetRayOrigin(p, n, offsetScale);
        ASSERT_TRUE(isFinite(q));
        const dvec3 d = dvec3(q) - dvec3(p);
        EXPECT_GT(glm::dot(d, dvec3(n)), 0.0) << "p = (" << p.x << ", " << p.y << ", " << p.z << ")";
        EXPECT_LE(glm::length(d), std::max(1.0, double(offsetScale)) / 16384.0 + 1e-4 * glm::length(dvec3(p)));
        if (HasFailure())
            return;
    }
}

TEST(RayOffset, ClearsTheErrorOfATestWithLargeVertices)
{
    // A point on a surface whose vertices reach |coordinate| S (a wall at x = 0 of a box of side S) leaves it by
    // at least 4 ulps of S along the normal, whatever its own coordinates: a triangle test computing with the
    // vertices (a driver's) errs by about an ulp of S. Wächter & Binder's offset alone moved such a point by
    // 1/65536, a quarter of an ulp of 555: NVIDIA's test then re-hit the Cornell box's red wall.
    Rng rng(pcgHash(89));
    for (int i = 0; i < 100'000; ++i)
    {
        const float s = std::pow(10.0f, 8.0f * rng.nextFloat() - 2.0f); // 1e-2 .. 1e6
        const float a = rng.nextFloat(), b = rng.nextFloat();
        const vec3 n = sampleUniformSphere({a, b});
        // Coordinates from 0 to S, some exactly 0 (axis-aligned walls through the origin).
        vec3 p;
        for (int k = 0; k < 3; ++k)
            p[k] = rng.nextFloat() < 0.3f ? 0.0f : s * (2.0f * rng.nextFloat() - 1.0f) * rng.nextFloat();
        const vec3 q = offsetRayOrigin(p, n, s);
        const double ulpOfS = std::ldexp(1.0, std::ilogb(std::max(1.0f, s)) - 23);
        EXPECT_GE(glm::dot(dvec3(q) - dvec3(p), dvec3(n)), 4.0 * ulpOfS)
            << "p = (" << p.x << ", " << p.y << ", " << p.z << "), S = " << s;
        if (HasFailure())
            return;
    }
}
TEST(RayOffset, SseIsTheScalarOneBitForBit)
{
    // The CPU's SSE offset is a twin of the scalar one that the GPU runs (Shared/RayOffset.h): the same bits for
    // points near and far from the origin, on both sides of the near-origin threshold, with zero and negative
    // coordinates.
    Rng rng(pcgHash(90));
    for (int i = 0; i < 200'000; ++i)
    {
        const float s = std::pow(10.0f, 10.0f * rng.nextFloat() - 4.0f); // 1e-4 .. 1e6
        vec3 p;
        for (int k = 0; k < 3; ++k)
            p[k] = rng.nextFloat() < 0.1f ? 0.0f : s * (2.0f * rng.nextFloat() - 1.0f);
        const float a = rng.nextFloat(), b = rng.nextFloat();
        const vec3 n = sampleUniformSphere({a, b});
        const float scale = i % 3 == 0 ? 1.0f : s * 2.0f * rng.nextFloat();
        const vec3 sse = offsetRayOrigin(p, n, scale);
        const vec3 shared = shader::offsetRayOriginScalar(p, n, scale);
        for (int k = 0; k < 3; ++k)
            ASSERT_EQ(std::bit_cast<std::uint32_t>(sse[k]), std::bit_cast<std::uint32_t>(shared[k]))
                << "p = (" << p.x << ", " << p.y << ", " << p.z << "), scale " << scale << ", axis " << k;
    }
}
} // namespace
} // namespace rt
