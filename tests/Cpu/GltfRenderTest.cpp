// A glTF scene rendered on the CPU engine: the light where the file's camera must see it, and the whole image
// in agreement (block Z-tests, tests/Support/BlockAgreement.h) with the same scene written by hand in the JSON
// format. A camera looking the wrong way, a node rotation not applied (the light would face up and the room go
// dark), a wrong emission or material mapping: each moves the image far beyond the noise. Metallic-roughness
// textures are fetched as linear data (not sRGB) by the CPU's shading, and render as their factors would.
#include <cstring>
#include <numbers>

#include <gtest/gtest.h>

#include "Engine/CpuEngine.h"
#include "Engine/CpuScene.h"
#include "Integrator/CpuShading.h"
#include "Render/RenderUniforms.h"
#include "RenderTestSupport.h"
#include "SceneFile/GltfImport.h"
#include "Image/ImageIO.h"
#include "SceneFile/JsonSceneReader.h"
#include "SceneFile/JsonSceneWriter.h"
#include "SceneFile/SceneFile.h"
#include "Support/BlockAgreement.h"
#include "Support/GltfWriter.h"
#include "Support/ScratchDir.h"
#include "Support/SmallSettings.h"

namespace rt::test
{
namespace
{
using Primitive = GltfWriter::Primitive;

Primitive quad(const vec3& q, const vec3& u, const vec3& v, int material)
{
    Primitive p;
    p.positions = {q, q + u, q + u + v, q + v};
    p.indices = {0, 1, 2, 0, 2, 3}; // counter-clockwise seen from u x v
    p.indexType = GltfWriter::kUnsignedShort;
    p.material = material;
    return p;
}

/// A floor, a rough metal triangle, a red triangle, and a light panel made facing up and turned to face down by
/// its node; the camera at (0, 1, 4) looking down -z, 60 degrees vertically.
std::filesystem::path writeRoom(const ScratchDir& dir)
{
    GltfWriter w;
    const int grey = w.material({{"pbrMetallicRoughness", {{"baseColorFactor", {0.6, 0.6, 0.6, 1}}, {"metallicFactor", 0}}}});
    const int steel = w.material(
        {{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1}}, {"metallicFactor", 1}, {"roughnessFactor", 0.2}}}});
    const int red = w.material({{"pbrMetallicRoughness", {{"baseColorFactor", {0.7, 0.1, 0.1, 1}}, {"metallicFactor", 0}}}});
    const int lamp = w.material({{"emissiveFactor", {1.0, 0.9, 0.8}},
                                 {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 5}}}}}});
    w.json()["extensionsUsed"] = {"KHR_materials_emissive_strength"};
    const int floor = w.mesh({quad({-3, 0, 3}, {6, 0, 0}, {0, 0, -6}, grey)}, "floor");
    Primitive metal;
    metal.positions = {{-1, 0, -1}, {1, 0, -1}, {0, 1.5f, -1}};
    metal.indices = {0, 1, 2};
    metal.material = steel;
    Primitive tri = metal;
    tri.positions = {{0.5f, 0, 1}, {2, 0, 0}, {1.2f, 1.2f, 0.5f}};
    tri.material = red;
    const int things = w.mesh({metal, tri}, "things");
    const int panel = w.mesh({quad({-0.5f, 0, 0.5f}, {1, 0, 0}, {0, 0, -1}, lamp)}, "panel"); // faces +y
    const int camera = w.perspective(std::numbers::pi / 3.0, 1.0);
    // The panel's node: 180 degrees about +x (quaternion (1, 0, 0, 0)), then up to y = 2.5: it faces -y.
    w.scene({w.node({{"mesh", floor}}), w.node({{"mesh", things}}),
             w.node({{"mesh", panel}, {"rotation", {1, 0, 0, 0}}, {"translation", {0, 2.5, 0}}}),
             w.node({{"camera", camera}, {"translation", {0, 1, 4}}})});
    return w.writeGlb(dir.path(), "room");
}

