// Ray-primitive tests: the cases the books' code and the thesis got wrong, and watertightness.
#include <gtest/gtest.h>

#include <cmath>

#include "Engine/CpuEngine.h"
#include "Geometry/Packets.h"
#include "Math/RayOffset.h"
#include "Random/Pcg.h"
#include "Sampling/Warps.h"
#include "Engine/CpuScene.h"
#include "Scene/SceneBuilder.h"
#include "Support/RenderWithSettings.h"

namespace rt::test
{
namespace
{
using namespace rt::cpu;

HitRecord closest(const CpuScene& cs, const Ray& ray)
{
    HitRecord hit;
    cs.intersect(TraceRay(ray, cs.rayNeeds()), 0.0f, kInfinity, hit, 1u);
    return hit;
}

Scene oneSphere(const vec3& c0, const vec3& c1, float r)
{
    SceneBuilder b("sphere");
    b.movingSphere(b.world(), c0, c1, r, b.lambertian(vec3(0.5f)));
    return b.finish();
}

TEST(Intersect, RayStartingInsideASphereHitsTheFarWall)
{
    const Scene scene = oneSphere(vec3(0.0f), vec3(0.0f), 2.0f);
    const CpuScene cs(scene);
    const HitRecord hit = closest(cs, Ray{vec3(0.5f, 0.0f, 0.0f), vec3(1.0f, 0.0f, 0.0f), 0.0f});
    ASSERT_NE(hit.prim, kNoIndex);
    EXPECT_NEAR(hit.t, 1.5f, 1e-5f);
    const SurfaceInteraction si = cs.interaction(TraceRay(Ray{vec3(0.5f, 0.0f, 0.0f), vec3(1.0f, 0.0f, 0.0f), 0.0f}, cs.rayNeeds()), hit);
    EXPECT_GT(si.n.x, 0.99f); // outward normal: the integrator flips it towards the ray
}

TEST(Intersect, MovingSphereIsWhereItIsAtTheRaysTime)
{
    // The thesis' CPU app moved spheres the wrong way: centre(t) must go from center0 (t=0) to center1 (t=1).
    const vec3 c0(0.0f, 0.0f, 0.0f), c1(0.0f, 10.0f, 0.0f);
    const Scene scene = oneSphere(c0, c1, 1.0f);
    const CpuScene cs(scene);
    const auto hitsAt = [&](float y, float time) {
        return closest(cs, Ray{vec3(-5.0f, y, 0.0f), vec3(1.0f, 0.0f, 0.0f), time}).prim != kNoIndex;
    };
    EXPECT_TRUE(hitsAt(0.0f, 0.0f));
    EXPECT_FALSE(hitsAt(0.0f, 0.5f));
    EXPECT_TRUE(hitsAt(5.0f, 0.5f));
    EXPECT_TRUE(hitsAt(9.5f, 0.95f));
    EXPECT_FALSE(hitsAt(-5.0f, 0.5f));
    // Its normal comes from the centre at that time, not the static one.
    const Ray ray{vec3(-5.0f, 5.0f, 0.0f), vec3(1.0f, 0.0f, 0.0f), 0.5f};
    const SurfaceInteraction si = cs.interaction(TraceRay(ray, cs.rayNeeds()), closest(cs, ray));
    EXPECT_NEAR(si.n.x, -1.0f, 1e-4f);
}

TEST(Intersect, HugeGroundSphereIsHitWhereItIs)
{
    // RTIOW's ground: radius 1000, camera a few units above. t must be accurate to a small fraction of
    // the height (research notes §3.1: the textbook discriminant loses it for small or distant spheres).
    const Scene scene = oneSphere(vec3(0.0f, -1000.0f, 0.0f), vec3(0.0f, -1000.0f, 0.0f), 1000.0f);
    const CpuScene cs(scene);
    const HitRecord hit = closest(cs, Ray{vec3(0.0f, 2.0f, 0.0f), vec3(0.0f, -1.0f, 0.0f), 0.0f});
    EXPECT_NEAR(hit.t, 2.0f, 2e-4f);
}

TEST(Intersect, SpherePacketAndScalarTestsShareTheNearRootRule)
{
    // The packet test, the scalar test and the GPU's take c = |f|^2 - r^2 exactly only where the near root lies
    // surely ahead of the ray (sphereQuadraticCForNearRoot). Rays leaving a sphere's surface to either side, in
    // every direction, from small to huge spheres (where c cancels for all of them): the same hits bit for bit,
    // and wherever the rule's c is not the exact one, the near root is behind the ray with both, or the rule's
    // lies within the rounding bound under which a root is the surface the ray leaves and the exact one within
    // twice that bound.
    Rng rng(11);
    int cancelling = 0;
    int withinTheBound = 0;
    for (const float radius : {1.0f, 90.0f, 1000.0f, 1e6f})
    {
        const SphereRec sphere{vec3(0.3f, -radius, 2.0f), radius, vec3(0.0f), 0, 0};
        SpherePacket packet;
        setLane(packet, 0, sphere, 7);
        padPacket(packet, 1);
        for (int i = 0; i < 20000; ++i)
        {
            const vec3 n = sampleUniformSphere(rng.next2D());
            const vec3 onSurface = sphere.center0 + radius * n;
            // Offset as the renderers offset a sphere's hit (scale 1), and farther (scale r).
            const vec3 origin = offsetRayOrigin(onSurface, i % 2 ? n : -n, i % 4 < 2 ? 1.0f : radius);
            const TraceRay ray(Ray{origin, sampleUniformSphere(rng.next2D()), 0.0f}, {false, false, false});
            const vec3 f = origin - sphere.center0;
            const float ff = glm::dot(f, f), rr = radius * radius;
            cancelling += std::fabs(ff - rr) < shader::kSphereCancellation * (ff + rr);
            HitRecord fromPacket{kInfinity, kNoIndex, 0.0f, 0.0f};
            HitRecord fromScalar{kInfinity, kNoIndex, 0.0f, 0.0f};
            const bool packetHit = intersectPacket(packet, ray, 0.0f, fromPacket);
            const bool scalarHit = intersectSphere(sphere, ray, 0.0f, fromScalar, 7);
            ASSERT_EQ(packetHit, scalarHit) << "radius " << radius << ", ray " << i;
            ASSERT_EQ(fromPacket.t, fromScalar.t) << "radius " << radius << ", ray " << i;
            const float b = glm::dot(f, ray.direction);
            const vec3 l = f - b * ray.direction;
            const float disc = rr - glm::dot(l, l);
            if (disc < 0.0f)
                continue;
            const float q = -(b + std::copysign(std::sqrt(disc), b));
            const float cRule = shader::sphereQuadraticCForNearRoot(f, radius, q);
            const float cExact = shader::sphereQuadraticC(f, radius);
            if (cRule == cExact || (cRule / q < 0.0f && cExact / q < 0.0f))
                continue;
            const double bound = double(shader::kSphereRootError) * (double(ff) + double(rr));
            ASSERT_LE(std::fabs(double(cRule)), bound) << "radius " << radius << ", ray " << i;
            ASSERT_LE(std::fabs(double(cExact)), 2.0 * bound) << "radius " << radius << ", ray " << i;
            ++withinTheBound;
        }
    }
    EXPECT_GT(cancelling, 70000); // the rays this is about: c cancels for nearly all of them
    EXPECT_GT(withinTheBound, 0); // and the rule leaves the exact c for some of them
}

TEST(Intersect, NearRootAheadOfAHugeSphereIsExact)
{
    // A ray from 1.5 units above a radius-1e6 ground, 30 degrees down: float's c (3e6 of 2e12) is ~3 % off,
    // and the hit distance with it. The rule takes the exact c there, in the scalar and the packet test alike.
    const float radius = 1e6f;
    const SphereRec sphere{vec3(0.0f, -radius, 0.0f), radius, vec3(0.0f), 0, 0};
    SpherePacket packet;
    setLane(packet, 0, sphere, 7);
    padPacket(packet, 1);
    const vec3 direction = glm::normalize(vec3(std::sqrt(3.0f), -1.0f, 0.0f));
    const TraceRay ray(Ray{vec3(0.0f, 1.5f, 0.0f), direction, 0.0f}, {false, false, false});
    // The near root in double: |o + t d - c|^2 = r^2.
    const double oy = 1.5 + 1e6, dx = double(direction.x), dy = double(direction.y);
    const double bHalf = oy * dy, cD = oy * oy - 1e12;
    const double expected = -bHalf - std::sqrt(bHalf * bHalf - (dx * dx + dy * dy) * cD);
    HitRecord fromScalar{kInfinity, kNoIndex, 0.0f, 0.0f};
    HitRecord fromPacket{kInfinity, kNoIndex, 0.0f, 0.0f};
    ASSERT_TRUE(intersectSphere(sphere, ray, 0.0f, fromScalar, 7));
    ASSERT_TRUE(intersectPacket(packet, ray, 0.0f, fromPacket));
    EXPECT_NEAR(fromScalar.t, expected, 1e-4 * expected);
    EXPECT_EQ(fromPacket.t, fromScalar.t);
}

TEST(Intersect, DegenerateTriangleIsNeverHit)
{
    // Three collinear vertices (pbrt's Triangle.BadCases): zero area, so no ray may report a hit.
    SceneBuilder b("degenerate");
    MeshData m;
    m.name = "line";
    m.positions = {{-1113.45f, -0.5f, -56.24f}, {-1113.45f, 0.0f, -56.24f}, {-1113.45f, 0.5f, -56.24f}};
    m.indices = {0, 1, 2};
    b.mesh(b.world(), b.addMesh(std::move(m)), b.lambertian(vec3(0.5f)));
    const Scene scene = b.finish();
    const CpuScene cs(scene);
    Rng rng(3);
    for (int i = 0; i < 10000; ++i)
    {
        const vec3 target(-1113.45f, rng.nextFloat() - 0.5f, -56.24f);
        const vec3 from = target + 10.0f * sampleUniformSphere({rng.nextFloat(), rng.nextFloat()});
        ASSERT_EQ(closest(cs, Ray{from, target - from, 0.0f}).prim, kNoIndex);
    }
}

/// A closed UV sphere as an indexed mesh, vertices perturbed so no two triangles are coplanar.
MeshData closedMesh(int stacks, int slices, std::uint32_t seed)
{
    SceneRandom rnd(seed);
    MeshData m;
    m.name = "closed";
    m.positions.push_back({0.0f, 1.0f, 0.0f});
    for (int i = 1; i < stacks; ++i)
        for (int j = 0; j < slices; ++j)
        {
            const float theta = kPi * float(i) / float(stacks), phi = 2.0f * kPi * float(j) / float(slices);
            const float r = 1.0f + 0.05f * rnd.uniform(-1.0f, 1.0f);
            m.positions.push_back(r * vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)));
        }
    m.positions.push_back({0.0f, -1.0f, 0.0f});
    const auto ring = [&](int i, int j) { return std::uint32_t(1 + (i - 1) * slices + (j % slices)); };
    const std::uint32_t bottom = std::uint32_t(m.positions.size() - 1);
    for (int j = 0; j < slices; ++j)
    {
        m.indices.insert(m.indices.end(), {0u, ring(1, j + 1), ring(1, j)});
        for (int i = 1; i < stacks - 1; ++i)
            m.indices.insert(m.indices.end(),
                             {ring(i, j), ring(i, j + 1), ring(i + 1, j + 1), ring(i, j), ring(i + 1, j + 1), ring(i + 1, j)});
        m.indices.insert(m.indices.end(), {bottom, ring(stacks - 1, j), ring(stacks - 1, j + 1)});
    }
    return m;
}

