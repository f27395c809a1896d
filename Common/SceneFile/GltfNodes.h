// The node hierarchy of a glTF scene (glTF 2.0 spec §3.5.2 "Nodes and Hierarchy", §3.5.3 "Transformations"):
// each node's world transform, composed in double from the root down.
#pragma once

#include <vector>

#include <glm/mat4x4.hpp>

#include "SceneFile/GltfFile.h"

namespace rt
{
/// A node met in the walk, with the transform from its own frame to the scene's (glTF's frame: +Y up, metres,
/// right-handed; the renderer takes glTF's units and axes as they are).
struct GltfPlacedNode
{
    int node = -1;
    glm::dmat4 worldFromNode{1.0};
};

/// The node's local transform: its `matrix` (column-major), or T * R * S from `translation`, `rotation` (a unit
/// quaternion x, y, z, w; normalised here) and `scale`. Throws SceneError naming the node's value for an array of
/// the wrong length or a number that is not finite, a zero quaternion.
glm::dmat4 gltfLocalTransform(const GltfDocument& doc, int node);

/// Every node of the scene to render, depth first in the order the file lists them, parents before children:
/// the document's `scene`, else scene 0, else (a file without scenes) every node that is no node's child.
/// Throws SceneError for a scene or node index out of range, and for a node reached twice (a cycle, or a node
/// with two parents: the spec requires disjoint trees).
std::vector<GltfPlacedNode> gltfSceneNodes(const GltfDocument& doc);
} // namespace rt
