// SceneFile/Gltf*: glTF 2.0 import. Files are written by tests/Support/GltfWriter.h, so every value read back is
// one the test chose: node transforms composed down the hierarchy, the camera's conversion, each branch of the
// material mapping, images (embedded, data URI, file) with the base colour factor, indices of each width and
// none, the one warning line, each error with its message, and truncated or corrupted files.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "Error.h"
#include "Image/ImageIO.h"
#include "SceneFile/GltfAccessors.h"
#include "SceneFile/GltfImages.h"
#include "SceneFile/GltfImport.h"
#include "SceneFile/GltfMaterials.h"
#include "SceneFile/SceneFile.h"
#include "Support/GltfWriter.h"
#include "Support/ScratchDir.h"

namespace rt::test
{
namespace
{
using Primitive = GltfWriter::Primitive;

/// One counter-clockwise triangle seen from +z, with normals +z and uvs.
Primitive triangle(int material = -1)
{
    Primitive p;
    p.positions = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    p.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    p.uvs = {{0, 0}, {1, 0}, {0, 1}};
    p.indices = {0, 1, 2};
    p.material = material;
    return p;
}

/// A scene of one node holding one triangle (with `material`), written as .gltf + .bin.
std::filesystem::path oneTriangle(const ScratchDir& dir, int material, GltfWriter& w, const std::string& name = "t")
{
    const int mesh = w.mesh({triangle(material)});
    w.scene({w.node({{"mesh", mesh}})});
    return w.writeGltf(dir.path(), name);
}

/// The message of the rt::Error that importing `file` throws ("" if it imports), checking the error's kind.
template <typename E = SceneError>
std::string errorOf(const std::filesystem::path& file)
{
    try
    {
        readGltf(file);
    }
    catch (const E& e)
    {
        return e.what();
    }
    catch (const Error& e)
    {
        ADD_FAILURE() << "another kind of error: " << e.what();
        return e.what();
    }
    ADD_FAILURE() << file << " imported";
    return "";
}

void expectNear(const vec3& a, const vec3& b, float tolerance = 1e-5f)
{
    EXPECT_NEAR(a.x, b.x, tolerance) << "x";
    EXPECT_NEAR(a.y, b.y, tolerance) << "y";
    EXPECT_NEAR(a.z, b.z, tolerance) << "z";
}

const MaterialData& onlyMaterial(const Scene& s)
{
    EXPECT_EQ(s.groups.size(), 1u);
    return s.materials.at(s.groups.at(0).meshes.at(0).material);
}

vec3 solidColor(const Scene& s, std::uint32_t texture)
{
    EXPECT_EQ(s.textures.at(texture).type, TextureType::Solid);
    return s.textures.at(texture).color0;
}

/// A 2 x 2 PNG: red, green / blue, white (row 0 on top), written to `dir` and returned as bytes.
std::vector<std::uint8_t> checkerPng(const ScratchDir& dir, const std::string& name = "tex.png")
{
    const std::vector<unsigned char> rgba = {200, 10, 10, 255, 10, 200, 10, 255, 10, 10, 200, 255, 250, 250, 250, 255};
    writePng8(dir / name, 2, 2, rgba);
    return GltfWriter::readBytes(dir / name);
}

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

// ---- Materials ----------------------------------------------------------------------------------------------

TEST(GltfMaterials, EmissiveTimesStrengthIsADiffuseLight)
{
    ScratchDir dir;
    GltfWriter w;
    const int mat = w.material({{"emissiveFactor", {1.0, 0.5, 0.25}},
                                {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4}}}}},
                                {"pbrMetallicRoughness", {{"metallicFactor", 1}}}});
    w.json()["extensionsUsed"] = {"KHR_materials_emissive_strength"};
    const GltfImport imported = readGltf(oneTriangle(dir, mat, w));
    const MaterialData& m = onlyMaterial(imported.scene);
    ASSERT_EQ(m.type, MaterialType::DiffuseLight) << "emission comes first, before metal";
    expectNear(solidColor(imported.scene, m.emissionTexture), {4, 2, 1});
    EXPECT_EQ(imported.scene.emitterCount(), 1u);
    EXPECT_FALSE(imported.skyAdded);
    EXPECT_EQ(imported.scene.background.type, BackgroundType::Constant);
    EXPECT_EQ(imported.scene.background.color0, vec3(0.0f));
    EXPECT_TRUE(imported.scene.defaults.unidirectionalLight) << "single-sided: front only";
    EXPECT_EQ(imported.warning(), "") << "everything was mapped";
}