/// The same room in the JSON format, written from the description above, not from the import.
const char* kRoomJson = R"({
  "camera": {"look_from": [0, 1, 4], "look_at": [0, 1, 3], "vfov": 60},
  "materials": [
    {"name": "grey", "type": "gltf_pbr", "base_color": [0.6, 0.6, 0.6], "metallic": 0},
    {"name": "steel", "type": "gltf_pbr", "base_color": [0.8, 0.8, 0.8], "metallic": 1, "roughness": 0.2},
    {"name": "red", "type": "gltf_pbr", "base_color": [0.7, 0.1, 0.1], "metallic": 0},
    {"name": "lamp", "type": "diffuse_light", "radiance": [5, 4.5, 4]}
  ],
  "shapes": [
    {"type": "quad", "q": [-3, 0, 3], "u": [6, 0, 0], "v": [0, 0, -6], "material": "grey"},
    {"type": "triangle", "p0": [-1, 0, -1], "p1": [1, 0, -1], "p2": [0, 1.5, -1], "material": "steel"},
    {"type": "triangle", "p0": [0.5, 0, 1], "p1": [2, 0, 0], "p2": [1.2, 1.2, 0.5], "material": "red"},
    {"type": "quad", "q": [-0.5, 2.5, -0.5], "u": [1, 0, 0], "v": [0, 0, 1], "material": "lamp"}
  ]
})";

TEST(CpuGltf, TheLightIsWhereTheFilesCameraSeesIt)
{
    ScratchDir dir;
    const Scene scene = readGltf(writeRoom(dir)).scene;
    // Depth 1 sees emitters only: the panel spans rows 8.3 to 13.5 and columns 25 to 39 of a 64 x 64 image.
    const Image image = renderCpu(scene, settingsFor(scene, 64, 4, 1)).image;
    const vec3 panel = image.at(32, 11);
    EXPECT_NEAR(panel.r, 5.0f, 1e-4f);
    EXPECT_NEAR(panel.g, 4.5f, 1e-4f);
    EXPECT_NEAR(panel.b, 4.0f, 1e-4f);
    EXPECT_EQ(image.at(32, 52), vec3(0.0f)) << "the floor emits nothing";
    EXPECT_EQ(image.at(32, 2), vec3(0.0f)) << "above the panel: the black background (the file has a light)";
    EXPECT_EQ(image.at(10, 11), vec3(0.0f)) << "beside the panel";
}

TEST(CpuGltf, RendersAsTheEquivalentJsonScene)
{
    ScratchDir dir;
    const Scene gltf = readGltf(writeRoom(dir)).scene;
    const Scene json = readJsonSceneText(kRoomJson, "room.json");
    cpu::CpuEngine engine(EngineKind::Multi);
    RenderSettings settings = settingsFor(gltf, 48, 64, 8);
    const BlockEstimate a = estimateBlocks(engine, gltf, settings);
    const BlockEstimate b = estimateBlocks(engine, json, settings);
    for (const std::string& f : disagreeingBlocks(a, b, kMaxZ))
        ADD_FAILURE() << "A = glTF, B = JSON: " << f;
    // Not two black images agreeing: the floor under the panel is lit.
    double sum = 0.0;
    for (double m : a.mean)
        sum += m;
    EXPECT_GT(sum / static_cast<double>(a.mean.size()), 0.05);
}
TEST(CpuGltf, ExportedAsJsonItReadsBackBitForBit)
{
    // Images embedded in a .glb and tinted by their base colour factor are no files of their own: --export-scene
    // writes them beside the JSON file, and the copy renders the same image bit for bit.
    ScratchDir dir;
    const std::vector<unsigned char> rgba = {200, 10, 10, 255, 10, 200, 10, 255, 10, 10, 200, 255, 250, 250, 250, 255};
    writePng8(dir / "tex.png", 2, 2, rgba);
    GltfWriter w;
    const int embedded = w.texture(w.imageInBuffer(GltfWriter::readBytes(dir / "tex.png")));
    const int external = w.texture(w.imageFile("tex.png"));
    // A metallic-roughness image in the buffer too: written out, and read back as linear data.
    const std::vector<unsigned char> mr = {0, 40, 255, 255, 0, 230, 0, 255, 0, 128, 128, 255, 0, 255, 60, 255};
    writePng8(dir / "mr.png", 2, 2, mr);
    const int metallicRoughness = w.texture(w.imageInBuffer(GltfWriter::readBytes(dir / "mr.png")));
    const auto textured = [&](int texture, std::vector<double> factor) {
        return w.material({{"pbrMetallicRoughness",
                            {{"baseColorTexture", {{"index", texture}}}, {"baseColorFactor", factor}, {"metallicFactor", 0}}}});
    };
    Primitive a = quad({-2, 0, 0}, {1.5f, 0, 0}, {0, 1.5f, 0}, textured(embedded, {1, 1, 1, 1}));
    a.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    Primitive b = a;
    b.positions = {{0, 0, 0}, {1.5f, 0, 0}, {1.5f, 1.5f, 0}, {0, 1.5f, 0}};
    b.material = w.material({{"pbrMetallicRoughness",
                              {{"baseColorTexture", {{"index", external}}},
                               {"baseColorFactor", {0.5, 1, 0.5, 1}},
                               {"metallicRoughnessTexture", {{"index", metallicRoughness}}},
                               {"roughnessFactor", 0.8}}}});
    const int mesh = w.mesh({a, b});
    w.scene({w.node({{"mesh", mesh}}), w.node({{"camera", w.perspective(1.0, 1.0)}, {"translation", {0, 0.75, 4}}})});
    const Scene original = readGltf(w.writeGlb(dir.path(), "textured")).scene;
    ASSERT_EQ(original.images.size(), 3u);

    exportScene(original, dir / "copy.json");
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "copy.image0.png")) << "the embedded image, written out";
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "copy.image1.png")) << "the tinted file, written out";
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "copy.image2.png")) << "the metallic-roughness image";
    const Scene copy = loadSceneFile(dir / "copy.json");
    ASSERT_EQ(copy.images.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_EQ(copy.images[i].rgba, original.images[i].rgba) << "image " << i;
    EXPECT_NE(original.images[1].rgba, rgba) << "the factor tinted the second";
    EXPECT_EQ(original.images[2].rgba, mr) << "the metallic-roughness texels as the file has them";
    ASSERT_EQ(copy.textures.size(), original.textures.size());
    EXPECT_EQ(std::memcmp(copy.textures.data(), original.textures.data(), sizeof(TextureData) * copy.textures.size()),
              0)
        << "textures, their linear flag included, bit for bit";
    ASSERT_EQ(copy.materials.size(), original.materials.size());
    EXPECT_EQ(
        std::memcmp(copy.materials.data(), original.materials.data(), sizeof(MaterialData) * copy.materials.size()), 0);
    const MaterialData& withMr = original.materials.at(original.groups.at(0).meshes.at(1).material);
    ASSERT_NE(withMr.metallicRoughnessTexture, kNoIndex);
    EXPECT_EQ(copy.textures.at(withMr.metallicRoughnessTexture).linear, 1u);

    RenderSettings s = settingsFor(original, 24, 2, 4);
    s.seed = 5;
    EXPECT_TRUE(bitIdentical(renderCpu(original, s).image, renderCpu(copy, s).image));
}

