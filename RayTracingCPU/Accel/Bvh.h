// A binary bounding volume hierarchy built with the surface area heuristic over binned centroids
// (Wald, "On fast Construction of SAH-based Bounding Volume Hierarchies", RT'07), flattened depth-first so a
// node's first child follows it in memory (pbrt-v4's LinearBVHNode layout), 32 bytes per node.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "Math/Aabb.h"

namespace rt::cpu
{
struct BvhNode
{
    vec3 boundsMin;
    std::uint32_t offset; // leaf: first primitive slot; interior: index of the second child
    vec3 boundsMax;
    std::uint16_t count; // primitives in a leaf; 0 for an interior node
    std::uint16_t axis; // split axis of an interior node
};
static_assert(sizeof(BvhNode) == 32);

struct Bvh
{
    std::vector<BvhNode> nodes;
    /// Primitive slots in leaf order: order[k] is the index (in the builder's input) of slot k.
    std::vector<std::uint32_t> order;
    int maxDepth = 0;

    /// Builds over primitive bounds (world space). Leaves hold up to maxLeafSize primitives, more than four
    /// only where the SAH finds a leaf cheaper than a split (small scenes). An empty input gives an empty tree.
    static Bvh build(std::span<const Aabb> primitiveBounds, int maxLeafSize = 16);
};

} // namespace rt::cpu
