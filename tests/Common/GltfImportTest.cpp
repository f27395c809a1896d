// SceneFile/Gltf*: glTF 2.0 import. Files are written by tests/Support/GltfWriter.h, so every value read back is
// one the test chose. Here: node transforms composed down the hierarchy, the camera's conversion and the framing
// without one, indices of each width and none, strips, fans and sparse accessors, and the one warning line.
// Materials and textures: GltfMaterialsTest.cpp; errors and damaged files: GltfErrorsTest.cpp.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "SceneFile/GltfImport.h"
#include "SceneFile/SceneFile.h"
#include "Support/GltfTestFiles.h"

namespace rt::test
{
namespace
{
// ---- Nodes --------------------------------------------------------------------------------------------------

TEST(GltfNodes, TranslateRotateScaleComposeDownTheHierarchy)
{
    ScratchDir dir;
    GltfWriter w;
    const int mesh = w.mesh({triangle()});
    const double s = std::sqrt(0.5);
    // Child: scale 2, then +90 degrees about +y (x -> -z), in TRS; parent: translate (1, 2, 3).
    const int child = w.node({{"mesh", mesh}, {"scale", {2, 2, 2}}, {"rotation", {0, s, 0, s}}});
    w.scene({w.node({{"translation", {1, 2, 3}}, {"children", {child}}})});
    const Scene scene = readGltf(w.writeGltf(dir.path(), "trs")).scene;
    ASSERT_EQ(scene.meshes.size(), 1u);
    const MeshData& m = scene.meshes[0];
    expectNear(m.positions[0], {1, 2, 1}); // (1,0,0): (2,0,0), (0,0,-2), + (1,2,3)
    expectNear(m.positions[1], {1, 4, 3}); // (0,1,0): (0,2,0)
    expectNear(m.positions[2], {3, 2, 3}); // (0,0,1): (0,0,2), (2,0,0)
    // The instance is the identity: the transform is in the vertices.
    ASSERT_EQ(scene.instances.size(), 1u);
    EXPECT_TRUE(scene.instances[0].worldFromObject.isIdentity());
}

TEST(GltfNodes, MatrixIsColumnMajorAndComposesWithAChildsTrs)
{
    ScratchDir dir;
    GltfWriter w;
    const int mesh = w.mesh({triangle()});
    const int child = w.node({{"mesh", mesh}, {"translation", {1, 0, 0}}});
    // Scale 3, then translate (0, 0, -5): the translation is the fourth column, elements 12 to 14.
    const std::vector<double> matrix = {3, 0, 0, 0, 0, 3, 0, 0, 0, 0, 3, 0, 0, 0, -5, 1};
    w.scene({w.node({{"matrix", matrix}, {"children", {child}}})});
    const MeshData m = readGltf(w.writeGltf(dir.path(), "matrix")).scene.meshes.at(0);
    expectNear(m.positions[0], {6, 0, -5}); // (1,0,0) + (1,0,0) = (2,0,0), x3, then z - 5
    expectNear(m.positions[1], {3, 3, -5});
    expectNear(m.positions[2], {3, 0, -2});
}

TEST(GltfNodes, MirroringTransformKeepsFrontFacesCounterClockwise)
{
    ScratchDir dir;
    GltfWriter w;
    Primitive p = triangle();
    p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}; // front +z
    const int mesh = w.mesh({p});
    w.scene({w.node({{"mesh", mesh}, {"scale", {-1, 1, 1}}})});
    const MeshData m = readGltf(w.writeGltf(dir.path(), "mirror")).scene.meshes.at(0);
    const vec3 a = m.positions[m.indices[0]], b = m.positions[m.indices[1]], c = m.positions[m.indices[2]];
    const vec3 front = glm::cross(b - a, c - a);
    EXPECT_GT(front.z, 0.0f) << "a mirror in x keeps the triangle facing +z (spec §3.7.2.1)";
    expectNear(m.normals[0], {0, 0, 1});
}

TEST(GltfNodes, NormalsFollowTheInverseTranspose)
{
    ScratchDir dir;
    GltfWriter w;
    Primitive p = triangle();
    const float r = std::sqrt(0.5f);
    p.normals = {{r, r, 0}, {r, r, 0}, {r, r, 0}};
    const int mesh = w.mesh({p});
    w.scene({w.node({{"mesh", mesh}, {"scale", {2, 1, 1}}})});
    const MeshData m = readGltf(w.writeGltf(dir.path(), "normals")).scene.meshes.at(0);
    expectNear(m.normals[0], glm::normalize(vec3(0.5f, 1.0f, 0.0f)));
}

TEST(GltfNodes, ACycleIsAnErrorNotALoop)
{
    ScratchDir dir;
    GltfWriter w;
    const int mesh = w.mesh({triangle()});
    w.node({{"mesh", mesh}, {"children", {1}}});
    w.node({{"children", {0}}});
    w.scene({0});
    EXPECT_NE(errorOf(w.writeGltf(dir.path(), "cycle")).find("node 0 is reached twice"), std::string::npos);
}

TEST(GltfNodes, WithoutScenesEveryRootNodeIsRendered)
{
    ScratchDir dir;
    GltfWriter w;
    const int mesh = w.mesh({triangle()});
    const int child = w.node({{"mesh", mesh}, {"translation", {0, 10, 0}}});
    w.node({{"mesh", mesh}, {"children", {child}}});
    w.node({{"mesh", mesh}, {"translation", {5, 0, 0}}});
    const Scene scene = readGltf(w.writeGltf(dir.path(), "noscene")).scene;
    ASSERT_EQ(scene.meshes.size(), 3u); // each node's copy of the mesh, the child's under its parent
    expectNear(scene.meshes[0].positions[0], {1, 0, 0});
    expectNear(scene.meshes[1].positions[0], {1, 10, 0});
    expectNear(scene.meshes[2].positions[0], {6, 0, 0});
}

// ---- Camera -------------------------------------------------------------------------------------------------

TEST(GltfCamera, LooksDownTheNodesMinusZWithItsUp)
{
    ScratchDir dir;
    GltfWriter w;
    const int mesh = w.mesh({triangle()});
    const double angle = -10.0 * std::numbers::pi / 180.0; // about +x: looking 10 degrees down
    const int cam = w.perspective(0.5, 1.5);
    const int camNode = w.node({{"camera", cam}, {"rotation", {std::sin(angle / 2), 0, 0, std::cos(angle / 2)}}});
    w.scene({w.node({{"mesh", mesh}}), w.node({{"translation", {0, 1, 5}}, {"children", {camNode}}})});
    const Scene scene = readGltf(w.writeGltf(dir.path(), "camera")).scene;
    const float d = 10.0f * std::numbers::pi_v<float> / 180.0f;
    expectNear(scene.camera.lookFrom, {0, 1, 5});
    expectNear(scene.camera.lookAt - scene.camera.lookFrom, {0, -std::sin(d), -std::cos(d)});
    expectNear(scene.camera.vup, {0, std::cos(d), -std::sin(d)});
    EXPECT_NEAR(scene.camera.vfovDegrees, 0.5 * 180.0 / std::numbers::pi, 1e-4);
    EXPECT_EQ(scene.camera.defocusAngleDegrees, 0.0f);
    EXPECT_FLOAT_EQ(scene.defaults.aspect, 1.5f);
}

TEST(GltfCamera, FirstPerspectiveCameraWinsOrthographicIsNoted)
{
    ScratchDir dir;
    GltfWriter w;
    const int mesh = w.mesh({triangle()});
    const int ortho = w.camera({{"type", "orthographic"},
                                {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}});
    const int first = w.perspective(0.8);
    const int second = w.perspective(0.3);
    w.scene({w.node({{"mesh", mesh}}), w.node({{"camera", ortho}, {"translation", {9, 9, 9}}}),
             w.node({{"camera", first}, {"translation", {0, 0, 3}}}),
             w.node({{"camera", second}, {"translation", {0, 0, 7}}})});
    const GltfImport imported = readGltf(w.writeGltf(dir.path(), "cameras"));
    expectNear(imported.scene.camera.lookFrom, {0, 0, 3});
    EXPECT_NEAR(imported.scene.camera.vfovDegrees, 0.8 * 180.0 / std::numbers::pi, 1e-4);
    EXPECT_EQ(imported.scene.defaults.aspect, SceneDefaults{}.aspect) << "no aspectRatio: the default";
    EXPECT_NE(imported.unmapped.find("orthographic cameras"), std::string::npos) << imported.unmapped;
}

TEST(GltfCamera, WithoutOneTheBoundsAreFramedFromPlusZ)
{
    ScratchDir dir;
    GltfWriter w;
    Primitive p = triangle();
    p.positions = {{-1, 0, 0}, {3, 0, 0}, {-1, 2, 4}}; // box [-1, 3] x [0, 2] x [0, 4]
    const int mesh = w.mesh({p});
    w.scene({w.node({{"mesh", mesh}})});
    const CameraDesc c = readGltf(w.writeGltf(dir.path(), "framed")).scene.camera;
    expectNear(c.lookAt, {1, 1, 2});
    const double radius = 0.5 * std::sqrt(16.0 + 4.0 + 16.0);
    const double distance = c.lookFrom.z - c.lookAt.z;
    expectNear(c.lookFrom, {1, 1, c.lookFrom.z});
    // The sphere around the bounds fills the view but for the margin: its angular radius is vfov / 2 / 1.1-ish.
    const double halfAngle = std::asin(radius / distance) * 180.0 / std::numbers::pi;
    EXPECT_LT(halfAngle, 0.5 * c.vfovDegrees);
    EXPECT_GT(halfAngle, 0.8 * 0.5 * c.vfovDegrees);
}

TEST(GltfCamera, YfovOutOfRangeIsRefusedNamingIt)
{
    ScratchDir dir;
    GltfWriter w;
    const int mesh = w.mesh({triangle()});
    const int cam = w.perspective(3.5); // 200 degrees
    w.scene({w.node({{"mesh", mesh}}), w.node({{"camera", cam}})});
    EXPECT_NE(errorOf(w.writeGltf(dir.path(), "fov")).find("/cameras/0/perspective/yfov"), std::string::npos);
}

// ---- Indices and modes --------------------------------------------------------------------------------------

TEST(GltfMeshes, IndicesOfEveryWidthAndNoneReadAlike)
{
    ScratchDir dir;
    GltfWriter w;
    Primitive quad = triangle();
    quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    quad.normals.clear();
    quad.uvs.clear();
    quad.indices = {0, 1, 2, 0, 2, 3};
    std::vector<Primitive> primitives;
    for (int type : {GltfWriter::kUnsignedByte, GltfWriter::kUnsignedShort, GltfWriter::kUnsignedInt})
    {
        quad.indexType = type;
        primitives.push_back(quad);
    }
    Primitive soup = quad;
    soup.indexType = GltfWriter::kNoIndices;
    soup.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    primitives.push_back(soup);
    const int mesh = w.mesh(primitives);
    w.scene({w.node({{"mesh", mesh}})});
    const Scene scene = readGltf(w.writeGltf(dir.path(), "indices")).scene;
    ASSERT_EQ(scene.meshes.size(), 4u);
    for (int k = 0; k < 3; ++k)
        EXPECT_EQ(scene.meshes[k].indices, quad.indices) << "width " << k;
    EXPECT_EQ(scene.meshes[3].indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
    EXPECT_EQ(scene.meshes[3].positions[5], vec3(0, 1, 0));
}

TEST(GltfMeshes, StripsAndFansBecomeTriangles)
{
    ScratchDir dir;
    GltfWriter w;
    Primitive strip = triangle();
    strip.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    strip.normals.clear();
    strip.uvs.clear();
    strip.indices = {0, 1, 2, 3};
    strip.mode = 5;
    Primitive fan = strip;
    fan.indices = {0, 1, 3, 2};
    fan.mode = 6;
    const int mesh = w.mesh({strip, fan});
    w.scene({w.node({{"mesh", mesh}})});
    const Scene scene = readGltf(w.writeGltf(dir.path(), "strips")).scene;
    EXPECT_EQ(scene.meshes.at(0).indices, (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2})); // both counter-clockwise
    EXPECT_EQ(scene.meshes.at(1).indices, (std::vector<std::uint32_t>{1, 3, 0, 3, 2, 0}));
}

TEST(GltfMeshes, GltfAndGlbAndDataUriFilesImportTheSameScene)
{
    ScratchDir dir;
    GltfWriter w;
    const int mat = w.material({{"pbrMetallicRoughness", {{"baseColorFactor", {0.3, 0.3, 0.3, 1}}, {"metallicFactor", 0}}}});
    const int mesh = w.mesh({triangle(mat)});
    w.scene({w.node({{"mesh", mesh}, {"translation", {1, 2, 3}}})});
    const Scene a = readGltf(w.writeGltf(dir.path(), "a")).scene;
    const Scene b = readGltf(w.writeGlb(dir.path(), "b")).scene;
    const Scene c = readGltf(w.writeEmbedded(dir.path(), "c")).scene;
    for (const Scene* s : {&b, &c})
    {
        EXPECT_EQ(s->meshes.at(0).positions, a.meshes.at(0).positions);
        EXPECT_EQ(s->meshes.at(0).indices, a.meshes.at(0).indices);
        EXPECT_EQ(s->materials.size(), a.materials.size());
    }
    EXPECT_EQ(loadSceneFile(dir / "b.glb").meshes.at(0).positions, a.meshes.at(0).positions) << "through SceneFile";
}

TEST(GltfMeshes, SparseAccessorsApplyTheirSubstitutions)
{
    ScratchDir dir;
    GltfWriter w;
    const int mesh = w.mesh({triangle()});
    // POSITION is accessor 0; move vertex 2 to (0, 0, 5).
    const std::uint8_t index = 2;
    const float value[3] = {0, 0, 5};
    const int indexView = w.bufferView(&index, 1);
    const int valueView = w.bufferView(value, sizeof value);
    w.json()["accessors"][0]["sparse"] = {{"count", 1},
                                         {"indices", {{"bufferView", indexView}, {"componentType", GltfWriter::kUnsignedByte}}},
                                         {"values", {{"bufferView", valueView}}}};
    w.scene({w.node({{"mesh", mesh}})});
    const MeshData m = readGltf(w.writeGltf(dir.path(), "sparse")).scene.meshes.at(0);
    EXPECT_EQ(m.positions[0], vec3(1, 0, 0));
    EXPECT_EQ(m.positions[2], vec3(0, 0, 5));
}

// ---- The warning --------------------------------------------------------------------------------------------

TEST(GltfWarning, OneLineNamesEachUnmappedFeatureOnce)
{
    ScratchDir dir;
    GltfWriter w;
    const int image = w.imageDataUri(checkerPng(dir));
    const nlohmann::json texture = {{"index", w.texture(image)}};
    const int mat = w.material({{"name", "Fancy"},
                                {"normalTexture", texture},
                                {"occlusionTexture", texture},
                                {"extensions", {{"KHR_materials_clearcoat", {{"clearcoatFactor", 1}}}}},
                                {"pbrMetallicRoughness",
                                 {{"baseColorTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"rotation", 1}}}}}}},
                                  {"metallicFactor", 0}}}});
    const int other = w.material({{"name", "Other"}, {"normalTexture", texture}, {"pbrMetallicRoughness", {{"metallicFactor", 0}}}});
    Primitive lines = triangle(mat);
    lines.mode = 1;
    lines.indices = {0, 1, 1, 2};
    Primitive outside = triangle(mat);
    outside.uvs = {{0, 0}, {2, 0}, {0, 1}};
    const int mesh = w.mesh({triangle(mat), lines, outside, triangle(other)}, "Thing");
    w.json()["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = w.json()["meshes"][0]["primitives"][0]["attributes"]["NORMAL"];
    w.json()["animations"] = nlohmann::json::array({{{"channels", nlohmann::json::array()}, {"samplers", nlohmann::json::array()}}});
    w.json()["extensionsUsed"] = {"KHR_materials_clearcoat", "KHR_texture_transform", "EXT_unknown_thing"};
    w.scene({w.node({{"mesh", mesh}})});
    const GltfImport imported = readGltf(w.writeGltf(dir.path(), "fancy"));
    const std::string warning = imported.warning();
    EXPECT_EQ(warning.find('\n'), std::string::npos) << "one line";
    EXPECT_EQ(warning.rfind(dir.path().string(), 0), 0u) << "starts with the file: " << warning;
    for (const char* feature :
         {"normal textures (material 'Fancy', material 'Other')", "occlusion textures (material 'Fancy')",
          "KHR_materials_clearcoat (material 'Fancy')", "KHR_texture_transform", "LINES primitives (skipped) (mesh 'Thing')",
          "vertex colours (mesh 'Thing')", "texture coordinates repeating within a triangle (clamped) (mesh 'Thing')", "animations", "EXT_unknown_thing",
          "lit by a gradient sky"})
        EXPECT_NE(warning.find(feature), std::string::npos) << feature << " in: " << warning;
    // Each feature once, however often met.
    EXPECT_EQ(warning.find("normal textures"), warning.rfind("normal textures")) << warning;
    EXPECT_EQ(warning.find("KHR_materials_clearcoat"), warning.rfind("KHR_materials_clearcoat")) << warning;
    EXPECT_EQ(warning.find("KHR_texture_transform"), warning.rfind("KHR_texture_transform")) << warning;
    EXPECT_EQ(imported.scene.meshes.size(), 3u) << "the LINES primitive skipped";
}

TEST(GltfWarning, TinygltfsOwnComplaintsArePassedOn)
{
    // tinygltf reads past a textureInfo without its required index (leaving it at -1), saying so in its error text.
    ScratchDir dir;
    GltfWriter w;
    const int mat = w.material({{"normalTexture", {{"scale", 1}}}, {"pbrMetallicRoughness", {{"metallicFactor", 0}}}});
    const GltfImport imported = readGltf(oneTriangle(dir, mat, w));
    EXPECT_NE(imported.unmapped.find("tinygltf: 'index' property is missing in NormalTextureInfo."), std::string::npos)
        << imported.unmapped;
    EXPECT_EQ(imported.unmapped.find("normal textures"), std::string::npos) << "no index: no normal texture";
}

} // namespace
} // namespace rt::test
