// glTF import: each branch of the material mapping (SceneFile/GltfMaterials.h's table), the sky added when
// nothing emits, base colour images (embedded, data URI, file) with their factor and their samplers' wrapping,
// and metallic-roughness images (linear data, untinted).
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

TEST(GltfMaterials, TransmissionAboveHalfIsARoughDielectricWithItsIorAndRoughness)
{
    ScratchDir dir;
    GltfWriter w;
    const int glass = w.material({{"extensions",
                                   {{"KHR_materials_transmission", {{"transmissionFactor", 0.9}}},
                                    {"KHR_materials_ior", {{"ior", 1.33}}}}},
                                  {"pbrMetallicRoughness", {{"metallicFactor", 0}, {"roughnessFactor", 0.3}}}});
    const int plain = w.material({{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1}}}}},
                                  {"pbrMetallicRoughness", {{"metallicFactor", 0}}}});
    const int weak = w.material({{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 0.4}}}}},
                                 {"pbrMetallicRoughness", {{"metallicFactor", 0}}}});
    const int mesh = w.mesh({triangle(glass), triangle(plain), triangle(weak)});
    w.scene({w.node({{"mesh", mesh}})});
    const GltfImport imported = readGltf(w.writeGltf(dir.path(), "glass"));
    const Scene& scene = imported.scene;
    const auto material = [&](int k) { return scene.materials.at(scene.groups.at(0).meshes.at(k).material); };
    ASSERT_EQ(material(0).type, MaterialType::RoughDielectric);
    EXPECT_FLOAT_EQ(material(0).ior, 1.33f);
    EXPECT_EQ(material(0).alphaX, 0.3f * 0.3f) << "alpha = roughnessFactor^2";
    EXPECT_EQ(material(0).alphaY, 0.3f * 0.3f);
    EXPECT_EQ(material(0).fresnel, FresnelModel::Exact);
    ASSERT_EQ(material(1).type, MaterialType::RoughDielectric);
    EXPECT_FLOAT_EQ(material(1).ior, 1.5f) << "KHR_materials_ior's default";
    EXPECT_EQ(material(1).alphaX, 1.0f) << "roughnessFactor's default 1";
    EXPECT_EQ(material(2).type, MaterialType::GltfPbr) << "transmission 0.4 is not glass";
    EXPECT_EQ(material(2).metallic, 0.0f);
    // The two partial ones are rounded, and the notes say which way; KHR_materials_ior is read.
    EXPECT_NE(imported.unmapped.find("partial transmission (0.9 of the light: clear glass)"), std::string::npos)
        << imported.unmapped;
    EXPECT_NE(imported.unmapped.find("partial transmission (0.4 of the light: opaque)"), std::string::npos)
        << imported.unmapped;
    EXPECT_EQ(imported.unmapped.find("KHR_materials"), std::string::npos) << imported.unmapped;
}

TEST(GltfMaterials, MetalsDoNotTransmit)
{
    // KHR_materials_transmission weighs the dielectric BRDF only: with metallicFactor's default 1 a fully
    // transmissive material is a metal, and at metallic 0.6 only 0.4 of the light is transmitted.
    ScratchDir dir;
    GltfWriter w;
    const int metal = w.material({{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1}}}}},
                                  {"pbrMetallicRoughness", {{"roughnessFactor", 0.2}}}});
    const int mostlyMetal =
        w.material({{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1}}}}},
                    {"pbrMetallicRoughness", {{"metallicFactor", 0.6}}}});
    const int mesh = w.mesh({triangle(metal), triangle(mostlyMetal)});
    w.scene({w.node({{"mesh", mesh}})});
    const GltfImport imported = readGltf(w.writeGltf(dir.path(), "metal"));
    const Scene& scene = imported.scene;
    const auto material = [&](int k) { return scene.materials.at(scene.groups.at(0).meshes.at(k).material); };
    ASSERT_EQ(material(0).type, MaterialType::GltfPbr);
    EXPECT_EQ(material(0).metallic, 1.0f);
    EXPECT_FLOAT_EQ(material(0).alphaX, 0.2f * 0.2f);
    ASSERT_EQ(material(1).type, MaterialType::GltfPbr);
    EXPECT_FLOAT_EQ(material(1).metallic, 0.6f);
    EXPECT_NE(imported.unmapped.find("partial transmission (0.4 of the light: opaque)"), std::string::npos)
        << imported.unmapped;
}

