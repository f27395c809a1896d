// Files for the glTF import's tests (tests/Common/Gltf*Test.cpp): one triangle in a file, a small PNG, and the
// checks they share (the error an import throws, a material's solid colour).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "Error.h"
#include "Image/ImageIO.h"
#include "SceneFile/GltfImport.h"
#include "Support/GltfWriter.h"
#include "Support/ScratchDir.h"

namespace rt::test
{
using Primitive = GltfWriter::Primitive;

/// One counter-clockwise triangle seen from +z, with normals +z and uvs.
inline Primitive triangle(int material = -1)
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
inline std::filesystem::path oneTriangle(const ScratchDir& dir, int material, GltfWriter& w, const std::string& name = "t")
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

inline void expectNear(const vec3& a, const vec3& b, float tolerance = 1e-5f)
{
    EXPECT_NEAR(a.x, b.x, tolerance) << "x";
    EXPECT_NEAR(a.y, b.y, tolerance) << "y";
    EXPECT_NEAR(a.z, b.z, tolerance) << "z";
}

inline const MaterialData& onlyMaterial(const Scene& s)
{
    EXPECT_EQ(s.groups.size(), 1u);
    return s.materials.at(s.groups.at(0).meshes.at(0).material);
}

inline vec3 solidColor(const Scene& s, std::uint32_t texture)
{
    EXPECT_EQ(s.textures.at(texture).type, TextureType::Solid);
    return s.textures.at(texture).color0;
}

/// A 2 x 2 PNG: red, green / blue, white (row 0 on top), written to `dir` and returned as bytes.
inline std::vector<std::uint8_t> checkerPng(const ScratchDir& dir, const std::string& name = "tex.png")
{
    const std::vector<unsigned char> rgba = {200, 10, 10, 255, 10, 200, 10, 255, 10, 10, 200, 255, 250, 250, 250, 255};
    writePng8(dir / name, 2, 2, rgba);
    return GltfWriter::readBytes(dir / name);
}

/// A 1 x 1 PNG of the texel `rgba`, written to `dir` and returned as bytes (a metallic-roughness texel: g
/// roughness, b metallic).
inline std::vector<std::uint8_t> texelPng(const ScratchDir& dir, const std::vector<unsigned char>& rgba,
                                          const std::string& name = "texel.png")
{
    writePng8(dir / name, 1, 1, rgba);
    return GltfWriter::readBytes(dir / name);
}

/// A non-metallic (gltf_pbr, metallicFactor 0) triangle textured with `image` times `factor`.
inline std::filesystem::path texturedTriangle(const ScratchDir& dir, GltfWriter& w, int image, const std::vector<double>& factor,
                                       const std::string& name)
{
    const int mat = w.material({{"pbrMetallicRoughness",
                                 {{"baseColorTexture", {{"index", w.texture(image)}}},
                                  {"baseColorFactor", factor},
                                  {"metallicFactor", 0}}}});
    return oneTriangle(dir, mat, w, name);
}

} // namespace rt::test
