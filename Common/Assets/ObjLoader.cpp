#include "Assets/ObjLoader.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <utility>

#include <spdlog/fmt/fmt.h>
#include <tiny_obj_loader.h>

#include "Assets/AssetPaths.h"
#include "Assets/MeshFit.h"
#include "Assets/ObjLines.h"
#include "Check.h"
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
} // namespace

MeshData loadObj(const std::string& path, ObjPlacement placement)
{
    const std::filesystem::path file = resolveAsset(path, "mesh");
    // Our scan first: it names the line of a problem tinyobjloader would read leniently or report vaguely.
    const ObjLines lines = scanObjLines(file);
    // Without a material reader: a mesh takes the scene's material, and an `mtllib` line may name any file (one
    // outside the scene's folders, a pipe that never ends, /dev/zero), which would be read for nothing.
    std::ifstream in(file, std::ios::binary);
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warnings, error;
    if (!in || !tinyobj::LoadObj(&attrib, &shapes, &materials, &warnings, &error, &in, nullptr, true, false))
        throw AssetError(fmt::format("malformed OBJ '{}': {}", file.string(),
                                     firstLine(error.empty() ? "cannot be parsed" : error)));

    const std::size_t vertexCount = lines.positions.size();
    if (attrib.vertices.size() != 3 * vertexCount) // one per `v` statement in both readers
        throw AssetError(fmt::format("malformed OBJ '{}': tinyobjloader read {} vertices where the file has {}",
                                     file.string(), attrib.vertices.size() / 3, vertexCount));
    MeshData mesh;
    mesh.name = file.filename().string();
    // Positions are shared between faces as written: that keeps the mesh watertight for the triangle test.
    for (const tinyobj::shape_t& shape : shapes)
    {
        std::size_t offset = 0;
        for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f)
        {
            const std::size_t n = shape.mesh.num_face_vertices[f];
            if (n == 3)
                for (std::size_t k = 0; k < 3; ++k)
                {
                    const int index = shape.mesh.indices[offset + k].vertex_index;
                    RT_CHECK(index >= 0 && static_cast<std::size_t>(index) < vertexCount); // scanObjLines checked
                    mesh.indices.push_back(static_cast<std::uint32_t>(index));
                }
            offset += n;
        }
    }
    if (mesh.indices.empty())
        throw AssetError(fmt::format("malformed OBJ '{}': it holds no triangles", file.string()));
    if (placement == ObjPlacement::AsWritten)
    {
        for (const dvec3& p : lines.positions)
        {
            if (glm::any(glm::greaterThan(glm::abs(p), dvec3(std::numeric_limits<float>::max()))))
                throw AssetError(fmt::format("OBJ '{}': a coordinate of vertex ({}, {}, {}) is beyond float's range",
                                             file.string(), p.x, p.y, p.z));
            mesh.positions.push_back(vec3(p));
        }
        return mesh;
    }
    std::string why;
    std::optional<std::vector<vec3>> fitted = fitMesh(lines.positions, why);
    if (!fitted)
        throw AssetError(fmt::format("OBJ '{}' cannot be fitted into a scene: {}", file.string(), why));
    mesh.positions = std::move(*fitted);
    return mesh;
}
} // namespace rt
