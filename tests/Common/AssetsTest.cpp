// Assets/: OBJ meshes and image textures load from the asset folder beside the binary, and every missing or
// malformed file is an AssetError whose one-line message names the file (seed-findings: "image texture
// failures returned cyan silently").
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>

#ifndef _WIN32
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

#include "Assets/AssetPaths.h"
#include "Assets/ImageLoader.h"
#include "Assets/MeshFit.h"
#include "Assets/ObjLoader.h"
#include "Error.h"
#include "Image/ImageIO.h"
#include "Support/AssetErrorOf.h"
#include "Support/CubeObj.h"
#include "Support/ScratchDir.h"

namespace rt
{
namespace
{
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
        expectNamesOnOneLine(test::assetErrorOf([&] { loadObj(file.string()); }), file.string());
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
        const std::string message = test::assetErrorOf([&] { loadObj(file.string()); });
        expectNamesOnOneLine(message, file.string());
        EXPECT_NE(message.find("line 6"), std::string::npos) << message;
    }
    const auto fine = dir.write("fine.obj", "usemtl NoSuchMaterial\n" + vertices + "f 1 2 3\nf 2 4 3\n");
    EXPECT_EQ(loadObj(fine.string()).triangleCount(), 2u);
}

#ifndef _WIN32
TEST(ObjLoader, AnMtllibLineIsNotRead)
{
    // A mesh takes the scene's material, and an OBJ's `mtllib` may name any file: one outside the scene's folders,
    // /dev/zero, or a pipe. Here a pipe, watched by a thread that opens its writing end whenever a reader holds the
    // other (a nonblocking open for writing succeeds only then) and closes it at once, so that a reader would get an
    // empty file and the test an answer instead of a hang.
    const test::ScratchDir dir;
    const std::filesystem::path pipe = dir.path() / "materials.mtl";
    ASSERT_EQ(mkfifo(pipe.c_str(), 0600), 0);
    const auto file = dir.write("mesh.obj", "mtllib materials.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");
    std::atomic<bool> loaded = false, opened = false;
    std::thread watcher([&] {
        while (!loaded)
        {
            if (const int fd = open(pipe.c_str(), O_WRONLY | O_NONBLOCK); fd >= 0)
            {
                opened = true;
                close(fd);
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
    });
    const MeshData mesh = loadObj(file.string());
    loaded = true;
    watcher.join();
    EXPECT_FALSE(opened) << "the loader opened the file its mtllib line names";
    EXPECT_EQ(mesh.triangleCount(), 1u);
}
#endif

TEST(ObjLoader, AVertexIndexOutOfRangeIsRejected)
{
    const test::ScratchDir dir;
    const auto file = dir.write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n");
    const std::string message = test::assetErrorOf([&] { loadObj(file.string()); });
    expectNamesOnOneLine(message, file.string());
}

TEST(ObjLoader, AnIndexOutOfRangeIsQuotedAsWritten)
{
    // tinyobjloader resolves relative indices and subtracts one before it reports: the message must quote
    // the file's own number and line (issue 13), whichever kind of index it is.
    const test::ScratchDir dir;
    const std::string vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    const struct
    {
        const char* face;
        const char* quoted;
    } cases[] = {{"f 1 2 9\n", "vertex index 9 "},      {"f -1 -2 -7\n", "vertex index -7 "},
                 {"f 1 2 0\n", "vertex index 0 "},      {"f 1/4 2/1 3/1\n", "texture coordinate index 4 "},
                 {"f 1//2 2//1 3//1\n", "normal index 2 "}, {"f 1 2 x\n", "vertex index 'x'"}};
    for (const auto& c : cases)
    {
        const auto file = dir.write("index.obj", vertices + "vt 0 0\nvn 0 0 1\n" + c.face);
        const std::string message = test::assetErrorOf([&] { loadObj(file.string()); });
        expectNamesOnOneLine(message, file.string());
        EXPECT_NE(message.find("line 6"), std::string::npos) << message;
        EXPECT_NE(message.find(c.quoted), std::string::npos) << c.face << " -> " << message;
    }
}

TEST(ObjLoader, ACoordinateThatIsNotAFiniteNumberIsRejectedNamingTheLine)
{
    // tinyobjloader reads `nan`, `inf`, an overflowing 1e400 and a missing coordinate as 0 (issue 13).
    const test::ScratchDir dir;
    for (const char* line : {"v nan 0 0\n", "v 0 inf 0\n", "v 0 0 -infinity\n", "v 1e400 0 0\n", "v 0 0\n",
                             "v 0 0 1x\n", "v 1 2 3 4 5\n", "vn 0 nan 1\n", "vn 0 1\n", "vt inf\n", "vt\n"})
    {
        const auto file = dir.write("nan.obj", std::string("v 0 0 0\n") + line + "v 1 0 0\nv 0 1 0\nf 1 3 4\n");
        const std::string message = test::assetErrorOf([&] { loadObj(file.string()); });
        expectNamesOnOneLine(message, file.string());
        EXPECT_NE(message.find("line 2"), std::string::npos) << line << " -> " << message;
    }
    // What the format allows still loads: w, a vertex colour, 1- to 3-number texture coordinates, exponents.
    const auto fine = dir.write("fine.obj", "v 0 0 0 1\nv 1e0 0 0 0.5 0.5 0.5\nv 0 +1. -0e5\nvt 0.5\nvt 0 1 0\n"
                                            "vn 0 0 1\nf 1/1/1 2/2/1 3/1/1\n");
    EXPECT_EQ(loadObj(fine.string()).triangleCount(), 1u);
}

TEST(ObjLoader, FarHugeAndTinyMeshesLoadFittedToTheSamePlace)
{
    // Issue 13: a +-1e7 cube went black on the GPU, a unit cube at 1e7 landed in a different wrong place on
    // each engine, a 0.5-wide one at 1e7 vanished (float rounds 1e7 +- 0.25 to whole numbers) and a 1e-7 cube
    // was shrunk. Fitted in double, every one of them is the same unit cube standing on the origin, so both
    // engines get the same float positions.
    const test::ScratchDir dir;
    const MeshData reference = loadObj(dir.write("unit.obj", test::cubeObj(0.0, 1.0)).string());
    const Aabb box = reference.bounds();
    EXPECT_EQ(box.min, vec3(-0.5f, 0.0f, -0.5f));
    EXPECT_EQ(box.max, vec3(0.5f, 1.0f, 0.5f));
    const struct
    {
        double centre, edge;
    } cubes[] = {{0.0, 2e7}, {1e7, 1.0}, {1e7, 0.5}, {0.0, 1e-7}, {-3e-9, 2e-9}, {1e300, 1e300}};
    for (const auto& c : cubes)
    {
        const MeshData mesh = loadObj(dir.write("cube.obj", test::cubeObj(c.centre, c.edge)).string());
        ASSERT_EQ(mesh.positions.size(), reference.positions.size());
        for (std::size_t i = 0; i < mesh.positions.size(); ++i)
            for (int k = 0; k < 3; ++k)
                ASSERT_NEAR(mesh.positions[i][k], reference.positions[i][k], 1e-6f)
                    << "cube of edge " << c.edge << " at " << c.centre << ", vertex " << i;
    }
}

TEST(ObjLoader, AFlatMeshIsFittedByItsWidthAndAPointIsRefused)
{
    const test::ScratchDir dir;
    const std::string faces = "f 1 2 3\nf 1 3 4\n";
    const MeshData plate = loadObj(dir.write("plate.obj", "v -4 7 -2\nv 4 7 -2\nv 4 7 2\nv -4 7 2\n" + faces).string());
    const Aabb box = plate.bounds();
    EXPECT_EQ(box.min.y, 0.0f);
    EXPECT_EQ(box.max.y, 0.0f);
    // Height 0: the fit height is kFlatMeshRatio of the width, 8, so the plate is 1 / kFlatMeshRatio wide.
    EXPECT_FLOAT_EQ(box.max.x - box.min.x, float(1.0 / kFlatMeshRatio));
    EXPECT_FLOAT_EQ(box.max.z - box.min.z, float(0.5 / kFlatMeshRatio));
    const auto point = dir.write("point.obj", "v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n");
    const std::string message = test::assetErrorOf([&] { loadObj(point.string()); });
    expectNamesOnOneLine(message, point.string());
    EXPECT_NE(message.find("one point"), std::string::npos) << message;
}

TEST(ObjLoader, AMissingFileNamesThePath)
{
    const std::string message = test::assetErrorOf([] { loadObj("meshes/no-such-mesh.obj"); });
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
    expectNamesOnOneLine(test::assetErrorOf([] { loadImage("textures/no-such-texture.png"); }), "textures/no-such-texture.png");
}

TEST(ImageLoader, AnUndecodableTextureNamesThePath)
{
    const test::ScratchDir dir;
    const auto file = dir.write("broken.png", "this is not a PNG");
    expectNamesOnOneLine(test::assetErrorOf([&] { loadImage(file.string()); }), file.string());
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
    const std::string message = test::assetErrorOf([] { resolveAsset("nowhere.obj", "mesh"); });
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