TEST(GltfMaterials, MetallicRoughnessFactorsAreGltfPbrsOwn)
{
    ScratchDir dir;
    GltfWriter w;
    const int mat = w.material(
        {{"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 0.8, 0.7, 1}}, {"metallicFactor", 0.5}, {"roughnessFactor", 0.3}}}});
    const Scene scene = readGltf(oneTriangle(dir, mat, w)).scene;
    const MaterialData& m = onlyMaterial(scene);
    ASSERT_EQ(m.type, MaterialType::GltfPbr);
    EXPECT_EQ(m.metallic, 0.5f);
    EXPECT_EQ(m.alphaX, 0.3f * 0.3f) << "alpha = roughnessFactor^2 (glTF 2.0 Appendix B)";
    EXPECT_EQ(m.alphaY, 0.3f * 0.3f);
    EXPECT_EQ(m.ior, 1.5f) << "the dielectric's ior without KHR_materials_ior";
    EXPECT_EQ(m.metallicRoughnessTexture, kNoIndex);
    EXPECT_EQ(m.fuzz, 0.0f) << "no fuzz: the metal of the books is gone";
    expectNear(solidColor(scene, m.albedoTexture), {0.9f, 0.8f, 0.7f});
}

TEST(GltfMaterials, EveryMetallicFactorIsKeptNotThresholded)
{
    ScratchDir dir;
    GltfWriter w;
    const int mat = w.material({{"pbrMetallicRoughness",
                                 {{"baseColorFactor", {0.2, 0.4, 0.6, 1}},
                                  {"metallicFactor", 0.49},
                                  {"roughnessFactor", 0}}}});
    const Scene scene = readGltf(oneTriangle(dir, mat, w)).scene;
    const MaterialData& m = onlyMaterial(scene);
    ASSERT_EQ(m.type, MaterialType::GltfPbr);
    EXPECT_EQ(m.metallic, 0.49f);
    EXPECT_EQ(m.alphaX, 0.0f) << "a smooth surface (the BSDF raises alpha to kMinMicrofacetAlpha)";
    expectNear(solidColor(scene, m.albedoTexture), {0.2f, 0.4f, 0.6f});
}

TEST(GltfMaterials, SpecDefaultsAreWhiteRoughMetal)
{
    ScratchDir dir;
    GltfWriter w;
    const int mat = w.material({{"name", "bare"}}); // metallicFactor and roughnessFactor default to 1 (§3.9.2)
    const Scene scene = readGltf(oneTriangle(dir, mat, w)).scene;
    const MaterialData& m = onlyMaterial(scene);
    ASSERT_EQ(m.type, MaterialType::GltfPbr);
    EXPECT_EQ(m.metallic, 1.0f);
    EXPECT_EQ(m.alphaX, 1.0f);
    EXPECT_EQ(m.ior, 1.5f);
    expectNear(solidColor(scene, m.albedoTexture), {1, 1, 1});
}

TEST(GltfMaterials, KhrMaterialsIorIsTheDielectricsIor)
{
    ScratchDir dir;
    GltfWriter w;
    const int mat = w.material({{"extensions", {{"KHR_materials_ior", {{"ior", 2.4}}}}},
                                {"pbrMetallicRoughness", {{"metallicFactor", 0.25}}}});
    w.json()["extensionsUsed"] = {"KHR_materials_ior"};
    const GltfImport imported = readGltf(oneTriangle(dir, mat, w));
    const MaterialData& m = onlyMaterial(imported.scene);
    ASSERT_EQ(m.type, MaterialType::GltfPbr);
    EXPECT_EQ(m.ior, 2.4f);
    EXPECT_EQ(imported.unmapped, "");

    GltfWriter low;
    const int bad = low.material({{"extensions", {{"KHR_materials_ior", {{"ior", 0.5}}}}}});
    const std::string e = errorOf(oneTriangle(dir, bad, low, "low"));
    EXPECT_NE(e.find("/materials/0/extensions/KHR_materials_ior/ior: expected a number in [1, 100], got 0.5"),
              std::string::npos)
        << e;
}

TEST(GltfMaterials, RoughnessOutOfRangeIsRefusedForGlassToo)
{
    ScratchDir dir;
    GltfWriter w;
    const int mat = w.material({{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1}}}}},
                                {"pbrMetallicRoughness", {{"metallicFactor", 0}, {"roughnessFactor", 1.5}}}});
    const std::string e = errorOf(oneTriangle(dir, mat, w));
    EXPECT_NE(e.find("/materials/0/pbrMetallicRoughness/roughnessFactor: expected a number in [0, 1], got 1.5"),
              std::string::npos)
        << e;
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
    EXPECT_EQ(m.type, MaterialType::GltfPbr);
    EXPECT_EQ(m.metallic, 1.0f);
    ASSERT_EQ(scene.textures.at(m.albedoTexture).type, TextureType::Image);
    EXPECT_EQ(scene.textures.at(m.albedoTexture).linear, 0u) << "base colour is sRGB colour";
}