TEST(GltfMaterials, EmissiveWithoutStrengthAndDoubleSided)
{
    ScratchDir dir;
    GltfWriter w;
    const int mat = w.material({{"emissiveFactor", {0.5, 0.5, 0.5}}, {"doubleSided", true}});
    const GltfImport imported = readGltf(oneTriangle(dir, mat, w));
    expectNear(solidColor(imported.scene, onlyMaterial(imported.scene).emissionTexture), {0.5, 0.5, 0.5});
    EXPECT_FALSE(imported.scene.defaults.unidirectionalLight) << "a double-sided emitter emits from both sides";
}

TEST(GltfMaterials, TransmissionAboveHalfIsADielectricWithItsIor)
{
    ScratchDir dir;
    GltfWriter w;
    const int glass = w.material({{"extensions",
                                   {{"KHR_materials_transmission", {{"transmissionFactor", 0.9}}},
                                    {"KHR_materials_ior", {{"ior", 1.33}}}}}});
    const int plain = w.material({{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1}}}}}});
    const int weak = w.material({{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 0.4}}}}},
                                 {"pbrMetallicRoughness", {{"metallicFactor", 0}}}});
    const int mesh = w.mesh({triangle(glass), triangle(plain), triangle(weak)});
    w.scene({w.node({{"mesh", mesh}})});
    const Scene scene = readGltf(w.writeGltf(dir.path(), "glass")).scene;
    const auto material = [&](int k) { return scene.materials.at(scene.groups.at(0).meshes.at(k).material); };
    ASSERT_EQ(material(0).type, MaterialType::Dielectric);
    EXPECT_FLOAT_EQ(material(0).ior, 1.33f);
    ASSERT_EQ(material(1).type, MaterialType::Dielectric);
    EXPECT_FLOAT_EQ(material(1).ior, 1.5f) << "KHR_materials_ior's default";
    EXPECT_EQ(material(2).type, MaterialType::Lambertian) << "transmission 0.4 is not glass";
}

