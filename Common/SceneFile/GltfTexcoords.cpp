#include "SceneFile/GltfTexcoords.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>

namespace rt
{
namespace
{
constexpr double kSlack = 1e-4; // exporters write 4.9999999 for 5

/// The period a triangle's coordinates (a, b, c) on one axis lie in, or nothing if they span more than one.
/// CLAMP_TO_EDGE keeps period 0 (the coordinates as written).
std::optional<double> period(double a, double b, double c, GltfWrap mode)
{
    if (mode == GltfWrap::ClampToEdge)
        return 0.0;
    const double k = std::floor(std::min({a, b, c}) + kSlack);
    if (std::max({a, b, c}) - k > 1.0 + kSlack)
        return std::nullopt;
    return k;
}

/// `x` of period `k` brought into [0, 1].
double wrapped(double x, double k, GltfWrap mode)
{
    const double f = x - k;
    return mode == GltfWrap::MirroredRepeat && std::fmod(std::abs(k), 2.0) == 1.0 ? 1.0 - f : f;
}
} // namespace

GltfWrap gltfWrap(int value)
{
    switch (value)
    {
    case 33648: return GltfWrap::MirroredRepeat;
    case 33071: return GltfWrap::ClampToEdge;
    default: return GltfWrap::Repeat;
    }
}

std::size_t wrapTexcoords(MeshData& mesh, std::vector<glm::dvec2>& st, GltfWrapModes modes)
{
    std::size_t spanning = 0;
    std::map<std::tuple<std::uint32_t, double, double>, std::uint32_t> copies; // (vertex, period s, period t)
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    {
        const std::uint32_t v[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
        const auto ks = period(st[v[0]].x, st[v[1]].x, st[v[2]].x, modes.s);
        const auto kt = period(st[v[0]].y, st[v[1]].y, st[v[2]].y, modes.t);
        if (!ks || !kt)
            ++spanning;
        const double shiftS = ks.value_or(0.0), shiftT = kt.value_or(0.0);
        if (shiftS == 0.0 && shiftT == 0.0)
            continue;
        for (int k = 0; k < 3; ++k)
        {
            const auto [it, added] =
                copies.try_emplace({v[k], shiftS, shiftT}, static_cast<std::uint32_t>(mesh.positions.size()));
            if (added)
            {
                mesh.positions.push_back(mesh.positions[v[k]]);
                if (!mesh.normals.empty())
                    mesh.normals.push_back(mesh.normals[v[k]]);
                st.push_back({ks ? wrapped(st[v[k]].x, shiftS, modes.s) : st[v[k]].x,
                              kt ? wrapped(st[v[k]].y, shiftT, modes.t) : st[v[k]].y});
            }
            mesh.indices[t + k] = it->second;
        }
    }
    return spanning;
}
} // namespace rt
