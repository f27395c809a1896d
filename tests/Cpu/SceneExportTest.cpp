// --export-scene's promise: every catalogue scene written as a JSON scene file and read back is the same
// scene, field by field and bit for bit (both in render space), and renders the same image bit for bit on the
// CPU engine.
#include <cstring>

#include <gtest/gtest.h>

#include "RenderTestSupport.h"
#include "SceneFile/JsonSceneWriter.h"
#include "SceneFile/SceneFile.h"
#include "Scenes/Catalogue.h"
#include "Support/CatalogueCases.h"
#include "Support/ScratchDir.h"

namespace rt::test
{
namespace
{
template <typename T>
bool sameBytes(const T& a, const T& b)
{
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

template <typename T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b)
{
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

/// Every field a renderer reads, compared bit for bit (names and ids aside).
void expectSameScene(const Scene& a, const Scene& b)
{
    EXPECT_TRUE(sameBytes(a.camera, b.camera)) << "camera";
    EXPECT_EQ(a.origin, b.origin) << "origin";
    EXPECT_TRUE(sameBytes(a.background, b.background)) << "background";
    const SceneDefaults& d = a.defaults; // field by field: the struct has padding after its bool
    const SceneDefaults& e = b.defaults;
    EXPECT_TRUE(d.spp == e.spp && d.depth == e.depth && d.width == e.width && sameBytes(d.aspect, e.aspect) &&
                d.unidirectionalLight == e.unidirectionalLight && d.estimator == e.estimator)
        << "defaults";
    EXPECT_TRUE(sameBytes(a.textures, b.textures)) << "textures";
    EXPECT_TRUE(sameBytes(a.materials, b.materials)) << "materials";
    ASSERT_EQ(a.images.size(), b.images.size());
    for (std::size_t i = 0; i < a.images.size(); ++i)
        EXPECT_TRUE(a.images[i].width == b.images[i].width && sameBytes(a.images[i].rgba, b.images[i].rgba)) << i;
    ASSERT_EQ(a.meshes.size(), b.meshes.size());
    for (std::size_t i = 0; i < a.meshes.size(); ++i)
    {
        const MeshData& m = a.meshes[i];
        const MeshData& n = b.meshes[i];
        EXPECT_TRUE(sameBytes(m.positions, n.positions) && sameBytes(m.normals, n.normals) && sameBytes(m.uvs, n.uvs) &&
                    sameBytes(m.indices, n.indices) && sameBytes(m.triangleMaterials, n.triangleMaterials))
            << "mesh " << i;
    }
    ASSERT_EQ(a.groups.size(), b.groups.size());
    for (std::size_t i = 0; i < a.groups.size(); ++i)
    {
        const GroupDesc& g = a.groups[i];
        const GroupDesc& h = b.groups[i];
        EXPECT_TRUE(sameBytes(g.spheres, h.spheres) && sameBytes(g.quads, h.quads) && sameBytes(g.meshes, h.meshes) &&
                    sameBytes(g.media, h.media))
            << "group " << i << " (" << g.name << ")";
    }
    EXPECT_TRUE(sameBytes(a.instances, b.instances)) << "instances";
    EXPECT_TRUE(sameBytes(a.lights, b.lights)) << "lights";
    EXPECT_TRUE(sameBytes(a.lightSources, b.lightSources)) << "light sources";
}

class CpuSceneExport : public ::testing::TestWithParam<std::string>
{
};

TEST_P(CpuSceneExport, ReadsBackTheSameSceneAndImage)
{
    SceneOptions options;
    options.count = GetParam() == "white-spheres" ? 2000 : -1; // the default 20,000 spheres write 3 MB
    const Scene original = makeScene(GetParam(), options);
    ScratchDir dir;
    const auto file = dir / (GetParam() + ".json");
    exportScene(placedScene(GetParam(), options), file); // as --export-scene: in the scene's own coordinates
    const Scene copy = makeScene(file.string()); // in render space, as the original
    expectSameScene(original, copy);

    RenderSettings s = smallSettings(24, 2, 8, original.defaults.estimator, original.defaults.aspect);
    s.unidirectionalLight = original.defaults.unidirectionalLight;
    s.seed = 5;
    const RenderResult a = renderCpu(original, s);
    const RenderResult b = renderCpu(copy, s);
    EXPECT_TRUE(bitIdentical(a.image, b.image));
}

INSTANTIATE_TEST_SUITE_P(AllScenes, CpuSceneExport, ::testing::ValuesIn(catalogueIds()),
                         [](const auto& param) { return testNameOf(param.param); });
} // namespace
} // namespace rt::test