/// A triangle of a gltf_pbr material whose metallic-roughness texture is the 2 x 2 image `texels` (row 0 on top),
/// the base colour the same image, with the factors given; lit by the sky the import adds.
Scene metallicRoughnessTriangle(const ScratchDir& dir, const std::vector<unsigned char>& texels, double metallicFactor,
                                double roughnessFactor)
{
    writePng8(dir / "mr.png", 2, 2, texels);
    GltfWriter w;
    const int texture = w.texture(w.imageFile("mr.png"));
    const int mat = w.material({{"pbrMetallicRoughness",
                                 {{"baseColorTexture", {{"index", texture}}},
                                  {"metallicRoughnessTexture", {{"index", texture}}},
                                  {"metallicFactor", metallicFactor},
                                  {"roughnessFactor", roughnessFactor}}}});
    Primitive p;
    p.positions = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    p.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    p.uvs = {{0, 1}, {1, 1}, {0.5, 0}};
    p.indices = {0, 1, 2};
    p.material = mat;
    w.scene({w.node({{"mesh", w.mesh({p})}}),
             w.node({{"camera", w.perspective(1.0, 1.0)}, {"translation", {0, 0, 3}}})});
    return readGltf(w.writeGltf(dir.path(), "mr")).scene;
}

TEST(GltfMetallicRoughness, TexelsAreLinearDataInTheCpuShading)
{
    // Texels (r, g, b): g the roughness, b the metallic, as bytes / 255 - not decoded from sRGB, which would make
    // g = 128 a roughness of 0.216 instead of 0.502. The base colour (the same image) is sRGB colour.
    ScratchDir dir;
    const std::vector<unsigned char> texels = {200, 128, 64, 255, 10, 255, 255, 255, 30, 0, 0, 255, 90, 51, 204, 255};
    const Scene scene = metallicRoughnessTriangle(dir, texels, 0.8, 0.5);
    const MaterialData& m = scene.materials.at(scene.groups.at(0).meshes.at(0).material);
    ASSERT_EQ(m.type, MaterialType::GltfPbr);
    ASSERT_EQ(m.alphaX, 0.25f);
    const cpu::CpuScene cs(scene);
    const RenderSettings settings = settingsFor(scene, 8, 1, 4);
    const shader::RenderUniforms uniforms = makeUniforms(scene, scene.camera, settings, 8, 8);
    shader::CpuShading<cpu::PathCode{}> shading(cs, uniforms);
    const auto hitAt = [](vec2 uv) {
        shader::SurfaceHit hit{};
        hit.normal = hit.shadingNormal = vec3(0, 0, 1);
        hit.frontFace = true;
        hit.uv = uv;
        hit.incoming = vec3(0, 0, -1);
        return hit;
    };
    // The nearest texel at (u, v), v up: (0.25, 0.75) is the top-left texel, (0.75, 0.25) the bottom-right.
    const struct
    {
        vec2 uv;
        std::size_t texel;
    } cases[] = {{{0.25f, 0.75f}, 0}, {{0.75f, 0.75f}, 1}, {{0.25f, 0.25f}, 2}, {{0.75f, 0.25f}, 3}};
    for (const auto& c : cases)
    {
        const unsigned char* t = &texels[4 * c.texel];
        const shader::SurfaceHit hit = hitAt(c.uv);
        const vec3 data = shading.evaluateTexture(m.metallicRoughnessTexture, hit.uv, hit.position);
        EXPECT_EQ(data, vec3(t[0], t[1], t[2]) / 255.0f) << "texel " << c.texel;
        const vec3 colour = shading.evaluateTexture(m.albedoTexture, hit.uv, hit.position);
        EXPECT_EQ(colour, vec3(srgb8ToLinear(t[0]), srgb8ToLinear(t[1]), srgb8ToLinear(t[2]))) << "texel " << c.texel;
        const shader::MicrofacetBsdf b = shading.microfacetBsdfAt(m, hit);
        const float g = static_cast<float>(t[1]) / 255.0f;
        const float expectedAlpha = std::max(0.25f * g * g, shader::kMinMicrofacetAlpha);
        EXPECT_EQ(b.gltf.alpha, expectedAlpha) << "texel " << c.texel << ": alpha = alphaX (g / 255)^2";
        EXPECT_EQ(b.gltf.metallic, 0.8f * (static_cast<float>(t[2]) / 255.0f)) << "texel " << c.texel;
        EXPECT_EQ(b.gltf.baseColor, colour) << "texel " << c.texel;
    }
    // The case the issue names, by its number: g = 128 gives alpha = alphaX (128 / 255)^2 = 0.25 x 0.2519646.
    EXPECT_NEAR(shading.microfacetBsdfAt(m, hitAt({0.25f, 0.75f})).gltf.alpha, 0.25f * 0.2519646f, 1e-7f);
}

