#include "SceneFile/GltfMeshes.h"

#include <cmath>
#include <limits>
#include <numeric>

#include <glm/mat3x3.hpp>
#include <spdlog/fmt/fmt.h>

#include "SceneFile/GltfAccessors.h"
#include "SceneFile/GltfTexcoords.h"

namespace rt
{
namespace
{
const char* modeName(int mode)
{
    switch (mode)
    {
    case TINYGLTF_MODE_POINTS: return "POINTS";
    case TINYGLTF_MODE_LINE: return "LINES";
    case TINYGLTF_MODE_LINE_LOOP: return "LINE_LOOP";
    case TINYGLTF_MODE_LINE_STRIP: return "LINE_STRIP";
    case TINYGLTF_MODE_TRIANGLES: return "TRIANGLES";
    case TINYGLTF_MODE_TRIANGLE_STRIP: return "TRIANGLE_STRIP";
    case TINYGLTF_MODE_TRIANGLE_FAN: return "TRIANGLE_FAN";
    default: return "unknown";
    }
}

/// The triangles of primitive mode `mode` over the vertex list `v`, three indices each (§3.7.2.1: strips
/// p_i = {v_i, v_{i+(1+i%2)}, v_{i+(2-i%2)}}, fans p_i = {v_{i+1}, v_{i+2}, v_0}).
std::vector<std::uint32_t> triangleIndices(int mode, std::vector<std::uint32_t> v)
{
    if (mode == TINYGLTF_MODE_TRIANGLES)
        return v;
    std::vector<std::uint32_t> out;
    if (v.size() < 3)
        return out;
    out.reserve(3 * (v.size() - 2));
    for (std::size_t i = 0; i + 2 < v.size(); ++i)
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP)
            out.insert(out.end(), {v[i], v[i + 1 + i % 2], v[i + 2 - i % 2]});
        else
            out.insert(out.end(), {v[i + 1], v[i + 2], v[0]});
    return out;
}

std::string meshName(const GltfDocument& doc, int index)
{
    const std::string& name = doc.model.meshes[static_cast<std::size_t>(index)].name;
    return name.empty() ? fmt::format("mesh {}", index) : fmt::format("mesh '{}'", name);
}

/// Notes the attributes and extensions of a primitive the import does not map.
void noteUnmapped(const tinygltf::Primitive& p, const std::string& where, GltfNotes& notes)
{
    for (const auto& [name, accessor] : p.attributes)
        if (name.starts_with("COLOR_"))
            notes.add("vertex colours", where);
        else if (name.starts_with("JOINTS_") || name.starts_with("WEIGHTS_"))
            notes.add("skins (meshes in their bind pose)", where);
    if (!p.targets.empty())
        notes.add("morph targets (the base shape)", where);
    for (const auto& [name, value] : p.extensions)
        notes.add(name, where);
}

/// Reads one primitive into `builder`'s world group; returns its triangle count (0 if skipped).
std::size_t addPrimitive(const GltfDocument& doc, int meshIndex, std::size_t k, const glm::dmat4& worldFromNode,
                         GltfMaterials& materials, SceneBuilder& builder, GltfNotes& notes, GltfMeshSummary& summary)
{
    const tinygltf::Mesh& gltfMesh = doc.model.meshes[static_cast<std::size_t>(meshIndex)];
    const tinygltf::Primitive& p = gltfMesh.primitives[k];
    const std::string pointer = fmt::format("/meshes/{}/primitives/{}", meshIndex, k);
    const std::string where = meshName(doc, meshIndex);
    noteUnmapped(p, where, notes);
    const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN)
    {
        notes.add(fmt::format("{} primitives (skipped)", modeName(mode)), where);
        return 0;
    }
    if (p.extensions.contains("KHR_draco_mesh_compression"))
        return 0; // its accessors hold no data without a Draco decoder: noted above, skipped

    const auto position = p.attributes.find("POSITION");
    if (position == p.attributes.end())
        doc.fail(pointer + "/attributes", "the primitive has no POSITION");
    const std::vector<double> xyz = readGltfAccessor(doc, position->second, 3, pointer + "/attributes/POSITION");
    const std::size_t vertexCount = xyz.size() / 3;
    if (vertexCount > std::numeric_limits<std::uint32_t>::max())
        doc.fail(pointer + "/attributes/POSITION", fmt::format("{} vertices: at most 2^32 - 1", vertexCount));
    std::vector<std::uint32_t> vertices;
    if (p.indices >= 0)
        vertices = readGltfIndices(doc, p.indices, vertexCount, pointer + "/indices");
    else
    {
        vertices.resize(vertexCount);
        std::iota(vertices.begin(), vertices.end(), 0u);
    }
    if (mode == TINYGLTF_MODE_TRIANGLES && vertices.size() % 3 != 0)
        doc.fail(pointer + (p.indices >= 0 ? "/indices" : "/attributes/POSITION"),
                 fmt::format("{} vertices do not make whole triangles", vertices.size()));
    std::vector<std::uint32_t> indices = triangleIndices(mode, std::move(vertices));
    if (indices.empty())
        return 0;
    const std::uint32_t material = materials.material(p.material, pointer + "/material");