/// Rays from random points inside the closed mesh, placed by `worldFromObject`, aimed exactly at its
/// vertices (half) and at points on its shared edges (half): the ones that hit nothing (research notes
/// §3.2: from inside a closed mesh every ray must hit; Möller-Trumbore with an epsilon leaked 10 %).
int leaks(int rays, const Transform& worldFromObject)
{
    SceneBuilder b("closed-mesh");
    const std::uint32_t meshIndex = b.addMesh(closedMesh(24, 48, 5));
    const std::uint32_t g = b.group("closed");
    b.mesh(g, meshIndex, b.lambertian(vec3(0.5f)));
    b.instance(g, worldFromObject);
    const Scene scene = b.finish();
    const CpuScene cs(scene);
    const MeshData& m = scene.meshes[meshIndex];
    Rng rng(77);
    int leaked = 0;
    for (int i = 0; i < rays; ++i)
    {
        const vec3 origin = 0.5f * vec3(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f);
        const std::size_t tri = std::size_t(rng.nextFloat() * float(m.triangleCount()));
        const vec3 a = m.positions[m.indices[3 * tri]], c = m.positions[m.indices[3 * tri + 1]];
        const vec3 target = (i % 2 == 0) ? a : a + rng.nextFloat() * (c - a); // a vertex, or a point on an edge
        // The vertex as the engine placed it: the same float transform of the same float vertex.
        const vec3 from = worldFromObject.point(origin), to = worldFromObject.point(target);
        if (closest(cs, Ray{from, to - from, 0.0f}).prim == kNoIndex)
            ++leaked;
    }
    return leaked;
}