TEST(CpuGltf, MetallicRoughnessTextureRendersAsItsTexelTimesTheFactorsBitForBit)
{
    // A 1 x 1 metallic-roughness texture renders the image of a material whose factors are the texel times the
    // factors (the same float arithmetic as microfacetBsdfAt's): the texture path, uv and all, reads linear data.
    ScratchDir dir;
    const std::vector<unsigned char> texel = {160, 128, 96, 255};
    const std::vector<unsigned char> texels = {160, 128, 96, 255, 160, 128, 96, 255,
                                               160, 128, 96, 255, 160, 128, 96, 255};
    const Scene textured = metallicRoughnessTriangle(dir, texels, 0.9, 0.7);
    Scene factors = textured;
    MaterialData& m = factors.materials.at(factors.groups.at(0).meshes.at(0).material);
    ASSERT_EQ(m.type, MaterialType::GltfPbr);
    const float g = static_cast<float>(texel[1]) / 255.0f;
    const float b = static_cast<float>(texel[2]) / 255.0f;
    m.alphaX = m.alphaY = m.alphaX * g * g;
    m.metallic = m.metallic * b;
    m.metallicRoughnessTexture = kNoIndex;
    RenderSettings s = settingsFor(textured, 24, 4, 4);
    s.seed = 3;
    const Image a = renderCpu(textured, s).image;
    EXPECT_TRUE(bitIdentical(a, renderCpu(factors, s).image));

    // Decoded as sRGB instead (the flag cleared), the texel would be another roughness and metallic: another image.
    Scene srgb = textured;
    srgb.textures.at(srgb.materials.at(srgb.groups.at(0).meshes.at(0).material).metallicRoughnessTexture).linear = 0;
    EXPECT_FALSE(bitIdentical(a, renderCpu(srgb, s).image)) << "the test can fail";
}
} // namespace
} // namespace rt::test
