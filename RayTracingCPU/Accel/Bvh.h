// A binary bounding volume hierarchy built with the surface area heuristic over binned centroids
// (Wald, "On fast Construction of SAH-based Bounding Volume Hierarchies", RT'07), flattened depth-first so a
// node's first child follows it in memory (pbrt-v4's LinearBVHNode layout), 32 bytes per node.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "Geometry/TraceRay.h"
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

/// Slab test against the node bounds within (0, tMax). The far distance is enlarged by 1 + 2 gamma(3) so the
/// test stays conservative under rounding (pbrt-v4 Bounds3::IntersectP), which the watertight triangle
/// test needs.
inline bool hitsBox(const BvhNode& n, const TraceRay& r, float tMax)
{
    const vec3 t0 = (n.boundsMin - r.origin) * r.invDirection;
    const vec3 t1 = (n.boundsMax - r.origin) * r.invDirection;
    const vec3 tNear = glm::min(t0, t1);
    const vec3 tFar = glm::max(t0, t1);
    // A NaN slab (0 * inf: origin on a slab plane of a flat box) is ignored: minf/maxf return the 2nd operand.
    const float enter = maxf(tNear.x, maxf(tNear.y, maxf(tNear.z, 0.0f)));
    const float exit = minf(tFar.x, minf(tFar.y, minf(tFar.z, tMax))) * 1.0000004f;
    return enter <= exit;
}

/// Visits the leaves whose boxes the ray enters before hit.t, nearer child first along the split axis.
/// `leaf(firstSlot, count)` tests primitives and shrinks hit.t; traversal culls with the current hit.t.
template <typename LeafFn>
inline void traverse(const Bvh& bvh, const TraceRay& r, const float& tMax, LeafFn&& leaf)
{
    if (bvh.nodes.empty())
        return;
    std::uint32_t stack[128];
    int top = 0;
    std::uint32_t index = 0;
    const BvhNode* nodes = bvh.nodes.data();
    for (;;)
    {
        const BvhNode& node = nodes[index];
        if (hitsBox(node, r, tMax))
        {
            if (node.count > 0)
            {
                leaf(node.offset, node.count);
                if (top == 0)
                    return;
                index = stack[--top];
            }
            else if (r.directionNegative[node.axis])
            {
                stack[top++] = index + 1;
                index = node.offset;
            }
            else
            {
                stack[top++] = node.offset;
                index = index + 1;
            }
        }
        else
        {
            if (top == 0)
                return;
            index = stack[--top];
        }
    }
}
} // namespace rt::cpu
