#include "Accel/Bvh4.h"

#include <algorithm>

#include "Error.h"

namespace rt::cpu
{
namespace
{
struct Collapser
{
    const Bvh& in;
    std::vector<Bvh4Node> out;

    float area(std::uint32_t n) const { return Aabb(in.nodes[n].boundsMin, in.nodes[n].boundsMax).surfaceArea(); }

    /// Writes the 4-wide node for binary interior node `n`; returns its index.
    std::uint32_t emit(std::uint32_t n)
    {
        // Open the largest interior grandchild until four children are gathered (Dammertz et al. §3).
        std::uint32_t children[4] = {n + 1, in.nodes[n].offset, 0, 0};
        int count = 2;
        while (count < 4)
        {
            int best = -1;
            for (int i = 0; i < count; ++i)
                if (in.nodes[children[i]].count == 0 && (best < 0 || area(children[i]) > area(children[best])))
                    best = i;
            if (best < 0)
                break;
            const std::uint32_t opened = children[best];
            children[best] = opened + 1;
            children[count++] = in.nodes[opened].offset;
        }
        const auto index = static_cast<std::uint32_t>(out.size());
        out.emplace_back();
        Bvh4Node node{};
        for (int i = 0; i < 4; ++i)
        {
            if (i >= count)
            {
                node.minX[i] = node.minY[i] = node.minZ[i] = 0.0f;
                node.maxX[i] = node.maxY[i] = node.maxZ[i] = 0.0f;
                continue;
            }
            const BvhNode& c = in.nodes[children[i]];
            node.minX[i] = c.boundsMin.x;
            node.minY[i] = c.boundsMin.y;
            node.minZ[i] = c.boundsMin.z;
            node.maxX[i] = c.boundsMax.x;
            node.maxY[i] = c.boundsMax.y;
            node.maxZ[i] = c.boundsMax.z;
            node.validMask |= 1u << i;
            if (c.count > 0)
            {
                if (c.offset > 0x00FFFFFFu || c.count > 0x7Fu)
                    throw SceneError("scene too large for the 4-wide BVH (over 16 million leaf packets)");
                node.child[i] = leafRef(c.offset, c.count);
            }
            else
                node.child[i] = emit(children[i]);
        }
        out[index] = node;
        return index;
    }
};
} // namespace

Bvh4 Bvh4::collapse(const Bvh& bvh)
{
    Bvh4 result;
    if (bvh.nodes.empty())
    {
        result.rootIsLeaf = true;
        return result;
    }
    if (bvh.nodes[0].count > 0)
    {
        result.rootIsLeaf = true;
        result.rootCount = bvh.nodes[0].count;
        return result;
    }
    Collapser c{bvh, {}};
    c.out.reserve(bvh.nodes.size() / 2 + 1);
    c.emit(0);
    result.nodes = std::move(c.out);
    return result;
}
} // namespace rt::cpu
