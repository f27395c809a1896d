// glTF's texture wrapping (glTF 2.0 spec §3.8.4 "Samplers": REPEAT, the default, MIRRORED_REPEAT, CLAMP_TO_EDGE)
// for engines whose image textures clamp: a triangle whose texture coordinates lie within one period of the
// pattern is moved (and, for an odd period of MIRRORED_REPEAT, mirrored) into [0, 1], where clamping and
// wrapping agree. Vertices shared by triangles moved by different periods are copied. A triangle that spans more
// than one period cannot be expressed so and is left to the clamp.
#pragma once

#include <cstddef>
#include <vector>

#include "Scene/Scene.h"

namespace rt
{
enum class GltfWrap
{
    Repeat, // 10497
    MirroredRepeat, // 33648
    ClampToEdge // 33071
};

struct GltfWrapModes
{
    GltfWrap s = GltfWrap::Repeat;
    GltfWrap t = GltfWrap::Repeat;
};

/// The wrap mode of a sampler's wrapS or wrapT value (an unknown value reads as REPEAT, the default).
GltfWrap gltfWrap(int value);

/// Moves each triangle of `mesh` into [0, 1]^2 by whole periods of `modes` as described above, `st` being the
/// mesh's texture coordinates as glTF writes them (one pair per position; s right, t down the image). Copies
/// vertices (position, normal, st) where triangles sharing them move differently. Returns how many triangles
/// span more than one period (left as they are).
std::size_t wrapTexcoords(MeshData& mesh, std::vector<glm::dvec2>& st, GltfWrapModes modes);
} // namespace rt