TEST(GltfMaterials, MetallicIsMetalWithRoughnessAsFuzz)
{
    ScratchDir dir;
    GltfWriter w;
    const int mat = w.material(
        {{"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 0.8, 0.7, 1}}, {"metallicFactor", 0.5}, {"roughnessFactor", 0.3}}}});
    const Scene scene = readGltf(oneTriangle(dir, mat, w)).scene;
    const MaterialData& m = onlyMaterial(scene);
    ASSERT_EQ(m.type, MaterialType::Metal);
    EXPECT_FLOAT_EQ(m.fuzz, 0.3f);
    expectNear(solidColor(scene, m.albedoTexture), {0.9f, 0.8f, 0.7f});
}

TEST(GltfMaterials, DielectricLessNonMetalIsLambertianWithBaseColour)
{
    ScratchDir dir;
    GltfWriter w;
    const int mat = w.material({{"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.4, 0.6, 1}}, {"metallicFactor", 0.49}}}});
    const Scene scene = readGltf(oneTriangle(dir, mat, w)).scene;
    const MaterialData& m = onlyMaterial(scene);
    ASSERT_EQ(m.type, MaterialType::Lambertian);
    expectNear(solidColor(scene, m.albedoTexture), {0.2f, 0.4f, 0.6f});
}

TEST(GltfMaterials, SpecDefaultsAreWhiteRoughMetal)
{
    ScratchDir dir;
    GltfWriter w;
    const int mat = w.material({{"name", "bare"}}); // metallicFactor and roughnessFactor default to 1 (§3.9.2)
    const Scene scene = readGltf(oneTriangle(dir, mat, w)).scene;
    const MaterialData& m = onlyMaterial(scene);
    ASSERT_EQ(m.type, MaterialType::Metal);
    EXPECT_EQ(m.fuzz, 1.0f);
    expectNear(solidColor(scene, m.albedoTexture), {1, 1, 1});
}

TEST(GltfMaterials, NoMaterialIsGreyLambertianAndNoEmitterAddsTheSky)
{
    ScratchDir dir;
    GltfWriter w;
    const GltfImport imported = readGltf(oneTriangle(dir, -1, w));
    const MaterialData& m = onlyMaterial(imported.scene);
    ASSERT_EQ(m.type, MaterialType::Lambertian);
    expectNear(solidColor(imported.scene, m.albedoTexture), vec3(GltfMaterials::kDefaultGrey));
    EXPECT_TRUE(imported.skyAdded);
    EXPECT_EQ(imported.scene.background.type, BackgroundType::Gradient);
    EXPECT_EQ(imported.scene.background.color1, vec3(0.5f, 0.7f, 1.0f));
    EXPECT_NE(imported.warning().find("nothing in the file emits: lit by a gradient sky"), std::string::npos)
        << imported.warning();
}

TEST(GltfMaterials, FactorOutOfRangeIsRefusedNamingIt)
{
    ScratchDir dir;
    GltfWriter w;
    const int mat = w.material({{"pbrMetallicRoughness", {{"baseColorFactor", {1.5, 0, 0, 1}}}}});
    const std::string e = errorOf(oneTriangle(dir, mat, w));
    EXPECT_NE(e.find("t.gltf: /materials/0/pbrMetallicRoughness/baseColorFactor/0: expected a number in [0, 1], got 1.5"),
              std::string::npos)
        << e;
}

// ---- Textures -----------------------------------------------------------------------------------------------

/// A Lambertian triangle textured with `image` times `factor`.
std::filesystem::path texturedTriangle(const ScratchDir& dir, GltfWriter& w, int image, const std::vector<double>& factor,
                                       const std::string& name)
{
    const int mat = w.material({{"pbrMetallicRoughness",
                                 {{"baseColorTexture", {{"index", w.texture(image)}}},
                                  {"baseColorFactor", factor},
                                  {"metallicFactor", 0}}}});
    return oneTriangle(dir, mat, w, name);
}

TEST(GltfTextures, EmbeddedDataUriAndFileImagesGiveTheSameTexels)
{
    ScratchDir dir;
    const std::vector<std::uint8_t> png = checkerPng(dir);
    GltfWriter a, b, c;
    const Scene inBuffer = readGltf([&] {
                               const int image = a.imageInBuffer(png);
                               texturedTriangle(dir, a, image, {1, 1, 1, 1}, "unused");
                               return a.writeGlb(dir.path(), "buffer");
                           }())
                               .scene;
    const Scene inUri = readGltf(texturedTriangle(dir, b, b.imageDataUri(png), {1, 1, 1, 1}, "uri")).scene;
    const Scene inFile = readGltf(texturedTriangle(dir, c, c.imageFile("tex.png"), {1, 1, 1, 1}, "file")).scene;
    const std::vector<unsigned char> expected = {200, 10, 10, 255, 10, 200, 10, 255, 10, 10, 200, 255, 250, 250, 250, 255};
    for (const Scene* s : {&inBuffer, &inUri, &inFile})
    {
        const MaterialData& m = onlyMaterial(*s);
        ASSERT_EQ(s->textures.at(m.albedoTexture).type, TextureType::Image) << s->id;
        const ImageData& image = s->images.at(s->textures[m.albedoTexture].image);
        EXPECT_EQ(image.width, 2);
        EXPECT_EQ(image.rgba, expected) << s->id;
        // TEXCOORD_0 with v flipped: glTF's (0, 0) is the image's top left, the engines' (0, 1).
        EXPECT_EQ(s->meshes.at(0).uvs.at(0), vec2(0, 1));
        EXPECT_EQ(s->meshes.at(0).uvs.at(2), vec2(0, 0));
    }
}

TEST(GltfTextures, BaseColourFactorIsMultipliedIntoTheTexels)
{
    ScratchDir dir;
    const std::vector<std::uint8_t> png = checkerPng(dir);
    GltfWriter w;
    const Scene scene = readGltf(texturedTriangle(dir, w, w.imageDataUri(png), {0.5, 1, 0.25, 1}, "tinted")).scene;
    const ImageData& image = scene.images.at(scene.textures.at(onlyMaterial(scene).albedoTexture).image);
    EXPECT_EQ(image.rgba[0], linearToSrgb8(srgb8ToLinear(200) * 0.5f));
    EXPECT_EQ(image.rgba[1], 10);
    EXPECT_EQ(image.rgba[2], linearToSrgb8(srgb8ToLinear(10) * 0.25f));
    EXPECT_EQ(image.rgba[12], linearToSrgb8(srgb8ToLinear(250) * 0.5f));
    EXPECT_EQ(image.rgba[3], 255) << "alpha kept";
    EXPECT_NE(image.rgba[12], 250) << "the factor changed the texel";
}

TEST(GltfTextures, MetalTakesTheTextureToo)
{
    ScratchDir dir;
    GltfWriter w;
    const int mat = w.material({{"pbrMetallicRoughness",
                                 {{"baseColorTexture", {{"index", w.texture(w.imageDataUri(checkerPng(dir)))}}},
                                  {"metallicFactor", 1},
                                  {"roughnessFactor", 0}}}});
    const Scene scene = readGltf(oneTriangle(dir, mat, w)).scene;
    const MaterialData& m = onlyMaterial(scene);
    EXPECT_EQ(m.type, MaterialType::Metal);
    EXPECT_EQ(scene.textures.at(m.albedoTexture).type, TextureType::Image);
}

TEST(GltfTextures, RepeatedAndMirroredCoordinatesAreMovedIntoTheUnitSquarePerTriangle)
{
    ScratchDir dir;
    GltfWriter w;
    const int image = w.imageDataUri(checkerPng(dir));
    const int sampler = static_cast<int>(w.json()["samplers"].size());
    w.json()["samplers"].push_back({{"wrapS", 33648}, {"wrapT", 10497}}); // MIRRORED_REPEAT, REPEAT
    const int texture = w.texture(image);
    w.json()["textures"][texture]["sampler"] = sampler;
    const int mat = w.material({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", texture}}}, {"metallicFactor", 0}}}});
    Primitive p = triangle(mat);
    // Two triangles sharing vertices 1 and 2: the first within one period in s and t, the second spanning two in
    // s; each moves its corners differently, so the shared vertices are copied.
    p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    p.normals.clear();
    p.uvs = {{5.25, 2.5}, {6, 2.5}, {5, 3}, {4.5, 3}};
    p.indices = {0, 1, 2, 2, 1, 3};
    const int mesh = w.mesh({p});
    w.scene({w.node({{"mesh", mesh}})});
    const GltfImport imported = readGltf(w.writeGltf(dir.path(), "wrap"));
    const MeshData& m = imported.scene.meshes.at(0);
    const auto uv = [&](std::size_t corner) { return m.uvs.at(m.indices.at(corner)); };
    const auto expectUv = [&](std::size_t corner, float s, float t) { // glTF's (s, t); the mesh holds (s, 1 - t)
        EXPECT_NEAR(uv(corner).x, s, 1e-6f) << "corner " << corner;
        EXPECT_NEAR(uv(corner).y, 1.0f - t, 1e-6f) << "corner " << corner;
    };
    // First triangle: s in [5, 6], period 5 (odd, mirrored: s -> 6 - s); t in [2, 3], period 2 (t -> t - 2).
    expectUv(0, 0.75f, 0.5f);
    expectUv(1, 0.0f, 0.5f);
    expectUv(2, 1.0f, 1.0f);
    // Second: s in [4.5, 6] spans two periods: left to the clamp, and noted; t in [2.5, 3] still moves by 2.
    expectUv(4, 6.0f, 0.5f);
    expectUv(5, 4.5f, 1.0f);
    EXPECT_NE(imported.unmapped.find("texture coordinates repeating within a triangle"), std::string::npos);
    // Every corner keeps its position.
    EXPECT_EQ(m.positions.at(m.indices[1]), vec3(1, 0, 0));
    EXPECT_EQ(m.positions.at(m.indices[5]), vec3(1, 1, 0));
}

TEST(GltfTextures, ClampToEdgeAndUntexturedMaterialsKeepTheirCoordinates)
{
    ScratchDir dir;
    GltfWriter w;
    const int image = w.imageDataUri(checkerPng(dir));
    w.json()["samplers"].push_back({{"wrapS", 33071}, {"wrapT", 33071}}); // CLAMP_TO_EDGE
    const int texture = w.texture(image);
    w.json()["textures"][texture]["sampler"] = 0;
    const int clamped = w.material({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", texture}}}, {"metallicFactor", 0}}}});
    Primitive a = triangle(clamped);
    a.uvs = {{3, 3}, {3.5, 3}, {3, 3.5}};
    Primitive b = a;
    b.material = -1;
    const int mesh = w.mesh({a, b});
    w.scene({w.node({{"mesh", mesh}})});
    const GltfImport imported = readGltf(w.writeGltf(dir.path(), "clamp"));
    for (const MeshData& m : imported.scene.meshes)
    {
        EXPECT_EQ(m.uvs.size(), 3u) << m.name;
        EXPECT_EQ(m.uvs.at(1), vec2(3.5f, -2.0f)) << m.name;
    }
    EXPECT_EQ(imported.unmapped, "");
}

TEST(GltfTextures, MissingImageFileIsAnAssetErrorNamingIt)
{
    ScratchDir dir;
    GltfWriter w;
    const std::string e = errorOf<AssetError>(texturedTriangle(dir, w, w.imageFile("gone%20away.png"), {1, 1, 1, 1}, "t"));
    EXPECT_NE(e.find("/images/0/uri: image file"), std::string::npos) << e;
    EXPECT_NE(e.find("gone away.png' not found"), std::string::npos) << "percent-decoded: " << e;
}

TEST(GltfTextures, UndecodableImageIsAnAssetError)
{
    ScratchDir dir;
    GltfWriter w;
    const std::string e = errorOf<AssetError>(texturedTriangle(dir, w, w.imageDataUri({1, 2, 3, 4, 5}), {1, 1, 1, 1}, "t"));
    EXPECT_NE(e.find("/images/0: image"), std::string::npos) << e;
    EXPECT_NE(e.find("cannot be decoded"), std::string::npos) << e;
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

// ---- Errors -------------------------------------------------------------------------------------------------

TEST(GltfErrors, MissingFile)
{
    ScratchDir dir;
    try
    {
        loadSceneFile(dir / "absent.gltf");
        FAIL() << "imported";
    }
    catch (const SceneError& e)
    {
        EXPECT_NE(std::string(e.what()).find("absent.gltf' not found"), std::string::npos) << e.what();
    }
    EXPECT_NE(errorOf(dir / "absent.glb").find("absent.glb: cannot be opened"), std::string::npos);
}

TEST(GltfErrors, MalformedJsonNamesTheFileAndTheParsersPlace)
{
    ScratchDir dir;
    const std::string e = errorOf(dir.write("bad.gltf", "{\"asset\": {\"version\": \"2.0\"},,}"));
    EXPECT_NE(e.find("bad.gltf: not a valid glTF 2.0 JSON file:"), std::string::npos) << e;
    EXPECT_NE(e.find("column"), std::string::npos) << "the JSON parser's place: " << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << "one line";
}

TEST(GltfErrors, MissingAssetVersionIsTinygltfsErrorPassedOn)
{
    ScratchDir dir;
    const std::string e = errorOf(dir.write("noasset.gltf", "{\"scenes\": []}"));
    EXPECT_NE(e.find("noasset.gltf: not a valid glTF 2.0 JSON file:"), std::string::npos) << e;
    EXPECT_NE(e.find("asset"), std::string::npos) << e;
}

TEST(GltfErrors, AccessorIndexOutOfRange)
{
    ScratchDir dir;
    GltfWriter w;
    const int mesh = w.mesh({triangle()});
    w.json()["meshes"][mesh]["primitives"][0]["attributes"]["POSITION"] = 99;
    w.scene({w.node({{"mesh", mesh}})});
    const std::string e = errorOf(w.writeGltf(dir.path(), "index"));
    EXPECT_NE(e.find("index.gltf: /meshes/0/primitives/0/attributes/POSITION: accessor 99 does not exist"),
              std::string::npos)
        << e;
}

TEST(GltfErrors, AccessorOverrunningItsBufferView)
{
    ScratchDir dir;
    GltfWriter w;
    const int mesh = w.mesh({triangle()});
    w.json()["accessors"][0]["count"] = 4; // three vertices' bytes in the view
    w.scene({w.node({{"mesh", mesh}})});
    const std::string e = errorOf(w.writeGltf(dir.path(), "overrun"));
    EXPECT_NE(e.find("/accessors/0: 4 elements of 12 bytes from byte 0 of bufferView 0 (stride 12) overrun its 36 bytes"),
              std::string::npos)
        << e;
}

TEST(GltfErrors, BufferViewBeyondItsBuffer)
{
    ScratchDir dir;
    GltfWriter w;
    const int mesh = w.mesh({triangle()});
    w.json()["bufferViews"][0]["byteOffset"] = 1000;
    w.scene({w.node({{"mesh", mesh}})});
    const std::string e = errorOf(w.writeGltf(dir.path(), "view"));
    EXPECT_NE(e.find("/bufferViews/0: bytes 1000 to 1036 lie beyond buffer 0"), std::string::npos) << e;
}

TEST(GltfErrors, VertexIndexOutOfRange)
{
    ScratchDir dir;
    GltfWriter w;
    Primitive p = triangle();
    p.indices = {0, 1, 7};
    p.indexType = GltfWriter::kUnsignedShort;
    const int mesh = w.mesh({p});
    w.scene({w.node({{"mesh", mesh}})});
    const std::string e = errorOf(w.writeGltf(dir.path(), "vertex"));
    EXPECT_NE(e.find("index 2 is 7, beyond the 3 vertices of the primitive (/meshes/0/primitives/0/indices)"),
              std::string::npos)
        << e;
}

TEST(GltfErrors, WrongAccessorType)
{
    ScratchDir dir;
    GltfWriter w;
    const int mesh = w.mesh({triangle()});
    w.json()["accessors"][0]["type"] = "VEC2";
    w.scene({w.node({{"mesh", mesh}})});
    const std::string e = errorOf(w.writeGltf(dir.path(), "type"));
    EXPECT_NE(e.find("/accessors/0/type: /meshes/0/primitives/0/attributes/POSITION uses it as 3 numbers per element, "
                     "but its type is VEC2"),
              std::string::npos)
        << e;
}

TEST(GltfErrors, NonFinitePosition)
{
    ScratchDir dir;
    GltfWriter w;
    Primitive p = triangle();
    p.positions[1].y = std::numeric_limits<float>::infinity();
    const int mesh = w.mesh({p});
    w.json()["accessors"][0].erase("max"); // JSON has no infinity
    w.json()["accessors"][0].erase("min");
    w.scene({w.node({{"mesh", mesh}})});
    const std::string e = errorOf(w.writeGltf(dir.path(), "inf"));
    EXPECT_NE(e.find("/accessors/0: vertex 1 is (0, inf, 0): not finite"), std::string::npos) << e;
}

TEST(GltfErrors, MissingBufferFileIsAnAssetError)
{
    ScratchDir dir;
    GltfWriter w;
    const std::filesystem::path file = oneTriangle(dir, -1, w, "lost");
    std::filesystem::remove(dir / "lost.bin");
    const std::string e = errorOf<AssetError>(file);
    EXPECT_NE(e.find("lost.gltf: buffer file"), std::string::npos) << e;
    EXPECT_NE(e.find("lost.bin"), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << "one line";
}

TEST(GltfErrors, NoTrianglesToRender)
{
    ScratchDir dir;
    GltfWriter w;
    Primitive points = triangle();
    points.mode = 0;
    const int mesh = w.mesh({points});
    w.scene({w.node({{"mesh", mesh}}), w.node({{"name", "empty"}})});
    const std::string e = errorOf(w.writeGltf(dir.path(), "points"));
    EXPECT_NE(e.find("points.gltf: the scene has no triangles to render (2 nodes, 1 meshes in the file; not mapped: "
                     "POINTS primitives (skipped) (mesh 0))"),
              std::string::npos)
        << e;
}

TEST(GltfErrors, MaterialIndexOutOfRange)
{
    ScratchDir dir;
    GltfWriter w;
    const std::string e = errorOf(oneTriangle(dir, 3, w));
    EXPECT_NE(e.find("/meshes/0/primitives/0/material: material 3 does not exist (the file has 0)"), std::string::npos)
        << e;
}

// ---- Robustness ---------------------------------------------------------------------------------------------

/// Imports `bytes` written to `file`: it must import or throw rt::Error, nothing else (and not crash).
void importOrRefuse(const std::filesystem::path& file, const std::vector<std::uint8_t>& bytes, const std::string& what)
{
    std::ofstream(file, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    try
    {
        readGltf(file);
    }
    catch (const Error&)
    {
    }
    catch (const std::exception& e)
    {
        ADD_FAILURE() << what << ": not an rt::Error: " << e.what();
    }
}

TEST(GltfRobustness, TruncatedAndCorruptedGlbNeverCrash)
{
    ScratchDir dir;
    GltfWriter w;
    const int mat = w.material({{"pbrMetallicRoughness",
                                 {{"baseColorTexture", {{"index", w.texture(w.imageInBuffer(checkerPng(dir)))}}},
                                  {"metallicFactor", 0}}}});
    Primitive p = triangle(mat);
    p.indexType = GltfWriter::kUnsignedShort;
    const int mesh = w.mesh({p, triangle(mat)});
    const int cam = w.perspective(0.7, 1.0);
    w.scene({w.node({{"mesh", mesh}, {"rotation", {0, 0.6, 0, 0.8}}}), w.node({{"camera", cam}, {"translation", {0, 0, 4}}})});
    const std::vector<std::uint8_t> good = w.glbBytes();
    const std::filesystem::path file = dir / "fuzz.glb";
    importOrRefuse(file, good, "the file itself");
    EXPECT_NO_THROW(readGltf(file)) << "the uncorrupted file imports";

    std::mt19937 rng(12);
    for (std::size_t length = 0; length < good.size(); length += 1 + length / 16)
        importOrRefuse(file, std::vector<std::uint8_t>(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(length)),
                       "truncated to " + std::to_string(length));
    for (int trial = 0; trial < 400; ++trial)
    {
        std::vector<std::uint8_t> bytes = good;
        const int flips = 1 + trial % 4;
        for (int f = 0; f < flips; ++f)
            bytes[rng() % bytes.size()] ^= static_cast<std::uint8_t>(1u << (rng() % 8));
        importOrRefuse(file, bytes, "trial " + std::to_string(trial));
    }
}

TEST(GltfRobustness, TruncatedGltfTextNeverCrashes)
{
    ScratchDir dir;
    GltfWriter w;
    oneTriangle(dir, w.material({{"emissiveFactor", {1, 1, 1}}}), w, "whole");
    const std::vector<std::uint8_t> text = GltfWriter::readBytes(dir / "whole.gltf");
    ASSERT_GT(text.size(), 100u);
    for (std::size_t length = 0; length < text.size(); length += 7)
        importOrRefuse(dir / "cut.gltf", std::vector<std::uint8_t>(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(length)),
                       "cut at " + std::to_string(length));
}
} // namespace
} // namespace rt::test
