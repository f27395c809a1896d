// Triangle meshes written inline in a JSON scene file: flat arrays, three numbers per position and normal,
// two per uv, three indices per triangle (counter-clockwise front faces), optionally one material per
// triangle. Read without a JsonNode per number, so a million-triangle mesh loads in about a second.
#pragma once

#include <cstdint>
#include <functional>

#include "Scene/Scene.h"
#include "SceneFile/JsonNode.h"

namespace rt
{
/// `m` has "positions" and "indices", optionally "normals" and "uvs" (one per position) and
/// "triangle_materials" (one per triangle, each resolved by `materialRef`). Throws SceneError at the first
/// value that is not a finite number, an index out of range, or an array of the wrong length.
MeshData readInlineMesh(const JsonNode& m, const std::function<std::uint32_t(const JsonNode&)>& materialRef);
} // namespace rt