TEST(GltfTextures, MetallicRoughnessTextureIsLinearDataUntintedBesideTheFactors)
{
    // One image as base colour (tinted, sRGB) and as metallic-roughness texture (its texels as they are, linear).
    ScratchDir dir;
    GltfWriter w;
    const std::vector<unsigned char> texel = {200, 128, 64, 255};
    const int texture = w.texture(w.imageDataUri(texelPng(dir, texel)));
    const int mat = w.material({{"pbrMetallicRoughness",
                                 {{"baseColorTexture", {{"index", texture}}},
                                  {"baseColorFactor", {0.5, 0.5, 0.5, 1}},
                                  {"metallicRoughnessTexture", {{"index", texture}}},
                                  {"metallicFactor", 0.8},
                                  {"roughnessFactor", 0.5}}}});
    const int again = w.material({{"pbrMetallicRoughness",
                                   {{"metallicRoughnessTexture", {{"index", texture}}}, {"metallicFactor", 0.1}}}});
    const int mesh = w.mesh({triangle(mat), triangle(again)});
    w.scene({w.node({{"mesh", mesh}})});
    const GltfImport imported = readGltf(w.writeGltf(dir.path(), "mr"));
    const Scene& scene = imported.scene;
    const MaterialData& m = scene.materials.at(scene.groups.at(0).meshes.at(0).material);
    ASSERT_EQ(m.type, MaterialType::GltfPbr);
    EXPECT_EQ(m.metallic, 0.8f) << "the factors stay the material's";
    EXPECT_EQ(m.alphaX, 0.25f);
    ASSERT_NE(m.metallicRoughnessTexture, kNoIndex);
    const TextureData& mr = scene.textures.at(m.metallicRoughnessTexture);
    ASSERT_EQ(mr.type, TextureType::Image);
    EXPECT_EQ(mr.linear, 1u);
    EXPECT_EQ(scene.images.at(mr.image).rgba, texel) << "not tinted by the base colour factor";
    const TextureData& base = scene.textures.at(m.albedoTexture);
    EXPECT_EQ(base.linear, 0u);
    EXPECT_NE(base.image, mr.image);
    EXPECT_EQ(scene.images.at(base.image).rgba[0], linearToSrgb8(srgb8ToLinear(200) * 0.5f)) << "the base colour is";
    const MaterialData& n = scene.materials.at(scene.groups.at(0).meshes.at(1).material);
    EXPECT_EQ(n.metallicRoughnessTexture, m.metallicRoughnessTexture) << "one texture per image";
    EXPECT_EQ(n.metallic, 0.1f);
    EXPECT_EQ(imported.unmapped.find("metallic-roughness"), std::string::npos) << imported.unmapped;
    EXPECT_NO_THROW(imported.scene.validate());
}

TEST(GltfTextures, MetallicRoughnessTextureOnAnotherTexcoordIsNotedAndLeftOut)
{
    ScratchDir dir;
    GltfWriter w;
    const int texture = w.texture(w.imageDataUri(texelPng(dir, {0, 128, 64, 255})));
    const int mat = w.material({{"name", "Other"},
                                {"pbrMetallicRoughness",
                                 {{"metallicRoughnessTexture", {{"index", texture}, {"texCoord", 1}}},
                                  {"metallicFactor", 0.3}}}});
    const GltfImport imported = readGltf(oneTriangle(dir, mat, w));
    const MaterialData& m = onlyMaterial(imported.scene);
    ASSERT_EQ(m.type, MaterialType::GltfPbr);
    EXPECT_EQ(m.metallicRoughnessTexture, kNoIndex);
    EXPECT_EQ(m.metallic, 0.3f);
    EXPECT_NE(imported.unmapped.find(
                  "metallic-roughness textures on TEXCOORD_1 (the factors alone) (material 'Other')"),
              std::string::npos)
        << imported.unmapped;
}

