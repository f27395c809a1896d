// A line-by-line check of the OBJ statements tinyobjloader reads leniently: it parses `nan`, `inf` and
// missing coordinates as 0, drops faces of fewer than three vertices, and reports out-of-range indices after
// converting them (relative indices resolved, one subtracted). This scanner holds the file to the format and
// names the line of the first problem; it also keeps the positions in double, as written, so that the mesh
// can be fitted into a scene before anything is rounded to float (Assets/MeshFit.h).
#pragma once

#include <filesystem>
#include <vector>

#include "Math/Math.h"

namespace rt
{
/// What the scan of a valid OBJ file found.
struct ObjLines
{
    std::vector<dvec3> positions; // one per `v` statement, in file order (the w or colour values dropped)
    std::size_t normals = 0; // `vn` statements
    std::size_t texcoords = 0; // `vt` statements
};

/// Scans `file` (which exists): every `v` has 3, 4 (x y z w) or 6 (x y z r g b) numbers, every `vn` 3, every
/// `vt` 1 to 3, all of them finite; every `f` has at least 3 vertices, each `v`, `v/t`, `v//n` or `v/t/n` of
/// integer indices in range (1..count, or -1..-count counting back from the statement). Other statements
/// are left to tinyobjloader. Throws AssetError "malformed OBJ '<file>': line N: <problem>", quoting an
/// index as written in the file (of positive indices out of range, the largest of its kind).
ObjLines scanObjLines(const std::filesystem::path& file);
} // namespace rt
