#include "Assets/ObjLoader.h"

#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <utility>

#include <spdlog/fmt/fmt.h>
#include <tiny_obj_loader.h>

#include "Assets/AssetPaths.h"
#include "Error.h"

namespace rt
{
namespace
{
std::string firstLine(const std::string& text)
{
    std::istringstream in(text);
    std::string line;
    std::getline(in, line);
    return line;
}

/// The first face statement with fewer than three vertices, as (line number, vertex count). tinyobjloader
/// drops such a face (an empty `f` line) without a word, which would load a malformed file with a hole.
std::optional<std::pair<std::size_t, int>> shortFace(const std::filesystem::path& file)
{
    std::ifstream in(file);
    std::string line;
    for (std::size_t number = 1; std::getline(in, line); ++number)
    {
        std::istringstream words(line.substr(0, line.find('#')));
        std::string keyword;
        if (!(words >> keyword) || keyword != "f")
            continue;
        int vertices = 0;
        for (std::string vertex; words >> vertex;)
            ++vertices;
        if (vertices < 3)
            return std::pair{number, vertices};
    }
    return std::nullopt;
}
} // namespace

MeshData loadObj(const std::string& path)
{
    const std::filesystem::path file = resolveAsset(path, "mesh");
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    config.mtl_search_path = file.parent_path().string();
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(file.string(), config))
        throw AssetError(fmt::format("malformed OBJ '{}': {}", file.string(),
                                     firstLine(reader.Error().empty() ? "cannot be parsed" : reader.Error())));
    if (const auto face = shortFace(file))
        throw AssetError(fmt::format("malformed OBJ '{}': line {}: a face with {} vertices (at least 3 needed)",
                                     file.string(), face->first, face->second));

    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    const std::size_t vertexCount = attrib.vertices.size() / 3;
    MeshData mesh;
    mesh.name = file.filename().string();
    mesh.positions.reserve(vertexCount);
    for (std::size_t i = 0; i < vertexCount; ++i)
    {
        const vec3 p(attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]);
        if (!isFinite(p))
            throw AssetError(fmt::format("malformed OBJ '{}': vertex {} is not finite", file.string(), i + 1));
        mesh.positions.push_back(p);
    }
    // Positions are shared between faces as written: that keeps the mesh watertight for the triangle test.
    for (const tinyobj::shape_t& shape : reader.GetShapes())
    {
        std::size_t offset = 0;
        for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f)
        {
            const std::size_t n = shape.mesh.num_face_vertices[f];
            if (n == 3)
                for (std::size_t k = 0; k < 3; ++k)
                {
                    const int index = shape.mesh.indices[offset + k].vertex_index;
                    if (index < 0 || static_cast<std::size_t>(index) >= vertexCount)
                        throw AssetError(fmt::format("malformed OBJ '{}': face {} of '{}' uses vertex {} of {}",
                                                     file.string(), f + 1, shape.name, index + 1, vertexCount));
                    mesh.indices.push_back(static_cast<std::uint32_t>(index));
                }
            offset += n;
        }
    }
    if (mesh.indices.empty())
        throw AssetError(fmt::format("malformed OBJ '{}': it holds no triangles", file.string()));
    return mesh;
}
} // namespace rt
