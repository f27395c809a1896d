// glTF meshes (glTF 2.0 spec §3.7.2 "Meshes") as the scene's triangle meshes: every primitive of every node's
// mesh becomes one MeshData in the world group, its vertices carried to world space by the node's transform
// (in double, then rounded to float once), so both engines get the geometry the file places.
#pragma once

#include <cstddef>
#include <vector>

#include "Math/Aabb.h"
#include "SceneFile/GltfMaterials.h"
#include "SceneFile/GltfNodes.h"

namespace rt
{
struct GltfMeshSummary
{
    std::size_t triangles = 0;
    std::size_t primitives = 0; // those read (a skipped mode or extension is not counted)
    glm::dvec3 boundsMin{std::numeric_limits<double>::infinity()}; // world space, of every vertex read
    glm::dvec3 boundsMax{-std::numeric_limits<double>::infinity()};
};

/// Adds the primitives of every mesh among `nodes` to `builder`'s world group:
///   - modes TRIANGLES (the default), TRIANGLE_STRIP and TRIANGLE_FAN, indexed (unsigned 8, 16 or 32-bit indices)
///     or not; POINTS and LINE* primitives are skipped and noted;
///   - POSITION (required), NORMAL (carried by the inverse transpose, normalised) and TEXCOORD_0 (v flipped: glTF's
///     v runs down the image, the engines' up; on a textured material each triangle moved into [0, 1] by whole
///     periods of its sampler's wrapping, GltfTexcoords.h) where present;
///   - a node whose transform mirrors (negative determinant) has its triangles' winding reversed (§3.7.2.1), so
///     that front faces stay counter-clockwise;
///   - a vertex that lands beyond float's range is an error.
/// Notes what it cannot map: other modes, morph targets, vertex colours, skins, compressed primitives (Draco,
/// meshopt), zero-length normals (dropped), texture coordinates repeating within one triangle (the engines
/// clamp).
/// Throws SceneError naming the value: a mesh or material index out of range, a primitive without POSITION, an
/// attribute whose count differs from POSITION's, a coordinate that is not finite; and whatever the accessors
/// throw (GltfAccessors.h).
GltfMeshSummary addGltfMeshes(const GltfDocument& doc, const std::vector<GltfPlacedNode>& nodes,
                              GltfMaterials& materials, SceneBuilder& builder, GltfNotes& notes);
} // namespace rt
