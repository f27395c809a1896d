// SceneFile/: the JSON scene format's reader (values, references, transforms, errors with their location),
// the writer's exact floats, and the reader's robustness against truncated and corrupted files.
#include <cmath>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "Error.h"
#include "SceneFile/JsonSceneReader.h"
#include "SceneFile/JsonSceneWriter.h"
#include "SceneFile/SceneFile.h"
#include "Support/ScratchDir.h"

namespace rt
{
namespace
{
/// A small scene in every part of the format that needs no file beside it.
const char* kSmallScene = R"({
  "format": "ray-tracing-scene",
  "version": 1,
  "camera": {"look_from": [0, 1, 5], "look_at": [0, 1, 0], "vfov": 40, "defocus_angle": 0.5, "focus_distance": 5,
             "shutter": [0, 0.5]},
  "render": {"spp": 16, "depth": 8, "width": 64, "aspect": 2, "unidirectional_light": false, "estimator": "nee",
             "sampling": "stratified"},
  "background": {"type": "constant", "color": [0.1, 0.2, 0.3]},
  "textures": [{"name": "check", "type": "checker", "scale": 0.25, "even": [1, 1, 1], "odd": [0, 0, 0]}],
  "materials": [
    {"name": "floor", "type": "lambertian", "albedo_texture": "check"},
    {"name": "red", "type": "lambertian", "albedo": [0.7, 0.1, 0.1]},
    {"name": "lamp", "type": "diffuse_light", "radiance": [4, 4, 4]},
    {"name": "mirror", "type": "metal", "albedo": [0.9, 0.9, 0.9], "fuzz": 0.2},
    {"name": "smoke", "type": "isotropic", "albedo": [0.5, 0.5, 0.5]}
  ],
  "meshes": [{"name": "tri", "positions": [0, 0, 0, 1, 0, 0, 0, 1, 0], "indices": [0, 1, 2]}],
  "shapes": [
    {"type": "quad", "q": [-5, 0, 5], "u": [10, 0, 0], "v": [0, 0, -10], "material": "floor"},
    {"type": "sphere", "center": [0, 1, 0], "radius": 0.5, "material": 1},
    {"type": "moving_sphere", "center0": [2, 1, 0], "center1": [2, 2, 0], "radius": 0.25, "material": "red"},
    {"type": "triangle", "p0": [-1, 3, 0], "p1": [1, 3, 0], "p2": [0, 3, 1], "material": "lamp"},
    {"type": "triangle", "p0": [-1, 3, 2], "p1": [1, 3, 2], "p2": [0, 3, 3], "material": "lamp"},
    {"type": "constant_medium", "boundary": "box", "min": [-3, 0, -3], "max": [-2, 1, -2], "density": 0.5,
     "material": "smoke"}
  ],
  "groups": [{"name": "blocks", "shapes": [
    {"type": "box", "min": [0, 0, 0], "max": [1, 2, 1], "material": "mirror"},
    {"type": "mesh", "mesh": "tri", "material": "red"}
  ]}],
  "instances": [{"group": "blocks", "transform": [{"translate": [10, 0, 0]}, {"rotate_y": 90}, {"scale": 2}]}],
  "light_targets": [{"type": "sphere", "center": [0, 1, 0], "radius": 0.5}]
})";

Scene readText(const std::string& text) { return readJsonSceneText(text, "test.json"); }

/// The message of the rt::Error that reading `text` throws ("" if it reads).
std::string errorOf(const std::string& text)
{
    try
    {
        readText(text);
    }
    catch (const Error& e)
    {
        return e.what();
    }
    return "";
}

/// `text` with the first occurrence of `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to)
{
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

std::string smallSceneWith(const std::string& from, const std::string& to) { return replaced(kSmallScene, from, to); }
TEST(JsonSceneReader, AnIndexCountsInTheFilesListAsTheSameReferenceByName)
{
    // Top-level shapes make the scene's "world" group first, so the file's groups are the scene's 1 and 2: the
    // index 1 took the scene's group 1 (the file's group 0) while the name "b" took the file's group 1.
    const std::string doc = R"({"materials": [{"name": "lamp", "type": "diffuse_light", "radiance": [4, 4, 4]}],
        "shapes": [{"type": "sphere", "center": [0, 5, 0], "radius": 1, "material": 0}],
        "groups": [{"name": "a", "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": 0}]},
                   {"name": "b", "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 2, "material": 0}]}],
        "instances": [{"group": 1}, {"group": "b"}, {"group": 0}, {"group": "a"}]})";
    const Scene s = readText(doc);
    ASSERT_GE(s.instances.size(), 4u);
    const auto groupOf = [&s](std::size_t k) { return s.instances[s.instances.size() - 4 + k].group; };
    EXPECT_EQ(groupOf(0), groupOf(1));
    EXPECT_EQ(groupOf(2), groupOf(3));
    EXPECT_NE(groupOf(0), groupOf(2));
    EXPECT_EQ(s.groups[groupOf(1)].name, "b");
    const std::string e = errorOf(replaced(doc, R"({"group": 0}, {"group": "a"})", R"({"group": 2})"));
    EXPECT_NE(e.find("/instances/2/group"), std::string::npos) << "the file has two groups: " << e;
}
} // namespace

