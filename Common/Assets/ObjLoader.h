#pragma once

#include <string>

#include "Scene/Scene.h"

namespace rt
{
/// Loads the triangles of a Wavefront OBJ file (tinyobjloader; polygons are triangulated, materials of the
/// file are ignored: the scene assigns its own). `path` is resolved with resolveAsset. The positions come
/// back fitted (Assets/MeshFit.h: floor centre at the origin, fit height 1), computed in double from the
/// file's text, so the same shape loads the same wherever and at whatever size it was written.
/// Throws AssetError naming the file and the problem, with its line where it has one (Assets/ObjLines.h):
/// missing, unparsable, no triangles, a vertex index out of range (as written), a face of fewer than 3
/// vertices, a vertex of too few coordinates, a coordinate that is not a finite number, or a mesh that
/// cannot be fitted (every vertex one point).
/// With ObjPlacement::AsWritten the positions are the file's own, rounded to float (a scene file that places
/// its meshes itself); a coordinate beyond float's range is then an error too.
enum class ObjPlacement
{
    Fit,
    AsWritten
};
MeshData loadObj(const std::string& path, ObjPlacement placement = ObjPlacement::Fit);
} // namespace rt