    MeshData mesh;
    mesh.name = gltfMesh.primitives.size() > 1 ? fmt::format("{} primitive {}", where, k) : where;
    mesh.positions.resize(vertexCount);
    constexpr double kMaxFloat = std::numeric_limits<float>::max();
    for (std::size_t i = 0; i < vertexCount; ++i)
    {
        const glm::dvec3 local(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
        if (!std::isfinite(local.x) || !std::isfinite(local.y) || !std::isfinite(local.z))
            doc.fail(fmt::format("/accessors/{}", position->second),
                     fmt::format("vertex {} is ({}, {}, {}): not finite", i, local.x, local.y, local.z));
        const glm::dvec3 world(worldFromNode * glm::dvec4(local, 1.0));
        if (!(glm::all(glm::lessThanEqual(glm::abs(world), glm::dvec3(kMaxFloat)))))
            doc.fail(pointer + "/attributes/POSITION",
                     fmt::format("vertex {} lands at ({}, {}, {}), beyond float's range", i, world.x, world.y, world.z));
        mesh.positions[i] = vec3(world);
        summary.boundsMin = glm::min(summary.boundsMin, world);
        summary.boundsMax = glm::max(summary.boundsMax, world);
    }

    const glm::dmat3 linear(worldFromNode);
    const double det = glm::determinant(linear);
    if (const auto normal = p.attributes.find("NORMAL"); normal != p.attributes.end())
    {
        const std::vector<double> n = readGltfAccessor(doc, normal->second, 3, pointer + "/attributes/NORMAL");
        if (n.size() != xyz.size())
            doc.fail(pointer + "/attributes/NORMAL",
                     fmt::format("{} normals for {} positions", n.size() / 3, vertexCount));
        const glm::dmat3 normalFromLocal = det != 0.0 ? glm::transpose(glm::inverse(linear)) : glm::dmat3(0.0);
        mesh.normals.resize(vertexCount);
        for (std::size_t i = 0; i < vertexCount && !mesh.normals.empty(); ++i)
        {
            const glm::dvec3 w = normalFromLocal * glm::dvec3(n[3 * i], n[3 * i + 1], n[3 * i + 2]);
            const double length = glm::length(w);
            if (!(length > 0.0) || !std::isfinite(length))
            {
                notes.add("zero-length or non-finite normals (the mesh's normals dropped)", where);
                mesh.normals.clear();
            }
            else
                mesh.normals[i] = vec3(w / length);
        }
    }
    if (det < 0.0) // a mirroring transform turns counter-clockwise triangles clockwise
        for (std::size_t t = 0; t < indices.size(); t += 3)
            std::swap(indices[t + 1], indices[t + 2]);
    mesh.indices = std::move(indices);
    if (const auto uv = p.attributes.find("TEXCOORD_0"); uv != p.attributes.end())
    {
        const std::vector<double> flat = readGltfAccessor(doc, uv->second, 2, pointer + "/attributes/TEXCOORD_0");
        if (flat.size() / 2 != vertexCount)
            doc.fail(pointer + "/attributes/TEXCOORD_0",
                     fmt::format("{} texture coordinates for {} positions", flat.size() / 2, vertexCount));
        std::vector<glm::dvec2> st(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i)
        {
            st[i] = {flat[2 * i], flat[2 * i + 1]};
            if (!std::isfinite(st[i].x) || !std::isfinite(st[i].y))
                doc.fail(fmt::format("/accessors/{}", uv->second),
                         fmt::format("texture coordinate {} is ({}, {}): not finite", i, st[i].x, st[i].y));
        }
        if (const std::optional<GltfWrapModes> wrap = materials.textured(material))
            if (wrapTexcoords(mesh, st, *wrap) > 0)
                notes.add("texture coordinates repeating within a triangle (clamped)", where);
        mesh.uvs.resize(st.size());
        for (std::size_t i = 0; i < st.size(); ++i) // glTF's t runs down the image, the engines' v up
            mesh.uvs[i] = vec2(static_cast<float>(st[i].x), static_cast<float>(1.0 - st[i].y));
    }
    const std::size_t triangles = mesh.triangleCount();
    builder.mesh(builder.world(), builder.addMesh(std::move(mesh)), material);
    ++summary.primitives;
    return triangles;
}
} // namespace

GltfMeshSummary addGltfMeshes(const GltfDocument& doc, const std::vector<GltfPlacedNode>& nodes,
                              GltfMaterials& materials, SceneBuilder& builder, GltfNotes& notes)
{
    GltfMeshSummary summary;
    const tinygltf::Model& m = doc.model;
    for (const GltfPlacedNode& placed : nodes)
    {
        const tinygltf::Node& node = m.nodes[static_cast<std::size_t>(placed.node)];
        if (node.mesh < 0)
            continue;
        if (static_cast<std::size_t>(node.mesh) >= m.meshes.size())
            doc.fail(fmt::format("/nodes/{}/mesh", placed.node),
                     fmt::format("mesh {} does not exist (the file has {})", node.mesh, m.meshes.size()));
        if (node.skin >= 0)
            notes.add("skins (meshes in their bind pose)", meshName(doc, node.mesh));
        const std::size_t primitives = m.meshes[static_cast<std::size_t>(node.mesh)].primitives.size();
        for (std::size_t k = 0; k < primitives; ++k)
            summary.triangles +=
                addPrimitive(doc, node.mesh, k, placed.worldFromNode, materials, builder, notes, summary);
    }
    return summary;
}
} // namespace rt
