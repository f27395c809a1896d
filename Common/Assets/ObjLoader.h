#pragma once

#include <string>

#include "Scene/Scene.h"

namespace rt
{
/// Loads the triangles of a Wavefront OBJ file (tinyobjloader; polygons are triangulated, materials of the
/// file are ignored: the scene assigns its own). `path` is resolved with resolveAsset.
/// Throws AssetError naming the file and the problem: missing, unparsable, no triangles, a vertex index out
/// of range, a face of fewer than 3 vertices, or a non-finite coordinate.
MeshData loadObj(const std::string& path);
} // namespace rt
