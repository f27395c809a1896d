// What a scene file may read and how deep it may nest (issue 41): a file it names resolves inside its own folder
// or the asset folder (a glTF buffer "../../../../etc/passwd" was read and rendered, and --export-scene copied its
// bytes), a name that is not a regular file is refused by what it is (a buffer "." gave std::bad_alloc as the
// message), and JSON nested past kMaxJsonNesting is refused before any parser recurses (60,000 levels in a
// scene, 30,000 in a glTF's extras, overflowed the stack).
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "Error.h"
#include "Image/ImageIO.h"
#include "SceneFile/JsonNode.h"
#include "SceneFile/SceneFile.h"
#include "Scenes/Catalogue.h"
#include "Support/GltfTestFiles.h"

namespace rt::test
{
namespace
{
/// The message of the SceneError that loading `file` throws ("" if it loads; another error fails the test).
std::string sceneErrorOf(const std::filesystem::path& file)
{
    try
    {
        loadSceneFile(file);
    }
    catch (const SceneError& e)
    {
        return e.what();
    }
    catch (const std::exception& e)
    {
        ADD_FAILURE() << "not a SceneError: " << e.what();
    }
    return {};
}

std::string nested(int depth) { return std::string(depth, '[') + std::string(depth, ']'); }

TEST(SceneFileBounds, AGltfBufferOutsideTheScenesFolderIsRefusedNamingIt)
{
    const ScratchDir dir;
    std::filesystem::create_directories(dir / "scene" / "sub");
    GltfWriter w;
    const std::filesystem::path file = oneTriangle(dir, -1, w, "t");
    // The buffer beside the folder, named through "..": refused though it exists and is valid.
    std::filesystem::rename(file, dir / "scene" / "t.gltf");
    w.json()["buffers"] = nlohmann::json::array({{{"uri", "../t.bin"}, {"byteLength", w.bin().size()}}});
    std::ofstream(dir / "scene" / "t.gltf") << w.json().dump();
    std::string e = sceneErrorOf(dir / "scene" / "t.gltf");
    EXPECT_NE(e.find("t.bin' lies outside the scene's folder"), std::string::npos) << e;
    // As far out as the root.
    w.json()["buffers"][0]["uri"] = "../../../../../../../../etc/passwd";
    std::ofstream(dir / "scene" / "p.gltf") << w.json().dump();
    e = sceneErrorOf(dir / "scene" / "p.gltf");
    EXPECT_NE(e.find("/etc/passwd' lies outside"), std::string::npos) << e;
    // A ".." that stays inside is a path like any other.
    std::filesystem::copy_file(dir / "t.bin", dir / "scene" / "t.bin");
    w.json()["buffers"][0]["uri"] = "sub/../t.bin";
    std::ofstream(dir / "scene" / "in.gltf") << w.json().dump();
    EXPECT_NO_THROW(loadSceneFile(dir / "scene" / "in.gltf"));
    // A folder as the buffer: refused for what it is.
    w.json()["buffers"][0]["uri"] = ".";
    std::ofstream(dir / "scene" / "dot.gltf") << w.json().dump();
    e = sceneErrorOf(dir / "scene" / "dot.gltf");
    EXPECT_NE(e.find("is not a regular file"), std::string::npos) << e;
}

TEST(SceneFileBounds, AGltfImageOutsideTheScenesFolderIsRefused)
{
    const ScratchDir dir;
    std::filesystem::create_directories(dir / "scene");
    writePng8(dir / "outside.png", 1, 1, {255, 0, 0, 255});
    GltfWriter w;
    const int image = w.imageFile("../outside.png");
    texturedTriangle(dir, w, image, {1, 1, 1, 1}, "t");
    std::filesystem::rename(dir / "t.gltf", dir / "scene" / "t.gltf");
    std::filesystem::rename(dir / "t.bin", dir / "scene" / "t.bin");
    const std::string e = sceneErrorOf(dir / "scene" / "t.gltf");
    EXPECT_NE(e.find("/images/0/uri: '../outside.png'"), std::string::npos) << e;
    EXPECT_NE(e.find("lies outside"), std::string::npos) << e;
}

TEST(SceneFileBounds, AJsonScenesTextureOrMeshOutsideItsFolderIsRefused)
{
    const ScratchDir dir;
    std::filesystem::create_directories(dir / "scene");
    writePng8(dir / "outside.png", 1, 1, {255, 0, 0, 255});
    std::ofstream(dir / "outside.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const std::string light = R"({"type": "sphere", "center": [0, 5, 0], "radius": 1, "material": "lamp"})";
    const std::string materials =
        R"("materials": [{"name": "lamp", "type": "diffuse_light", "radiance": [4, 4, 4]},
                         {"name": "m", "type": "lambertian", "albedo_texture": 0}])";
    std::ofstream(dir / "scene" / "tex.json")
        << R"({"textures": [{"type": "image", "path": "../outside.png"}], )" << materials
        << R"(, "shapes": [)" << light << "]}";
    std::string e = sceneErrorOf(dir / "scene" / "tex.json");
    EXPECT_NE(e.find("/textures/0/path: texture '../outside.png': '"), std::string::npos) << e;
    EXPECT_NE(e.find("outside.png' lies outside the scene's folder"), std::string::npos) << e;
    // An absolute path outside is refused the same way.
    std::ofstream(dir / "scene" / "mesh.json")
        << R"({"meshes": [{"obj": ")" << (dir / "outside.obj").string() << R"("}], )" << materials
        << R"(, "textures": [{"type": "checker", "scale": 1, "even": [1, 1, 1], "odd": [0, 0, 0]}], "shapes": [)"
        << light << "]}";
    e = sceneErrorOf(dir / "scene" / "mesh.json");
    EXPECT_NE(e.find("/meshes/0/obj: mesh '"), std::string::npos) << e;
    EXPECT_NE(e.find("lies outside"), std::string::npos) << e;
}

TEST(SceneFileBounds, NestingPastTheLimitIsRefusedBeforeAnyParserRecurses)
{
    const ScratchDir dir;
    // A JSON scene 60,000 deep in a value, a glTF 30,000 deep in its extras, and the same in a .glb's JSON chunk.
    std::string e = sceneErrorOf(dir.write("deep.json", R"({"camera": )" + nested(60000) + "}"));
    EXPECT_NE(e.find("deep.json:1:523: arrays and objects nested deeper than 512 levels"), std::string::npos) << e;
    e = sceneErrorOf(dir.write("deep.gltf", R"({"asset": {"version": "2.0"}, "extras": )" + nested(30000) + "}"));
    EXPECT_NE(e.find("nested deeper than 512"), std::string::npos) << e;
    GltfWriter w;
    oneTriangle(dir, -1, w, "g");
    w.json()["extras"] = nlohmann::json::array();
    std::vector<std::uint8_t> glb = w.glbBytes();
    std::string json = w.json().dump();
    // Splice the deep value into the JSON chunk by hand: nlohmann cannot build one that deep.
    const std::string deepJson = json.substr(0, json.size() - 1) + R"(, "more": )" + nested(30000) + "}";
    std::string padded = deepJson;
    while (padded.size() % 4 != 0)
        padded += ' ';
    std::vector<std::uint8_t> out(glb.begin(), glb.begin() + 12);
    const auto u32 = [&out](std::uint32_t v) {
        for (int i = 0; i < 4; ++i)
            out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    };
    u32(static_cast<std::uint32_t>(padded.size()));
    u32(0x4E4F534Au); // "JSON"
    out.insert(out.end(), padded.begin(), padded.end());
    std::ofstream(dir / "deep.glb", std::ios::binary).write(reinterpret_cast<const char*>(out.data()),
                                                              static_cast<std::streamsize>(out.size()));
    e = sceneErrorOf(dir / "deep.glb");
    EXPECT_NE(e.find("nested deeper than 512"), std::string::npos) << e;
    // At the limit itself a value is only wrong, not refused for its depth.
    e = sceneErrorOf(dir.write("edge.json", R"({"camera": )" + nested(kMaxJsonNesting - 1) + "}"));
    EXPECT_EQ(e.find("nested deeper"), std::string::npos) << e;
    EXPECT_NE(e.find("/camera"), std::string::npos) << e;
}
/// The message of the SceneError that building the scene file `file` as the apps do (makeScene: the file, then
/// the options) throws ("" if it builds).
std::string builtErrorOf(const std::filesystem::path& file, const SceneOptions& options = {})
{
    try
    {
        makeScene(file.string(), options);
    }
    catch (const SceneError& e)
    {
        return e.what();
    }
    return {};
}

TEST(SceneFileBounds, GeometryBeyondFloat32sReachIsRefusedWhateverPlacedIt)
{
    // What --scale-scene and --translate-scene refuse, a scene file's own transforms placed silently (a glTF
    // node scaled by 1e20 rendered black with status 0).
    const ScratchDir dir;
    const auto scene = [](const std::string& transform) {
        return R"({"camera": {"look_from": [0, 1, 5], "look_at": [0, 1, 0], "vfov": 40},
            "materials": [{"name": "lamp", "type": "diffuse_light", "radiance": [4, 4, 4]}],
            "groups": [{"name": "g", "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 0.5,
                                                 "material": "lamp"}]}],
            "instances": [{"group": "g", "transform": [)" + transform + "]}]}";
    };
    EXPECT_EQ(builtErrorOf(dir.write("fine.json", scene(R"({"scale": 1000})"))), "");
    const std::filesystem::path huge = dir.write("huge.json", scene(R"({"scale": 1e10})"));
    std::string e = builtErrorOf(huge);
    EXPECT_NE(e.find("huge.json: the scene is 1.73205e+10 world units across"), std::string::npos) << e;
    // --scale-scene may bring it back into float32's reach: the check is on the scene as rendered.
    SceneOptions smaller;
    smaller.transform.scale = 1e-4f;
    EXPECT_EQ(builtErrorOf(huge, smaller), "");
    // Far from its camera: render space (the camera at the origin) cannot hold it either.
    e = builtErrorOf(dir.write("far.json", scene(R"({"translate": [1e6, 0, 0]})")));
    EXPECT_NE(e.find("far.json: the scene (size"), std::string::npos) << e;
    EXPECT_NE(e.find("from the origin of its coordinates (the camera, as rendered)"), std::string::npos) << e;
    EXPECT_NE(e.find("times its size; float32 renders it right up to 32 times"), std::string::npos) << e;
    GltfWriter w;
    const int mesh = w.mesh({triangle()});
    w.scene({w.node({{"mesh", mesh}, {"scale", {1e20, 1e20, 1e20}}})});
    e = builtErrorOf(w.writeGltf(dir.path(), "scaled"));
    EXPECT_NE(e.find("scaled.gltf: the scene is"), std::string::npos) << e;
}
} // namespace
} // namespace rt::test
