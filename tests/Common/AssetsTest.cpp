// Assets/: OBJ meshes and image textures load from the asset folder beside the binary, and every missing or
// malformed file is an AssetError whose one-line message names the file (seed-findings: "image texture
// failures returned cyan silently").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "Assets/AssetPaths.h"
#include "Assets/ImageLoader.h"
#include "Assets/ObjLoader.h"
#include "Error.h"
#include "Image/ImageIO.h"
#include "Support/ScratchDir.h"

namespace rt
{
namespace
{
/// Runs `f`, which must throw AssetError; returns its message.
template <typename F>
std::string assetErrorOf(F&& f)
{
    try
    {
        f();
    }
    catch (const AssetError& e)
    {
        return e.what();
    }
    catch (const std::exception& e)
    {
        ADD_FAILURE() << "not an AssetError: " << e.what();
        return {};
    }
    ADD_FAILURE() << "no AssetError";
    return {};
}

void expectNamesOnOneLine(const std::string& message, const std::string& name)
{
    EXPECT_NE(message.find(name), std::string::npos) << "'" << name << "' not in: " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
}

const std::filesystem::path kAssimpInvalid = RT_ASSIMP_INVALID_MODELS;

TEST(ObjLoader, AssimpsInvalidModelsAreRejectedNamingTheFile)
{
    // Debian's assimp-testmodels: an index 0 and indices past the 8 vertices (malformed.obj), an empty face
    // line and an undefined material (malformed2.obj), an empty file (empty.obj).
    if (!std::filesystem::is_directory(kAssimpInvalid))
        GTEST_SKIP() << kAssimpInvalid << " is missing: install Debian's assimp-testmodels to run this test";
    for (const char* name : {"malformed.obj", "malformed2.obj", "empty.obj"})
    {
        const std::filesystem::path file = kAssimpInvalid / name;
        expectNamesOnOneLine(assetErrorOf([&] { loadObj(file.string()); }), file.string());
    }
}

TEST(ObjLoader, AFaceOfFewerThanThreeVerticesIsRejected)
{
    // tinyobjloader skips such a face silently; the loader must not (the project's rule: a malformed OBJ is an
    // error naming the problem). An undefined material alone is fine: the scene assigns materials.
    const test::ScratchDir dir;
    const std::string vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n";
    for (const char* face : {"f\n", "f 1 2\n", "f 1 2 # 3 in a comment\n"})
    {
        const auto file = dir.write("short.obj", vertices + "f 1 2 3\n" + face);
        const std::string message = assetErrorOf([&] { loadObj(file.string()); });
        expectNamesOnOneLine(message, file.string());
        EXPECT_NE(message.find("line 6"), std::string::npos) << message;
    }
    const auto fine = dir.write("fine.obj", "usemtl NoSuchMaterial\n" + vertices + "f 1 2 3\nf 2 4 3\n");
    EXPECT_EQ(loadObj(fine.string()).triangleCount(), 2u);
}

TEST(ObjLoader, AVertexIndexOutOfRangeIsRejected)
{
    const test::ScratchDir dir;
    const auto file = dir.write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n");
    const std::string message = assetErrorOf([&] { loadObj(file.string()); });
    expectNamesOnOneLine(message, file.string());
}

TEST(ObjLoader, AMissingFileNamesThePath)
{
    const std::string message = assetErrorOf([] { loadObj("meshes/no-such-mesh.obj"); });
    expectNamesOnOneLine(message, "meshes/no-such-mesh.obj");
    EXPECT_NE(message.find(assetRoot().string()), std::string::npos) << "where it looked: " << message;
}

TEST(ObjLoader, LoadsTheBunny)
{
    // Assets/meshes/bunny.obj: 3674 triangles (Assets/LICENSES.md), found through the binary's asset folder.
    const MeshData bunny = loadObj("meshes/bunny.obj");
    EXPECT_EQ(bunny.triangleCount(), 3674u);
    EXPECT_EQ(bunny.name, "bunny.obj");
    for (std::uint32_t i : bunny.indices)
        ASSERT_LT(i, bunny.positions.size());
    for (const vec3& p : bunny.positions)
        ASSERT_TRUE(isFinite(p));
    const Aabb box = bunny.bounds();
    EXPECT_GT(glm::length(box.max - box.min), 0.0f);
}

TEST(ImageLoader, AMissingTextureNamesThePath)
{
    expectNamesOnOneLine(assetErrorOf([] { loadImage("textures/no-such-texture.png"); }), "textures/no-such-texture.png");
}

TEST(ImageLoader, AnUndecodableTextureNamesThePath)
{
    const test::ScratchDir dir;
    const auto file = dir.write("broken.png", "this is not a PNG");
    expectNamesOnOneLine(assetErrorOf([&] { loadImage(file.string()); }), file.string());
}

TEST(ImageLoader, LoadsSrgbTexelsTopRowFirst)
{
    // A 2 x 2 PNG written through ImageIO: loadImage gives the 8-bit sRGB codes, row 0 at the top, alpha 255.
    const test::ScratchDir dir;
    Image image(2, 2);
    image.at(0, 0) = vec3(1.0f, 0.0f, 0.0f);
    image.at(1, 0) = vec3(0.0f, 1.0f, 0.0f);
    image.at(0, 1) = vec3(0.0f, 0.0f, 1.0f);
    image.at(1, 1) = vec3(0.5f);
    writePng(dir / "texture.png", image);
    const ImageData t = loadImage((dir / "texture.png").string());
    ASSERT_EQ(t.width, 2);
    ASSERT_EQ(t.height, 2);
    ASSERT_EQ(t.rgba.size(), 16u);
    const std::vector<std::uint8_t> expected = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 188, 188, 188, 255};
    EXPECT_EQ(t.rgba, expected);
}

TEST(AssetPaths, TheAssetRootIsBesideTheBinary)
{
    // The tests run from build/bin, where the build copied Assets/ (unless RT_ASSET_DIR says otherwise).
    if (const char* env = std::getenv("RT_ASSET_DIR"); env && *env)
        GTEST_SKIP() << "RT_ASSET_DIR is set to " << env;
    EXPECT_EQ(assetRoot(), executableDir() / "Assets");
    EXPECT_TRUE(std::filesystem::is_regular_file(assetRoot() / "meshes" / "bunny.obj"));
}

TEST(AssetPaths, AnExistingUserPathWinsOverTheAssetFolder)
{
    const test::ScratchDir dir;
    const auto file = dir.write("mine.obj", "v 0 0 0\n");
    EXPECT_EQ(resolveAsset(file.string(), "mesh"), file);
    EXPECT_EQ(resolveAsset("meshes/bunny.obj", "mesh"), assetRoot() / "meshes/bunny.obj");
    const std::string message = assetErrorOf([] { resolveAsset("nowhere.obj", "mesh"); });
    EXPECT_NE(message.find("mesh"), std::string::npos) << message;
}

TEST(AssetPaths, RtAssetDirOverridesTheRoot)
{
    const test::ScratchDir dir;
    const char* previous = std::getenv("RT_ASSET_DIR");
    const std::string saved = previous ? previous : "";
    ::setenv("RT_ASSET_DIR", dir.path().c_str(), 1);
    const std::filesystem::path root = assetRoot();
    if (previous)
        ::setenv("RT_ASSET_DIR", saved.c_str(), 1);
    else
        ::unsetenv("RT_ASSET_DIR");
    EXPECT_EQ(root, dir.path());
}
} // namespace
} // namespace rt
