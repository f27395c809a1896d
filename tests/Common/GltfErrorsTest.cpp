// glTF import: each error with its message (missing file, malformed JSON, accessors and buffer views out of
// range, vertex indices out of range, a missing buffer file, nothing to render), and truncated or bit-flipped
// files, which must be refused with an rt::Error and never crash.
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "SceneFile/GltfImport.h"
#include "SceneFile/SceneFile.h"
#include "Support/GltfTestFiles.h"

namespace rt::test
{
namespace
{
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

TEST(GltfErrors, APropertyOfTheWrongTypeIsRefusedNotReadPast)
{
    // tinygltf left each at its default without a word: the file rendered something else than it says.
    ScratchDir dir;
    const auto fileWith = [&dir](const char* name, const std::function<void(nlohmann::json&)>& edit) {
        GltfWriter w;
        const int mat = w.material({{"pbrMetallicRoughness", {{"baseColorFactor", {1, 0, 0, 1}}}}});
        oneTriangle(dir, mat, w, name);
        edit(w.json());
        return w.writeGltf(dir.path(), name);
    };
    const auto errorWith = [&fileWith](const char* name, const std::function<void(nlohmann::json&)>& edit) {
        return errorOf(fileWith(name, edit));
    };
    std::string e = errorWith("pbr", [](nlohmann::json& j) { j["materials"][0]["pbrMetallicRoughness"] = {1, 2}; });
    EXPECT_NE(e.find("pbr.gltf: /materials/0/pbrMetallicRoughness: expected an object, got an array of 2"),
              std::string::npos) << e;
    e = errorWith("factor", [](nlohmann::json& j) { j["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = "red"; });
    EXPECT_NE(e.find("/materials/0/pbrMetallicRoughness/baseColorFactor: expected an array of numbers of length 4"),
              std::string::npos) << e;
    e = errorWith("scale", [](nlohmann::json& j) { j["nodes"][0]["scale"] = {2, 2}; });
    EXPECT_NE(e.find("/nodes/0/scale: expected an array of numbers of length 3, got an array of 2"), std::string::npos)
        << e;
    e = errorWith("index", [](nlohmann::json& j) { j["meshes"][0]["primitives"][0]["material"] = 0.5; });
    EXPECT_NE(e.find("/meshes/0/primitives/0/material: expected an integer, got 0.5"), std::string::npos) << e;
    e = errorWith("nodes", [](nlohmann::json& j) { j["nodes"] = nlohmann::json::object(); });
    EXPECT_NE(e.find("nodes.gltf: /nodes: expected an array, got an object"), std::string::npos) << e;
    // Unchanged, the same file imports.
    EXPECT_NO_THROW(readGltf(fileWith("fine", [](nlohmann::json&) {})));
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
