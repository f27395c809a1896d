// A glTF scene rendered on the CPU engine: the light where the file's camera must see it, and the whole image
// in agreement (block Z-tests, tests/Support/BlockAgreement.h) with the same scene written by hand in the JSON
// format. A camera looking the wrong way, a node rotation not applied (the light would face up and the room go
// dark), a wrong emission or albedo mapping: each moves the image far beyond the noise.
#include <numbers>

#include <gtest/gtest.h>

#include "Engine/CpuEngine.h"
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

/// A floor, a fuzzy metal triangle, a red triangle, and a light panel made facing up and turned to face down by
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
    {"name": "grey", "type": "lambertian", "albedo": [0.6, 0.6, 0.6]},
    {"name": "steel", "type": "metal", "albedo": [0.8, 0.8, 0.8], "fuzz": 0.2},
    {"name": "red", "type": "lambertian", "albedo": [0.7, 0.1, 0.1]},
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
    const auto textured = [&](int texture, std::vector<double> factor) {
        return w.material({{"pbrMetallicRoughness",
                            {{"baseColorTexture", {{"index", texture}}}, {"baseColorFactor", factor}, {"metallicFactor", 0}}}});
    };
    Primitive a = quad({-2, 0, 0}, {1.5f, 0, 0}, {0, 1.5f, 0}, textured(embedded, {1, 1, 1, 1}));
    a.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    Primitive b = a;
    b.positions = {{0, 0, 0}, {1.5f, 0, 0}, {1.5f, 1.5f, 0}, {0, 1.5f, 0}};
    b.material = textured(external, {0.5, 1, 0.5, 1});
    const int mesh = w.mesh({a, b});
    w.scene({w.node({{"mesh", mesh}}), w.node({{"camera", w.perspective(1.0, 1.0)}, {"translation", {0, 0.75, 4}}})});
    const Scene original = readGltf(w.writeGlb(dir.path(), "textured")).scene;
    ASSERT_EQ(original.images.size(), 2u);

    exportScene(original, dir / "copy.json");
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "copy.image0.png")) << "the embedded image, written out";
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "copy.image1.png")) << "the tinted file, written out";
    const Scene copy = loadSceneFile(dir / "copy.json");
    ASSERT_EQ(copy.images.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i)
        EXPECT_EQ(copy.images[i].rgba, original.images[i].rgba) << "image " << i;
    EXPECT_NE(original.images[1].rgba, rgba) << "the factor tinted the second";

    RenderSettings s = settingsFor(original, 24, 2, 4);
    s.seed = 5;
    EXPECT_TRUE(bitIdentical(renderCpu(original, s).image, renderCpu(copy, s).image));
}
} // namespace
} // namespace rt::test
