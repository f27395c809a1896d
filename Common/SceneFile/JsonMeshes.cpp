#include "SceneFile/JsonMeshes.h"

#include <cmath>

#include <spdlog/fmt/fmt.h>

namespace rt
{
namespace
{
/// The numbers of `list` (a multiple of `arity` of them), as float.
std::vector<float> floats(const JsonNode& list, std::size_t arity)
{
    const std::size_t n = list.size();
    if (n % arity != 0)
        list.fail(fmt::format("expected a multiple of {} numbers, got {}", arity, n));
    std::vector<float> out(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        const nlohmann::json& v = list.value()[i];
        const double d = v.is_number() ? v.get<double>() : NAN;
        if (!std::isfinite(d) || std::abs(d) > JsonNode::kMaxFloat)
            list[i].number(); // throws, naming the element
        out[i] = static_cast<float>(d);
    }
    return out;
}

template <typename V>
std::vector<V> vectors(const JsonNode& list, std::size_t expected, const char* what)
{
    constexpr std::size_t arity = sizeof(V) / sizeof(float);
    const std::vector<float> f = floats(list, arity);
    if (expected != 0 && f.size() != expected * arity)
        list.fail(fmt::format("expected one {} per position ({} numbers), got {}", what, expected * arity, f.size()));
    std::vector<V> out(f.size() / arity);
    for (std::size_t i = 0; i < out.size(); ++i)
        for (std::size_t k = 0; k < arity; ++k)
            out[i][static_cast<int>(k)] = f[arity * i + k];
    return out;
}
} // namespace

MeshData readInlineMesh(const JsonNode& m, const std::function<std::uint32_t(const JsonNode&)>& materialRef)
{
    MeshData mesh;
    mesh.positions = vectors<vec3>(m["positions"], 0, "position");
    if (mesh.positions.empty())
        m["positions"].fail("expected at least 3 positions");
    const JsonNode indices = m["indices"];
    const std::size_t n = indices.size();
    if (n == 0 || n % 3 != 0)
        indices.fail(fmt::format("expected a positive multiple of 3 indices, got {}", n));
    mesh.indices.resize(n);
    const std::uint64_t count = mesh.positions.size();
    for (std::size_t i = 0; i < n; ++i)
    {
        const nlohmann::json& v = indices.value()[i];
        if (!v.is_number_unsigned() || v.get<std::uint64_t>() >= count)
            indices[i].integer(0, static_cast<std::int64_t>(count) - 1); // throws, naming the element
        mesh.indices[i] = static_cast<std::uint32_t>(v.get<std::uint64_t>());
    }
    if (m.has("normals"))
        mesh.normals = vectors<vec3>(m["normals"], mesh.positions.size(), "normal");
    if (m.has("uvs"))
        mesh.uvs = vectors<vec2>(m["uvs"], mesh.positions.size(), "uv");
    if (m.has("triangle_materials"))
    {
        const JsonNode mats = m["triangle_materials"];
        if (mats.size() != n / 3)
            mats.fail(fmt::format("expected one material per triangle ({}), got {}", n / 3, mats.size()));
        mesh.triangleMaterials.resize(n / 3);
        for (std::size_t t = 0; t < n / 3; ++t)
            mesh.triangleMaterials[t] = materialRef(mats[t]);
    }
    return mesh;
}
} // namespace rt
