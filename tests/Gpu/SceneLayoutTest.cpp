// How Common scenes map onto BLASes, TLAS instances and the shaders' records (host only, no device).
#include <gtest/gtest.h>

#include "RayTracing/GeometryFingerprint.h"
#include "RayTracing/SceneLayout.h"
#include "Shared/QuadUv.h"
#include "Scene/SceneBuilder.h"
#include "Scenes/Catalogue.h"

namespace rt::gpu
{
namespace
{

std::size_t countKind(const SceneLayout& l, BlasDesc::Kind kind)
{
    std::size_t n = 0;
    for (const BlasDesc& b : l.blases)
        n += b.kind == kind;
    return n;
}

TEST(SceneLayout, AllSpheresOfAGroupShareOneProceduralBlas)
{
    SceneBuilder b("spheres");
    const std::uint32_t w = b.world();
    const std::uint32_t mat = b.lambertian(vec3(0.5f));
    for (int i = 0; i < 50; ++i)
        b.sphere(w, vec3(float(i), 0.0f, 0.0f), 0.4f, mat);
    const SceneLayout l = layoutScene(b.finish());
    ASSERT_EQ(l.blases.size(), 1u);
    EXPECT_EQ(l.blases[0].kind, BlasDesc::Kind::Procedural);
    EXPECT_EQ(l.blases[0].sphereCount, 50u);
    EXPECT_EQ(l.blases[0].mediumCount, 0u);
    ASSERT_EQ(l.instances.size(), 1u);
    EXPECT_EQ(l.instances[0].kind, HitGroupKind::Spheres);
    EXPECT_EQ(l.hitGroups, HitGroupLayout(false, true, false)) << "spheres only: one hit record";
    EXPECT_EQ(l.instances[0].hitGroup, 0u);
    EXPECT_EQ(l.spheres.size(), 50u);
    EXPECT_EQ(l.aabbs.size(), 50u);
}

TEST(SceneLayout, MovingSphereBoxCoversItsSweep)
{
    SceneBuilder b("moving");
    b.movingSphere(b.world(), vec3(0.0f), vec3(0.0f, 2.0f, 0.0f), 0.5f, b.lambertian(vec3(0.5f)));
    const SceneLayout l = layoutScene(b.finish());
    ASSERT_EQ(l.aabbs.size(), 1u);
    EXPECT_EQ(l.aabbs[0].min, vec3(-0.5f));
    EXPECT_EQ(l.aabbs[0].max, vec3(0.5f, 2.5f, 0.5f));
    EXPECT_EQ(l.spheres[0].center1, vec3(0.0f, 2.0f, 0.0f));
}

TEST(SceneLayout, QuadsBecomeTwoTrianglesWithEdgeUvsAndTheirNormal)
{
    SceneBuilder b("quads");
    const std::uint32_t red = b.lambertian(vec3(1, 0, 0));
    const std::uint32_t blue = b.lambertian(vec3(0, 0, 1));
    b.quad(b.world(), vec3(1, 2, 3), vec3(2, 0, 0), vec3(0, 0, -3), red);
    b.quad(b.world(), vec3(0, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1), blue);
    const SceneLayout l = layoutScene(b.finish());
    ASSERT_EQ(l.blases.size(), 1u);
    EXPECT_EQ(l.blases[0].kind, BlasDesc::Kind::Triangles);
    EXPECT_EQ(l.blases[0].triangleCount, 4u);
    EXPECT_EQ(l.blases[0].vertexCount, 8u);
    EXPECT_EQ(l.triangleMaterials, (std::vector<std::uint32_t>{red, red, blue, blue}));
    const shader::InstanceRecord& r = l.records[l.instances[0].record];
    ASSERT_EQ(r.firstUv, shader::kQuadUvs);
    // Every triangle faces along u x v, and the hit shader's uv (quadUv) at each corner is the corner's edge
    // coordinates: corner k of a triangle has barycentrics (b1, b2) = (0, 0), (1, 0), (0, 1).
    const vec3 quadNormal = glm::normalize(glm::cross(vec3(2, 0, 0), vec3(0, 0, -3)));
    for (int t = 0; t < 2; ++t)
    {
        const glm::uvec3 tri = l.triangles[r.firstTriangle + t];
        const vec3 p0 = l.positions[r.firstVertex + tri.x];
        const vec3 p1 = l.positions[r.firstVertex + tri.y];
        const vec3 p2 = l.positions[r.firstVertex + tri.z];
        EXPECT_GT(glm::dot(glm::normalize(glm::cross(p1 - p0, p2 - p0)), quadNormal), 0.999f);
        const vec2 corners[3] = {vec2(0, 0), vec2(1, 0), vec2(0, 1)};
        const std::uint32_t vertices[3] = {tri.x, tri.y, tri.z};
        for (int k = 0; k < 3; ++k)
        {
            const vec2 uv = shader::quadUv(std::uint32_t(t), corners[k].x, corners[k].y);
            const vec3 expected = vec3(1, 2, 3) + uv.x * vec3(2, 0, 0) + uv.y * vec3(0, 0, -3);
            EXPECT_EQ(l.positions[r.firstVertex + vertices[k]], expected) << "triangle " << t << " corner " << k;
        }
    }
    EXPECT_EQ(l.instances[0].kind, HitGroupKind::Triangles);
    EXPECT_EQ(l.hitGroups, HitGroupLayout(true, false, false));
    EXPECT_EQ(l.instances[0].hitGroup, 0u);
}

TEST(SceneLayout, SpheresAndMediaOfAGroupAreTwoGeometriesOfOneBlas)
{
    SceneBuilder b("fog");
    const std::uint32_t w = b.world();
    b.sphere(w, vec3(0.0f), 1.0f, b.dielectric(1.5f));
    b.sphereMedium(w, vec3(0.0f), 1.0f, 0.2f, vec3(0.5f));
    b.boxMedium(w, vec3(2.0f), vec3(3.0f), 0.1f, vec3(1.0f));
    const SceneLayout l = layoutScene(b.finish());
    ASSERT_EQ(l.blases.size(), 1u);
    EXPECT_EQ(l.blases[0].sphereCount, 1u);
    EXPECT_EQ(l.blases[0].mediumCount, 2u);
    EXPECT_EQ(l.instances[0].kind, HitGroupKind::Spheres);
    // Geometry 1 (media) lands on the record after the spheres': the medium group's.
    EXPECT_EQ(l.hitGroups, HitGroupLayout(false, true, true));
    EXPECT_EQ(l.instances[0].hitGroup + 1, l.hitGroups.record(HitGroupKind::Media));
    EXPECT_EQ(l.media[1].boundary, shader::MediumBoundary::Box);
    EXPECT_EQ(l.aabbs[l.blases[0].firstMediumAabb + 1].min, vec3(2.0f));
}

TEST(SceneLayout, MediaOnlyGroupStartsAtTheMediumHitGroup)
{
    SceneBuilder b("smoke");
    const std::uint32_t g = b.group("smoke");
    b.boxMedium(g, vec3(0.0f), vec3(1.0f), 0.01f, vec3(0.0f));
    b.instance(g, Transform::translate(vec3(5.0f)));
    const SceneLayout l = layoutScene(b.finish());
    ASSERT_EQ(l.instances.size(), 1u);
    EXPECT_EQ(l.instances[0].kind, HitGroupKind::Media);
    EXPECT_EQ(l.hitGroups, HitGroupLayout(false, false, true)) << "no sphere group without spheres";
    EXPECT_EQ(l.instances[0].hitGroup, 0u);
    EXPECT_EQ(l.instances[0].worldFromObject, Transform::translate(vec3(5.0f)).m);
}

TEST(SceneLayout, InstancedGroupReusesItsBlasesAndRecords)
{
    SceneBuilder b("boxes");
    const std::uint32_t box = b.group("box");
    b.box(box, vec3(0.0f), vec3(1.0f), b.lambertian(vec3(0.7f)));
    b.sphere(box, vec3(0.5f), 0.25f, b.metal(vec3(0.8f), 0.0f));
    for (int i = 0; i < 3; ++i)
        b.instance(box, Transform::translate(vec3(float(i) * 2.0f, 0.0f, 0.0f)));
    const SceneLayout l = layoutScene(b.finish());
    EXPECT_EQ(l.blases.size(), 2u); // the box's quads, its sphere
    EXPECT_EQ(l.records.size(), 2u);
    EXPECT_EQ(l.instances.size(), 6u); // 3 instances x 2 BLASes
    EXPECT_EQ(l.blases[0].triangleCount, 12u);
}

TEST(SceneLayout, EachInstanceOfAnEmittingGroupNamesItsOwnLights)
{
    // A group with a lit sphere, a lit quad and an unlit quad, placed twice: one BLAS per kind for both, but
    // each instance's records name that instance's lights, so a hit can find its LightData.
    SceneBuilder b("lamps");
    const std::uint32_t lamp = b.group("lamp");
    const std::uint32_t glow = b.diffuseLight(vec3(3.0f));
    b.quad(lamp, vec3(0.0f), {1, 0, 0}, {0, 1, 0}, b.lambertian(vec3(0.5f)));
    b.quad(lamp, vec3(0.0f, 2.0f, 0.0f), {1, 0, 0}, {0, 0, 1}, glow);
    b.sphere(lamp, vec3(0.5f), 0.25f, glow);
    b.instance(lamp, Transform::translate(vec3(0.0f)));
    b.instance(lamp, Transform::translate(vec3(5.0f, 0.0f, 0.0f)));
    const Scene scene = b.finish();
    ASSERT_EQ(scene.emitterCount(), 4u);
    const SceneLayout l = layoutScene(scene);
    EXPECT_EQ(l.blases.size(), 2u);
    std::vector<std::uint32_t> quadLights;
    std::vector<std::uint32_t> sphereLights;
    for (const TlasInstanceDesc& i : l.instances)
    {
        const shader::InstanceRecord& r = l.records[i.record];
        ASSERT_NE(r.firstPrimitiveLight, kNoIndex);
        if (i.kind == HitGroupKind::Triangles)
        {
            ASSERT_LE(r.firstPrimitiveLight + 4u, l.primitiveLights.size());
            EXPECT_EQ(l.primitiveLights[r.firstPrimitiveLight], kNoIndex); // the unlit quad, both triangles
            EXPECT_EQ(l.primitiveLights[r.firstPrimitiveLight + 1], kNoIndex);
            EXPECT_EQ(l.primitiveLights[r.firstPrimitiveLight + 2], l.primitiveLights[r.firstPrimitiveLight + 3]);
            quadLights.push_back(l.primitiveLights[r.firstPrimitiveLight + 2]);
        }
        else
            sphereLights.push_back(l.primitiveLights[r.firstPrimitiveLight]);
    }
    ASSERT_EQ(quadLights.size(), 2u);
    ASSERT_EQ(sphereLights.size(), 2u);
    for (int k = 0; k < 2; ++k)
    {
        // The LightData each names is that instance's primitive, in world space.
        const float x = 5.0f * float(k);
        EXPECT_EQ(scene.lights[quadLights[k]].shape, shader::LightShape::Quad);
        EXPECT_EQ(scene.lights[quadLights[k]].p0, vec3(x, 2.0f, 0.0f));
        EXPECT_EQ(scene.lights[sphereLights[k]].shape, shader::LightShape::Sphere);
        EXPECT_EQ(scene.lights[sphereLights[k]].p0, vec3(x + 0.5f, 0.5f, 0.5f));
    }
}

TEST(SceneLayout, MeshBlasIsSharedAcrossMaterials)
{
    // mesh-in-one-weekend places one mesh three times with three materials.
    const SceneLayout l = layoutScene(makeScene("mesh-in-one-weekend"));
    EXPECT_EQ(countKind(l, BlasDesc::Kind::Triangles), 1u);
    std::vector<std::uint32_t> materials;
    std::vector<std::uint32_t> blases;
    for (const TlasInstanceDesc& i : l.instances)
        if (i.kind == HitGroupKind::Triangles)
        {
            blases.push_back(i.blas);
            materials.push_back(l.records[i.record].material);
        }
    ASSERT_EQ(materials.size(), 3u);
    EXPECT_EQ(blases[0], blases[1]);
    EXPECT_EQ(blases[1], blases[2]);
    EXPECT_NE(materials[0], materials[1]);
    EXPECT_NE(materials[1], materials[2]);
}

TEST(SceneLayout, PerTriangleMaterialsOfAMesh)
{
    const SceneLayout l = layoutScene(makeScene("cube-and-spheres"));
    bool found = false;
    for (const shader::InstanceRecord& r : l.records)
        if (r.firstTriangleMaterial != kNoIndex && r.firstUv == kNoIndex)
        {
            found = true;
            EXPECT_LE(r.firstTriangleMaterial + 12u, l.triangleMaterials.size());
        }
    EXPECT_TRUE(found) << "the cube's six coloured faces";
}

TEST(SceneLayout, EveryCatalogueSceneIsConsistent)
{
    for (const SceneInfo& info : sceneCatalogue())
    {
        SCOPED_TRACE(info.id);
        SceneOptions options;
        if (info.id == "white-spheres")
            options.count = 200;
        const Scene scene = makeScene(info.id, options);
        const SceneLayout l = layoutScene(scene);
        EXPECT_FALSE(l.instances.empty());
        for (const TlasInstanceDesc& i : l.instances)
        {
            ASSERT_LT(i.blas, l.blases.size());
            ASSERT_LT(i.record, l.records.size());
            ASSERT_TRUE(l.hitGroups.has(i.kind));
            EXPECT_EQ(i.hitGroup, l.hitGroups.record(i.kind));
            const BlasDesc& b = l.blases[i.blas];
            if (b.sphereCount > 0 && b.mediumCount > 0) // media are geometry 1: the next record
            {
                EXPECT_EQ(i.hitGroup + 1, l.hitGroups.record(HitGroupKind::Media));
            }
        }
        EXPECT_EQ(l.hitGroups.has(HitGroupKind::Spheres), !l.spheres.empty());
        EXPECT_EQ(l.hitGroups.has(HitGroupKind::Media), !l.media.empty());
        EXPECT_EQ(l.hitGroups.has(HitGroupKind::Triangles), !l.triangles.empty());
        for (const BlasDesc& b : l.blases)
        {
            EXPECT_LE(b.firstTriangle + b.triangleCount, l.triangles.size());
            EXPECT_LE(b.firstVertex + b.vertexCount, l.positions.size());
            EXPECT_LE(b.firstMediumAabb + b.mediumCount, l.aabbs.size());
        }
        for (const shader::SphereRecord& s : l.spheres)
            EXPECT_LT(s.material, scene.materials.size());
        for (std::uint32_t m : l.triangleMaterials)
            EXPECT_LT(m, scene.materials.size());
        // Every emitter is named by exactly the primitives it was made from: as many as its triangles
        // (two per quad, one per mesh triangle) or one per sphere, over all records.
        std::vector<int> named(scene.lights.size(), 0);
        for (std::uint32_t light : l.primitiveLights)
            if (light != kNoIndex)
            {
                ASSERT_LT(light, scene.emitterCount());
                ++named[light];
            }
        for (std::uint32_t i = 0; i < scene.emitterCount(); ++i)
            EXPECT_EQ(named[i], scene.lights[i].shape == shader::LightShape::Quad ? 2 : 1) << "light " << i;
    }
}
TEST(SceneLayout, QuadsAndMediaWithoutSpheresTakeTwoRecords)
{
    const SceneLayout l = layoutScene(makeScene("rtnw-cornell-smoke"));
    EXPECT_EQ(l.hitGroups, HitGroupLayout(true, false, true));
    for (const TlasInstanceDesc& i : l.instances)
        EXPECT_EQ(i.hitGroup, i.kind == HitGroupKind::Triangles ? 0u : 1u);
}

TEST(GeometryFingerprint, SameGeometryWithOtherMaterialsMatches)
{
    SceneOptions exact;
    exact.fresnel = shader::FresnelModel::Exact;
    SceneOptions schlick;
    schlick.fresnel = shader::FresnelModel::Schlick;
    EXPECT_EQ(fingerprintOf(layoutScene(makeScene("rtrol-cornell-glass", exact))),
              fingerprintOf(layoutScene(makeScene("rtrol-cornell-glass", schlick))));

    // Materials and emission of the same shapes: the records and lights differ, not the acceleration structures.
    const auto scene = [](vec3 albedo, vec3 radiance) {
        SceneBuilder b("materials");
        b.sphere(b.world(), vec3(0.0f), 1.0f, b.lambertian(albedo));
        b.quad(b.world(), vec3(-1, 2, -1), vec3(2, 0, 0), vec3(0, 0, 2), b.diffuseLight(radiance));
        return b.finish();
    };
    EXPECT_EQ(fingerprintOf(layoutScene(scene(vec3(0.5f), vec3(4.0f)))),
              fingerprintOf(layoutScene(scene(vec3(0.9f, 0.1f, 0.1f), vec3(1.0f)))));
}

TEST(GeometryFingerprint, MovedInstancesKeepTheBlasesNotTheTlas)
{
    const auto scene = [](float x, float radius) {
        SceneBuilder b("moved");
        const std::uint32_t g = b.group("ball");
        b.sphere(g, vec3(0.0f), radius, b.lambertian(vec3(0.5f)));
        b.box(g, vec3(1.0f), vec3(2.0f), b.lambertian(vec3(0.5f)));
        b.instance(g, Transform::translate(vec3(x, 0.0f, 0.0f)));
        return b.finish();
    };
    const GeometryFingerprint a = fingerprintOf(layoutScene(scene(0.0f, 1.0f)));
    const GeometryFingerprint moved = fingerprintOf(layoutScene(scene(3.0f, 1.0f)));
    const GeometryFingerprint bigger = fingerprintOf(layoutScene(scene(0.0f, 1.5f)));
    EXPECT_EQ(a.blases, moved.blases);
    EXPECT_NE(a.tlas, moved.tlas);
    EXPECT_NE(a.blases, bigger.blases) << "a sphere's AABB is a build input";
    EXPECT_NE(a.tlas, bigger.tlas) << "new BLASes need a new TLAS";
    EXPECT_NE(fingerprintOf(layoutScene(makeScene("rtnw-cornell-box"))),
              fingerprintOf(layoutScene(makeScene("rtnw-quads"))));
}
} // namespace
} // namespace rt::gpu