TEST(SceneFile, ReadsEveryPartOfTheSmallScene)
{
    const Scene s = readText(kSmallScene);
    EXPECT_EQ(s.id, "test.json");
    EXPECT_EQ(s.camera.lookFrom, vec3(0, 1, 5));
    EXPECT_FLOAT_EQ(s.camera.vfovDegrees, 40.0f);
    EXPECT_FLOAT_EQ(s.camera.defocusAngleDegrees, 0.5f);
    EXPECT_FLOAT_EQ(s.camera.shutterClose, 0.5f);
    EXPECT_EQ(s.defaults.spp, 16);
    EXPECT_EQ(s.defaults.depth, 8);
    EXPECT_FLOAT_EQ(s.defaults.aspect, 2.0f);
    EXPECT_FALSE(s.defaults.unidirectionalLight);
    EXPECT_EQ(s.defaults.estimator, Estimator::Nee);
    EXPECT_EQ(s.defaults.sampling, PixelSampling::Stratified);
    EXPECT_EQ(s.background.color0, vec3(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(s.background.color1, s.background.color0);
    // The world group ("shapes") comes first and is placed once with the identity; "blocks" after it.
    ASSERT_EQ(s.groups.size(), 2u);
    ASSERT_EQ(s.instances.size(), 2u);
    EXPECT_TRUE(s.instances[0].worldFromObject.isIdentity());
    const GroupDesc& world = s.groups[s.instances[0].group];
    EXPECT_EQ(world.spheres.size(), 2u);
    EXPECT_TRUE(world.spheres[1].moving());
    EXPECT_EQ(world.quads.size(), 1u);
    EXPECT_EQ(world.media.size(), 1u);
    EXPECT_EQ(s.materials[world.spheres[0].material].type, MaterialType::Lambertian); // by index: "red"
    // The two triangles of the world become one mesh with a material per triangle.
    ASSERT_EQ(world.meshes.size(), 1u);
    const MeshData& tris = s.meshes[world.meshes[0].mesh];
    EXPECT_EQ(tris.triangleCount(), 2u);
    EXPECT_EQ(tris.triangleMaterials.size(), 2u);
    // The box is six quads; the checker kept its scale.
    EXPECT_EQ(s.groups[1].quads.size(), 6u);
    EXPECT_FLOAT_EQ(s.textures[0].scale, 0.25f);
    EXPECT_FLOAT_EQ(s.materials[3].fuzz, 0.2f);
    // Lights: the two emitting triangles, then the sphere target.
    ASSERT_EQ(s.lights.size(), 3u);
    EXPECT_EQ(s.emitterCount(), 2u);
    EXPECT_EQ(s.lightSources[2].kind, LightSource::Kind::Target);
    EXPECT_FLOAT_EQ(s.lights[0].area + s.lights[1].area, 2.0f); // two triangles of area 1
}

TEST(SceneFile, InstanceStepsMultiplyInTheOrderWritten)
{
    // translate * rotate_y(90) * scale(2): the object point (1, 0, 0) scales to (2, 0, 0), rotates to
    // (0, 0, -2), then moves to (10, 0, -2).
    const Scene s = readText(kSmallScene);
    const vec3 p = s.instances[1].worldFromObject.point({1, 0, 0});
    EXPECT_NEAR(p.x, 10.0f, 1e-5f);
    EXPECT_NEAR(p.y, 0.0f, 1e-5f);
    EXPECT_NEAR(p.z, -2.0f, 1e-5f);
}

TEST(SceneFile, ErrorsNameTheValueAndWhatWasExpected)
{
    struct Case
    {
        std::string text;
        std::string expected; // a part of the message
    };
    const std::vector<Case> cases = {
        {smallSceneWith("\"radius\": 0.5, \"material\": 1", "\"radius\": -0.5, \"material\": 1"),
         "test.json: /shapes/1/radius: expected a number in [0"},
        {smallSceneWith("\"u\": [10, 0, 0]", "\"u\": [0, 0, 0]"), "/shapes/0: the quad has zero area"},
        {smallSceneWith("\"vfov\": 40", "\"vfov\": \"wide\""), "/camera/vfov: expected a number, got \"wide\""},
        {smallSceneWith("\"fuzz\": 0.2", "\"fuzzz\": 0.2"), "/materials/3: unknown key 'fuzzz'"},
        {smallSceneWith("\"material\": \"red\"}", "\"material\": \"blue\"}"), "no material is named 'blue'"},
        {smallSceneWith("\"material\": 1}", "\"material\": 7}"), "/shapes/1/material: expected an integer in [0, 4]"},
        {smallSceneWith("\"version\": 1", "\"version\": 2"), "/version: expected an integer in [1, 1]"},
        {smallSceneWith("\"indices\": [0, 1, 2]", "\"indices\": [0, 1, 3]"), "/meshes/0/indices/2"},
        {replaced(smallSceneWith("{\"scale\": 2}", "{\"scale\": [1, 2, 1]}"), "\"material\": \"mirror\"}",
                  "\"material\": \"mirror\"}, {\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, \"material\": 0}"),
         "/instances/0/transform: the group has spheres"},
        {smallSceneWith("{\"scale\": 2}", "{\"scale\": [2, -2, 2]}"), "/instances/0/transform: the transform mirrors"},
        {smallSceneWith("\"depth\": 8", "\"depth\": 8.5"), "/render/depth: expected an integer"},
        {smallSceneWith("\"estimator\": \"nee\"", "\"estimator\": \"path\""), "expected one of 'bsdf', 'mixture'"},
        {smallSceneWith("\"sampling\": \"stratified\"", "\"sampling\": \"halton\""), "expected one of 'random', 'stratified'"},
        {smallSceneWith("\"name\": \"red\"", "\"name\": \"floor\""),
         "/shapes/0/material: more than one material is named 'floor': refer to it by its index"},
        {smallSceneWith("\"density\": 0.5,", "\"density\": 0.5, \"albedo\": [1, 1, 1],"), "one of the two"},
        {smallSceneWith("\"look_at\": [0, 1, 0]", "\"look_at\": [0, 1, 5]"), "looks at its own position"},
        {"{\"shapes\": []}", "the scene has nothing to render"},
        {"[1, 2]", "/: expected an object"},
    };
    for (const Case& c : cases)
    {
        const std::string message = errorOf(c.text);
        EXPECT_NE(message.find(c.expected), std::string::npos) << "expected '" << c.expected << "' in: " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
    }
}

TEST(SceneFile, SyntaxErrorsGiveLineAndColumn)
{
    const std::string message = errorOf("{\n  \"camera\": {\n    \"vfov\": 40,,\n  }\n}\n");
    EXPECT_EQ(message.rfind("test.json:3:16: ", 0), 0u) << message;
}

TEST(SceneFile, MissingFilesAreNamedWithTheirPointer)
{
    test::ScratchDir dir;
    const auto file = dir.write("scene.json", smallSceneWith(R"("textures": [)",
                                                              R"("textures": [{"type": "image", "path": "nope.png"}, )"));
    try
    {
        loadSceneFile(file);
        FAIL() << "a missing texture must stop the read";
    }
    catch (const SceneError& e)
    {
        EXPECT_NE(std::string(e.what()).find("/textures/0/path: texture 'nope.png' not found"), std::string::npos)
            << e.what();
    }
    EXPECT_THROW(loadSceneFile(dir / "absent.json"), SceneError);
}

TEST(SceneFile, ObjMeshesLoadFittedOrAsWritten)
{
    test::ScratchDir dir;
    dir.write("tri.obj", "v 10 20 30\nv 14 20 30\nv 10 22 30\nf 1 2 3\n");
    const auto scene = [&](const std::string& fit) {
        return loadSceneFile(dir.write("s.json", R"({"materials": [{"type": "lambertian", "albedo": [1, 1, 1]}],
            "meshes": [{"obj": "tri.obj")" + fit + R"(}], "shapes": [{"type": "mesh", "mesh": 0, "material": 0}]})"));
    };
    const Scene asWritten = scene(", \"fit\": false");
    EXPECT_EQ(asWritten.meshes[0].positions[1], vec3(14, 20, 30));
    const Scene fitted = scene("");
    EXPECT_FLOAT_EQ(fitted.meshes[0].bounds().max.y - fitted.meshes[0].bounds().min.y, 1.0f); // fit height 1
}

TEST(SceneFile, ExactFloatsReadBackBitForBit)
{
    EXPECT_EQ(nlohmann::json(exactFloat(0.73f)).dump(), "0.73");
    std::mt19937 rng(7);
    for (int i = 0; i < 200000; ++i)
    {
        std::uint32_t bits = rng();
        float f;
        std::memcpy(&f, &bits, sizeof f);
        if (!std::isfinite(f))
            continue;
        const std::string text = nlohmann::json(exactFloat(f)).dump();
        const float back = static_cast<float>(nlohmann::json::parse(text).get<double>());
        ASSERT_EQ(std::memcmp(&back, &f, sizeof f), 0) << text;
    }
}

// Every truncation of a valid file and a few thousand random byte flips: the reader either builds a
// scene or throws an rt::Error; any other exception, a crash or a hang fails.
TEST(SceneFile, SurvivesTruncationsAndByteFlips)
{
    const std::string text = kSmallScene;
    const auto survives = [](const std::string& t) {
        try
        {
            readText(t);
        }
        catch (const Error&)
        {
        }
        catch (const std::exception& e)
        {
            ADD_FAILURE() << "not an rt::Error: " << e.what() << "\nfor:\n" << t;
            return false;
        }
        return true;
    };
    for (std::size_t n = 0; n < text.size(); ++n)
        ASSERT_TRUE(survives(text.substr(0, n))) << "truncated at " << n;
    std::mt19937 rng(11);
    int built = 0;
    for (int i = 0; i < 3000; ++i)
    {
        std::string t = text;
        for (int flips = 1 + static_cast<int>(rng() % 3); flips > 0; --flips)
            t[rng() % t.size()] = static_cast<char>(rng() % 256);
        ASSERT_TRUE(survives(t));
        built += errorOf(t).empty() ? 1 : 0;
    }
    EXPECT_GT(built, 0) << "some flips (inside a number, say) leave a valid scene";
}
} // namespace rt

namespace rt
{
TEST(SceneFile, DielectricsTakeTheirFresnelModel)
{
    const std::string doc = R"({"materials": [{"type": "dielectric", "ior": 1.5, "fresnel": "exact"},
        {"type": "dielectric", "ior": 1.33}], "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
        "material": 0}]})";
    const Scene s = readText(doc);
    EXPECT_EQ(s.materials[0].fresnel, shader::FresnelModel::Exact);
    EXPECT_EQ(s.materials[1].fresnel, shader::FresnelModel::Schlick) << "the books' model by default";
    EXPECT_NE(errorOf(replaced(doc, "\"exact\"", "\"fast\"")).find("/materials/0/fresnel: expected one of"),
              std::string::npos);
}
TEST(SceneFile, MicrofacetMaterialsTakeAlphaOrGltfRoughness)
{
    const std::string doc = R"({"materials": [
        {"type": "conductor", "alpha": [0.1, 0.3], "eta": [0.2, 0.9, 1.1], "k": [3.9, 2.4, 2.2]},
        {"type": "conductor", "roughness": 0.5, "f0": [0.9, 0.6, 0.3]},
        {"type": "rough_dielectric", "alpha": 0.05, "ior": 1.5},
        {"type": "gltf_pbr", "base_color": [0.73, 0.73, 0.73], "metallic": 0.25, "roughness": 0.3},
        {"type": "gltf_pbr"}],
        "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": 0}]})";
    const Scene s = readText(doc);
    ASSERT_EQ(s.materials.size(), 5u);
    const MaterialData& exact = s.materials[0];
    EXPECT_EQ(exact.type, MaterialType::Conductor);
    EXPECT_EQ(exact.fresnel, FresnelModel::Exact);
    EXPECT_EQ(exact.alphaX, 0.1f);
    EXPECT_EQ(exact.alphaY, 0.3f);
    EXPECT_EQ(exact.eta, vec3(0.2f, 0.9f, 1.1f));
    EXPECT_EQ(exact.k, vec3(3.9f, 2.4f, 2.2f));
    const MaterialData& schlick = s.materials[1];
    EXPECT_EQ(schlick.fresnel, FresnelModel::Schlick);
    EXPECT_EQ(schlick.alphaX, 0.25f) << "roughness as glTF maps it: alpha = roughness^2";
    EXPECT_EQ(s.textures[schlick.albedoTexture].color0, vec3(0.9f, 0.6f, 0.3f));
    EXPECT_EQ(s.materials[2].type, MaterialType::RoughDielectric);
    EXPECT_EQ(s.materials[2].ior, 1.5f);
    const MaterialData& gltf = s.materials[3];
    EXPECT_EQ(gltf.type, MaterialType::GltfPbr);
    EXPECT_EQ(gltf.metallic, 0.25f);
    EXPECT_EQ(gltf.alphaX, 0.3f * 0.3f);
    EXPECT_EQ(gltf.ior, 1.5f) << "glTF's default ior";
    EXPECT_EQ(gltf.metallicRoughnessTexture, kNoIndex);
    EXPECT_EQ(s.materials[4].metallic, 1.0f) << "glTF's defaults: metallic 1, roughness 1";
    EXPECT_EQ(s.materials[4].alphaX, 1.0f);

    const std::vector<std::pair<std::string, std::string>> bad = {
        {replaced(doc, "\"alpha\": [0.1, 0.3]", "\"alpha\": 0.1, \"roughness\": 0.3"), "one of them"},
        {replaced(doc, "\"alpha\": [0.1, 0.3]", "\"alpha\": [0.1, 1.3]"), "/materials/0/alpha/1: expected a number in [0, 1]"},
        {replaced(doc, "\"roughness\": 0.5, \"f0\"", "\"roughness\": 0.5, \"eta\": [1, 1, 1], \"f0\""), "not both"},
        {replaced(doc, "\"eta\": [0.2, 0.9, 1.1], ", ""), "/materials/0: 'eta' is missing"},
        {replaced(doc, "\"alpha\": 0.05, \"ior\": 1.5", "\"alpha\": [0.05, 0.1], \"ior\": 1.5"), "/materials/2/alpha: expected a number"},
        {replaced(doc, "\"metallic\": 0.25", "\"metallic\": 2"), "/materials/3/metallic: expected a number in [0, 1]"},
    };
    for (const auto& [text, expected] : bad)
    {
        const std::string message = errorOf(text);
        EXPECT_NE(message.find(expected), std::string::npos) << "expected '" << expected << "' in: " << message;
    }
}
} // namespace rt

