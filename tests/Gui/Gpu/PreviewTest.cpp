// Host-side pieces of the window's images: the rasterised preview's geometry and camera, and the heatmap's
// cost summary.
#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "App/Gui/PreviewMesh.h"
#include "Engine/ProgressiveFrame.h"
#include "App/Gui/RasterPreview.h"
#include "Scenes/Catalogue.h"

namespace rt::gpu::gui
{
namespace
{
Scene oneGroup(const GroupDesc& group, const Transform& worldFromObject, const std::vector<MaterialData>& materials,
               const std::vector<TextureData>& textures)
{
    Scene s;
    s.id = "test";
    s.textures = textures;
    s.materials = materials;
    s.groups = {group};
    s.instances = {{0, worldFromObject}};
    return s;
}

TextureData solid(const vec3& color)
{
    TextureData t{};
    t.type = TextureType::Solid;
    t.color0 = color;
    return t;
}

MaterialData lambertian(std::uint32_t texture)
{
    MaterialData m{};
    m.type = MaterialType::Lambertian;
    m.albedoTexture = texture;
    m.emissionTexture = kNoIndex;
    return m;
}

MaterialData light(std::uint32_t texture)
{
    MaterialData m{};
    m.type = MaterialType::DiffuseLight;
    m.albedoTexture = kNoIndex;
    m.emissionTexture = texture;
    return m;
}

TEST(PreviewMesh, QuadIsTwoTrianglesWithItsNormalAndAlbedo)
{
    GroupDesc g;
    g.quads.push_back({vec3(0.0f), vec3(2, 0, 0), vec3(0, 3, 0), 0});
    const PreviewGeometry p = buildPreviewGeometry(
        oneGroup(g, Transform::translate({0, 0, 5}), {lambertian(0)}, {solid({0.2f, 0.4f, 0.6f})}));
    ASSERT_EQ(p.triangles.size(), 6u);
    for (const PreviewVertex& v : p.triangles)
    {
        EXPECT_FLOAT_EQ(v.position.z, 5.0f);
        EXPECT_FLOAT_EQ(v.normal.z, 1.0f);
        EXPECT_EQ(v.color, vec4(0.2f, 0.4f, 0.6f, 1.0f));
    }
}

TEST(PreviewMesh, SpheresFollowTheirInstanceAndEmittersAreFlatAndNormalised)
{
    GroupDesc g;
    g.spheres.push_back({vec3(1, 0, 0), vec3(1, 0, 0), 0.5f, 0});
    const PreviewGeometry p = buildPreviewGeometry(oneGroup(
        g, Transform::translate({0, 10, 0}) * Transform::scale(vec3(2.0f)), {light(0)}, {solid({15, 10, 5})}));
    ASSERT_EQ(p.spheres.size(), 1u);
    EXPECT_EQ(p.spheres[0].sphere, vec4(2, 10, 0, 1));
    EXPECT_EQ(p.spheres[0].color, vec4(1.0f, 10.0f / 15.0f, 5.0f / 15.0f, 0.0f));
}

TEST(PreviewMesh, BoxMediumIsTwelveTriangles)
{
    GroupDesc g;
    MediumDesc box;
    box.boundary = MediumDesc::Boundary::Box;
    box.boxMin = vec3(0.0f);
    box.boxMax = vec3(1.0f);
    g.media.push_back(box);
    const PreviewGeometry p = buildPreviewGeometry(oneGroup(g, Transform::identity(), {lambertian(0)}, {solid(vec3(0.5f))}));
    EXPECT_EQ(p.triangles.size(), 36u);
}

TEST(PreviewMesh, EveryCatalogueSceneHasSomethingToDraw)
{
    for (const SceneInfo& info : sceneCatalogue())
    {
        const PreviewGeometry p = buildPreviewGeometry(makeScene(info.id));
        EXPECT_GT(p.triangles.size() + p.spheres.size(), 0u) << info.id;
    }
}

TEST(PreviewMesh, UnitSphereVerticesAreOnTheSphere)
{
    const std::vector<PreviewVertex> sphere = unitSphereMesh(8, 4);
    EXPECT_EQ(sphere.size(), 8u * 4u * 6u);
    for (const PreviewVertex& v : sphere)
        EXPECT_NEAR(glm::length(v.position), 1.0f, 1e-5f);
}

TEST(RasterPreview, TheTargetIsAtTheCentreAndUpIsUp)
{
    CameraDesc c;
    c.lookFrom = vec3(0, 0, 10);
    c.lookAt = vec3(0, 0, 0);
    c.vfovDegrees = 90.0f;
    const mat4 m = clipFromWorld(c, 2.0f, Aabb(vec3(-1.0f), vec3(1.0f)));
    const vec4 centre = m * vec4(0, 0, 0, 1);
    EXPECT_NEAR(centre.x / centre.w, 0.0f, 1e-6f);
    EXPECT_NEAR(centre.y / centre.w, 0.0f, 1e-6f);
    EXPECT_GT(centre.z / centre.w, 0.0f);
    EXPECT_LT(centre.z / centre.w, 1.0f);
    // Half the vertical field of view above the axis is the top edge: y = -1 in Vulkan's clip space.
    const vec4 top = m * vec4(0, 10, 0, 1);
    EXPECT_NEAR(top.y / top.w, -1.0f, 1e-5f);
    // The aspect widens x: the point at 45 degrees to the right is half way to the right edge.
    const vec4 right = m * vec4(10, 0, 0, 1);
    EXPECT_NEAR(right.x / right.w, 0.5f, 1e-5f);
}

TEST(CostSummary, NinetyFifthPercentileInsideItsBucket)
{
    shader::CostStats stats{};
    const float max = 1.0e6f;
    std::memcpy(&stats.maxBits, &max, sizeof(max));
    stats.buckets[10] = 90; // [1024, 2048)
    stats.buckets[11] = 10; // [2048, 4096): the 95th percentile is half way through, in log2
    const CostSummary s = summarizeCost(stats);
    EXPECT_FLOAT_EQ(s.max, 1.0e6f);
    EXPECT_NEAR(s.high, std::exp2(11.5f), 1.0f);
    EXPECT_EQ(summarizeCost(shader::CostStats{}).high, 0.0f);
}
} // namespace
} // namespace rt::gpu::gui
