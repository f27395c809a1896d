// SBT layout arithmetic for the two drivers the project targets (queried values, never assumed ones), and
// the hit records a scene's TLAS instances reach: with only the hit groups a scene needs, each instance's
// sbtRecordOffset + geometry index must land on the record holding its geometry's shader group, in the
// general pipeline (every group) and in the scene's specialised one (its groups only), on lavapipe's 32-byte
// and NVIDIA's 64-byte base alignment.
#include <gtest/gtest.h>

#include "RayTracing/HitGroupLayout.h"
#include "RayTracing/RayTracingPipeline.h"
#include "RayTracing/SceneLayout.h"
#include "RayTracing/ShaderBindingTable.h"
#include "Scene/SceneBuilder.h"
#include "Scenes/Catalogue.h"

namespace rt::gpu
{
namespace
{
void expectValid(const SbtLayout& l, std::uint32_t handleSize, std::uint32_t handleAlignment,
                 std::uint32_t baseAlignment, std::uint32_t missCount, std::uint32_t hitCount)
{
    for (const SbtLayout::Region* r : {&l.raygen, &l.miss, &l.hit})
    {
        EXPECT_EQ(r->offset % baseAlignment, 0u);
        EXPECT_EQ(r->stride % handleAlignment, 0u);
        EXPECT_GE(r->stride, handleSize);
    }
    EXPECT_EQ(l.raygen.size, l.raygen.stride); // VUID-vkCmdTraceRaysKHR-size-04023
    EXPECT_GE(l.miss.size, missCount * l.miss.stride);
    EXPECT_GE(l.hit.size, hitCount * l.hit.stride);
    EXPECT_GE(l.miss.offset, l.raygen.offset + l.raygen.size);
    EXPECT_GE(l.hit.offset, l.miss.offset + l.miss.size);
    EXPECT_EQ(l.totalSize, l.hit.offset + l.hit.size);
}

TEST(ShaderBindingTable, LavapipeLayout)
{
    const SbtLayout l = computeSbtLayout(32, 16, 32, 1, 3);
    expectValid(l, 32, 16, 32, 1, 3);
    EXPECT_EQ(l.miss.offset, 32u);
    EXPECT_EQ(l.hit.offset, 64u);
    EXPECT_EQ(l.hit.stride, 32u);
    EXPECT_EQ(l.totalSize, 160u);
}

TEST(ShaderBindingTable, NvidiaLayoutUses64ByteRegionAlignment)
{
    const SbtLayout l = computeSbtLayout(32, 32, 64, 1, 3);
    expectValid(l, 32, 32, 64, 1, 3);
    EXPECT_EQ(l.raygen.stride, 64u);
    EXPECT_EQ(l.miss.offset, 64u);
    EXPECT_EQ(l.hit.offset, 128u);
    EXPECT_EQ(l.hit.stride, 32u);
}

TEST(ShaderBindingTable, HandleLargerThanAlignment)
{
    expectValid(computeSbtLayout(48, 16, 64, 2, 5), 48, 16, 64, 2, 5);
}

TEST(HitGroupLayout, RecordsFollowTheKindsPresent)
{
    const HitGroupLayout all = HitGroupLayout::all();
    EXPECT_EQ(all.count(), 3u);
    EXPECT_EQ(all.record(HitGroupKind::Triangles), 0u);
    EXPECT_EQ(all.record(HitGroupKind::Spheres), 1u);
    EXPECT_EQ(all.record(HitGroupKind::Media), 2u);
    const HitGroupLayout noSpheres(true, false, true);
    EXPECT_EQ(noSpheres.count(), 2u);
    EXPECT_EQ(noSpheres.record(HitGroupKind::Media), 1u);
    EXPECT_EQ(noSpheres.kindAt(1), HitGroupKind::Media);
    const HitGroupLayout noTriangles(false, true, true);
    EXPECT_EQ(noTriangles.record(HitGroupKind::Spheres), 0u);
    EXPECT_EQ(noTriangles.record(HitGroupKind::Media), 1u) << "media right after spheres (geometry 1)";
    EXPECT_TRUE(all.covers(noSpheres));
    EXPECT_FALSE(noSpheres.covers(noTriangles));
    // The general pipeline (groups raygen, 2 miss, triangles 3, spheres 4, media 5) serving a scene without
    // spheres puts its medium group in the scene's record 1.
    EXPECT_EQ(hitRecordGroups(noSpheres, all, 2), (std::vector<std::uint32_t>{3, 5}));
    EXPECT_EQ(hitRecordGroups(noSpheres, noSpheres, 2), (std::vector<std::uint32_t>{3, 4}));
}

struct Device
{
    const char* name;
    std::uint32_t handleSize, handleAlignment, baseAlignment;
};
constexpr Device kDevices[] = {{"lavapipe", 32, 16, 32}, {"nvidia", 32, 32, 64}};

/// The kinds of a pipeline's hit groups in group order, as createPathTracingPipeline adds them.
std::vector<HitGroupKind> pipelineHitKinds(const HitGroupLayout& groups)
{
    std::vector<HitGroupKind> kinds;
    for (HitGroupKind k : {HitGroupKind::Triangles, HitGroupKind::Spheres, HitGroupKind::Media})
        if (groups.has(k))
            kinds.push_back(k);
    return kinds;
}

/// Follows every TLAS instance of `scene` through traceRayEXT's record arithmetic (sbtRecordOffset 0,
/// stride 1: hit record = instance offset + geometry index) into the SBT the engine writes for `pipeline`'s
/// groups, and checks the record holds the shader group of that geometry's kind.
void expectEveryGeometryFindsItsGroup(const Scene& scene, bool specialised)
{
    const SceneLayout l = layoutScene(scene);
    const HitGroupLayout pipeline = specialised ? l.hitGroups : HitGroupLayout::all();
    const std::vector<HitGroupKind> groupKinds = pipelineHitKinds(pipeline);
    const std::vector<std::uint32_t> recordGroups = hitRecordGroups(l.hitGroups, pipeline, kMissGroupCount);
    for (const Device& d : kDevices)
    {
        SCOPED_TRACE(d.name);
        const SbtPlan plan = planSbt(d.handleSize, d.handleAlignment, d.baseAlignment, kMissGroupCount, recordGroups);
        expectValid(plan.layout, d.handleSize, d.handleAlignment, d.baseAlignment, kMissGroupCount,
                    l.hitGroups.count());
        const auto groupAt = [&](VkDeviceSize offset) -> int {
            for (const SbtPlan::Copy& c : plan.copies)
                if (c.offset == offset)
                    return int(c.group);
            return -1;
        };
        for (const TlasInstanceDesc& i : l.instances)
        {
            const BlasDesc& b = l.blases[i.blas];
            std::vector<HitGroupKind> geometries; // in BLAS geometry order
            if (b.kind == BlasDesc::Kind::Triangles)
                geometries.push_back(HitGroupKind::Triangles);
            if (b.sphereCount > 0)
                geometries.push_back(HitGroupKind::Spheres);
            if (b.mediumCount > 0)
                geometries.push_back(HitGroupKind::Media);
            for (std::uint32_t g = 0; g < geometries.size(); ++g)
            {
                const std::uint32_t record = i.hitGroup + g;
                ASSERT_LT(record, l.hitGroups.count());
                const VkDeviceSize offset = plan.layout.hit.offset + record * plan.layout.hit.stride;
                ASSERT_LE(offset + d.handleSize, plan.layout.hit.offset + plan.layout.hit.size);
                const int group = groupAt(offset);
                ASSERT_GE(group, int(1 + kMissGroupCount)) << "record " << record << " holds no hit group";
                ASSERT_LT(std::size_t(group - 1 - kMissGroupCount), groupKinds.size());
                EXPECT_EQ(groupKinds[group - 1 - kMissGroupCount], geometries[g]) << "record " << record;
            }
        }
    }
}

TEST(ShaderBindingTable, SceneWithoutSpheresFindsItsTriangleAndMediumGroups)
{
    const Scene smoke = makeScene("rtnw-cornell-smoke"); // quads and box media
    ASSERT_FALSE(layoutScene(smoke).hitGroups.has(HitGroupKind::Spheres));
    expectEveryGeometryFindsItsGroup(smoke, true);
    expectEveryGeometryFindsItsGroup(smoke, false);
    expectEveryGeometryFindsItsGroup(makeScene("rtnw-quads"), true); // triangles only
}

TEST(ShaderBindingTable, SceneWithoutTrianglesFindsItsSphereAndMediumGroups)
{
    const Scene spheres = makeScene("rtow-final");
    ASSERT_FALSE(layoutScene(spheres).hitGroups.has(HitGroupKind::Triangles));
    expectEveryGeometryFindsItsGroup(spheres, true);
    expectEveryGeometryFindsItsGroup(spheres, false);
    // Spheres with media in one BLAS (geometry 0 and 1), and a group of media alone.
    SceneBuilder b("fog");
    b.sphere(b.world(), vec3(0.0f), 1.0f, b.dielectric(1.5f));
    b.sphereMedium(b.world(), vec3(0.0f), 0.9f, 0.2f, vec3(0.5f));
    const std::uint32_t smoke = b.group("smoke");
    b.boxMedium(smoke, vec3(2.0f), vec3(3.0f), 0.1f, vec3(1.0f));
    b.instance(smoke, Transform::translate(vec3(1.0f)));
    const Scene fog = b.finish();
    ASSERT_EQ(layoutScene(fog).hitGroups, HitGroupLayout(false, true, true));
    expectEveryGeometryFindsItsGroup(fog, true);
    expectEveryGeometryFindsItsGroup(fog, false);
}

TEST(ShaderBindingTable, EveryCatalogueSceneFindsItsGroups)
{
    for (const SceneInfo& info : sceneCatalogue())
    {
        SCOPED_TRACE(info.id);
        SceneOptions options;
        if (info.id == "white-spheres")
            options.count = 200;
        const Scene scene = makeScene(info.id, options);
        expectEveryGeometryFindsItsGroup(scene, true);
        expectEveryGeometryFindsItsGroup(scene, false);
    }
}
} // namespace
} // namespace rt::gpu