TEST(Watertight, RaysAtVerticesAndEdgesOfAClosedMeshNeverLeak)
{
    EXPECT_EQ(leaks(200000, Transform::identity()), 0) << "of 200000 rays";
}

// The stress suite's form (label stress): a million rays, also with the mesh moved 100 of its sizes from the
// origin and scaled (every coordinate rounded to that magnitude's ulp, the shared vertices identically).
TEST(StressWatertight, MillionRaysAtEdgesAndVerticesNeverLeak)
{
    EXPECT_EQ(leaks(1000000, Transform::identity()), 0) << "at the origin";
    EXPECT_EQ(leaks(1000000, Transform::translate({200.0f, -150.0f, 100.0f}) * Transform::rotateY(30.0f)), 0)
        << "moved and rotated";
    EXPECT_EQ(leaks(1000000, Transform::translate({2e5f, 0.0f, -1e5f}) * Transform::scale(vec3(1e3f))), 0)
        << "scaled by 1e3 and moved";
}
} // namespace
} // namespace rt::test

namespace rt::test
{
namespace
{
/// A Lambertian ground sphere under a uniform sky of radiance 1: every path that leaves the ground escapes
/// (a sphere is convex), so the ground shows exactly its albedo. Rays that re-hit the ground they leave
/// (acne) darken it: with only the ray offset, radius 1000 gave 0.365 instead of 0.5.
class GroundSphere : public ::testing::TestWithParam<float>
{
};

TEST_P(GroundSphere, ShowsItsAlbedoUnderAUniformSky)
{
    const float radius = GetParam();
    SceneBuilder b("ground");
    b.sphere(b.world(), {0.0f, -radius, 0.0f}, radius, b.lambertian(vec3(0.5f)));
    Scene& s = b.scene();
    s.camera.lookFrom = {0.0f, 0.1f * radius, 0.05f * radius}; // looking 53-73 degrees down: only ground in view
    s.camera.lookAt = {0.0f, 0.0f, 0.0f};
    s.camera.vfovDegrees = 20.0f;
    s.background = {BackgroundType::Constant, vec3(1.0f), vec3(1.0f)};
    const Scene scene = b.finish();
    cpu::CpuEngine engine(EngineKind::Multi);
    engine.setScene(scene);
    RenderSettings settings;
    settings.width = 32;
    settings.spp = 16;
    settings.depth = 20;
    settings.estimator = Estimator::BsdfOnly; // zero variance: every escaping path carries exactly the albedo
    RenderControl control;
    const Image image = renderWithSettings(engine, settings, control).image;
    for (const vec3& p : image.pixels())
        ASSERT_NEAR(p.x, 0.5f, 1e-4f);
}

INSTANTIATE_TEST_SUITE_P(Radii, GroundSphere, ::testing::Values(1.0f, 100.0f, 1000.0f, 10000.0f));
} // namespace
} // namespace rt::test