#include "Image/ImageIO.h"

namespace rt
{
TEST(SceneFile, ImageTexturesTakeTheLinearFlagAndWriteItBack)
{
    // An image texture's texels are sRGB colour unless "linear": true (data, as glTF's metallic-roughness).
    test::ScratchDir dir;
    writePng8(dir / "mr.png", 1, 1, {0, 128, 64, 255});
    const std::string doc = R"({"textures": [{"type": "image", "path": "mr.png", "linear": true},
        {"type": "image", "path": "mr.png"}, {"type": "image", "path": "mr.png", "linear": false}],
        "materials": [{"type": "gltf_pbr", "base_color_texture": 1, "metallic_roughness_texture": 0}],
        "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": 0}]})";
    const Scene s = loadSceneFile(dir.write("s.json", doc));
    ASSERT_EQ(s.textures.size(), 3u);
    EXPECT_EQ(s.textures[0].linear, 1u);
    EXPECT_EQ(s.textures[1].linear, 0u) << "sRGB by default";
    EXPECT_EQ(s.textures[2].linear, 0u);

    const nlohmann::ordered_json j = sceneToJson(s);
    EXPECT_EQ(j["textures"][0].value("linear", false), true) << j["textures"][0].dump();
    EXPECT_FALSE(j["textures"][1].contains("linear")) << "written only where set: " << j["textures"][1].dump();
    exportScene(s, dir / "copy.json");
    const Scene copy = loadSceneFile(dir / "copy.json");
    ASSERT_EQ(copy.textures.size(), s.textures.size());
    EXPECT_EQ(std::memcmp(copy.textures.data(), s.textures.data(), s.textures.size() * sizeof(TextureData)), 0)
        << "the textures read back bit for bit";

    const auto errorIn = [&](const std::string& text) {
        try
        {
            loadSceneFile(dir.write("bad.json", text));
        }
        catch (const Error& e)
        {
            return std::string(e.what());
        }
        return std::string();
    };
    std::string e = errorIn(replaced(doc, "\"linear\": true", "\"linear\": 1"));
    EXPECT_NE(e.find("/textures/0/linear: expected true or false"), std::string::npos) << e;
    e = errorIn(replaced(doc, R"({"type": "image", "path": "mr.png"})",
                         R"({"type": "checker", "scale": 1, "even": [1, 1, 1], "odd": [0, 0, 0], "linear": true})"));
    EXPECT_NE(e.find("/textures/1: unknown key 'linear'"), std::string::npos) << "images only: " << e;
}
} // namespace rt