TEST(GltfTextures, MetallicRoughnessTextureThatDoesNotExistIsRefused)
{
    ScratchDir dir;
    GltfWriter w;
    w.texture(w.imageDataUri(texelPng(dir, {0, 128, 64, 255})));
    const int mat = w.material({{"pbrMetallicRoughness", {{"metallicRoughnessTexture", {{"index", 4}}}}}});
    const std::string e = errorOf(oneTriangle(dir, mat, w));
    EXPECT_NE(e.find("/materials/0/pbrMetallicRoughness/metallicRoughnessTexture/index: texture 4 does not exist (the "
                     "file has 1)"),
              std::string::npos)
        << e;
}

TEST(GltfTextures, MetallicRoughnessTextureOfGlassIsNoted)
{
    ScratchDir dir;
    GltfWriter w;
    const int texture = w.texture(w.imageDataUri(texelPng(dir, {0, 128, 64, 255})));
    const int mat = w.material({{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1}}}}},
                                {"pbrMetallicRoughness",
                                 {{"metallicFactor", 0}, {"metallicRoughnessTexture", {{"index", texture}}}}}});
    const GltfImport imported = readGltf(oneTriangle(dir, mat, w));
    EXPECT_EQ(onlyMaterial(imported.scene).type, MaterialType::RoughDielectric);
    EXPECT_NE(imported.unmapped.find("metallic-roughness textures of transmissive materials"), std::string::npos)
        << imported.unmapped;
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

TEST(GltfTextures, MetallicRoughnessSamplersWrapTooAndTheBaseColoursWins)
{
    ScratchDir dir;
    GltfWriter w;
    const int image = w.imageDataUri(texelPng(dir, {0, 128, 64, 255}));
    w.json()["samplers"].push_back({{"wrapS", 33648}, {"wrapT", 10497}}); // MIRRORED_REPEAT, REPEAT
    w.json()["samplers"].push_back({{"wrapS", 33071}, {"wrapT", 33071}}); // CLAMP_TO_EDGE
    const int mirrored = w.texture(image);
    w.json()["textures"][mirrored]["sampler"] = 0;
    const int clamped = w.texture(w.imageDataUri(checkerPng(dir)));
    w.json()["textures"][clamped]["sampler"] = 1;
    // Only a metallic-roughness texture: its sampler wraps the coordinates.
    const int alone = w.material({{"pbrMetallicRoughness", {{"metallicRoughnessTexture", {{"index", mirrored}}}}}});
    // Both: the base colour's sampler (clamp) wins, and the difference is noted.
    const int both = w.material({{"name", "Both"},
                                 {"pbrMetallicRoughness",
                                  {{"baseColorTexture", {{"index", clamped}}},
                                   {"metallicRoughnessTexture", {{"index", mirrored}}}}}});
    Primitive a = triangle(alone);
    a.uvs = {{5.25, 2.5}, {6, 2.5}, {5, 3}};
    Primitive b = a;
    b.material = both;
    const int mesh = w.mesh({a, b});
    w.scene({w.node({{"mesh", mesh}})});
    const GltfImport imported = readGltf(w.writeGltf(dir.path(), "mrwrap"));
    const MeshData& moved = imported.scene.meshes.at(0);
    // s in [5, 6]: period 5, odd, mirrored (s -> 6 - s); t in [2, 3] -> t - 2; the mesh holds (s, 1 - t).
    EXPECT_NEAR(moved.uvs.at(moved.indices.at(0)).x, 0.75f, 1e-6f);
    EXPECT_NEAR(moved.uvs.at(moved.indices.at(0)).y, 0.5f, 1e-6f);
    EXPECT_NEAR(moved.uvs.at(moved.indices.at(2)).x, 1.0f, 1e-6f);
    EXPECT_NEAR(moved.uvs.at(moved.indices.at(2)).y, 0.0f, 1e-6f);
    const MeshData& kept = imported.scene.meshes.at(1);
    EXPECT_EQ(kept.uvs.at(kept.indices.at(0)), vec2(5.25f, -1.5f)) << "clamped as the base colour's sampler says";
    EXPECT_NE(imported.unmapped.find("metallic-roughness textures wrapping unlike their base colour (wrapped as "
                                     "the base colour) (material 'Both')"),
              std::string::npos)
        << imported.unmapped;
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
