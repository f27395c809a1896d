// glTF import: each branch of the material mapping (SceneFile/GltfMaterials.h's table), the sky added when
// nothing emits, and base colour images (embedded, data URI, file) with their factor and their samplers' wrapping.
#include <gtest/gtest.h>

#include "Image/ImageIO.h"
#include "SceneFile/GltfImport.h"
#include "SceneFile/GltfMaterials.h"
#include "Support/GltfTestFiles.h"

namespace rt::test
{
namespace
{
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

} // namespace
} // namespace rt::test
