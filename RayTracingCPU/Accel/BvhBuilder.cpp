#include <algorithm>
#include <array>
#include <numeric>

#include "Accel/Bvh.h"
#include "Geometry/Lanes.h"

namespace rt::cpu
{
namespace
{
constexpr int kBins = 16;
constexpr float kNodeCost = 2.0f; // a 4-wide node visit (box tests, sorting, stack) measured at ~2 packet tests
constexpr int kMaxSahDepth = 64; // below it, median splits: depth stays < 64 + 32 (Bvh4's traversal stack: 512)

float packets(std::uint32_t n) { return float((n + kLanes - 1) / kLanes); }

struct Builder
{
    std::span<const Aabb> bounds;
    std::vector<vec3> centroids;
    std::vector<std::uint32_t> indices;
    std::vector<BvhNode> nodes;
    int maxLeafSize;
    int maxDepth = 0;

    std::uint32_t build(std::uint32_t begin, std::uint32_t end, int depth)
    {
        maxDepth = std::max(maxDepth, depth);
        const auto nodeIndex = static_cast<std::uint32_t>(nodes.size());
        nodes.push_back({});
        Aabb box, centroidBox;
        for (std::uint32_t i = begin; i < end; ++i)
        {
            box.expand(bounds[indices[i]]);
            centroidBox.expand(centroids[indices[i]]);
        }
        nodes[nodeIndex].boundsMin = box.min;
        nodes[nodeIndex].boundsMax = box.max;
        const std::uint32_t count = end - begin;

        int axis = -1;
        std::uint32_t mid = begin;
        if (count > 4)
            findSplit(begin, end, box, centroidBox, depth, axis, mid);
        if (axis < 0)
        {
            makeLeaf(nodeIndex, begin, count);
            return nodeIndex;
        }
        nodes[nodeIndex].axis = static_cast<std::uint16_t>(axis);
        build(begin, mid, depth + 1);
        const std::uint32_t second = build(mid, end, depth + 1);
        nodes[nodeIndex].offset = second;
        nodes[nodeIndex].count = 0;
        return nodeIndex;
    }

    void makeLeaf(std::uint32_t nodeIndex, std::uint32_t begin, std::uint32_t count)
    {
        nodes[nodeIndex].offset = begin;
        nodes[nodeIndex].count = static_cast<std::uint16_t>(count);
    }

    /// Picks the cheapest binned SAH split over all three axes (the thesis' BVH never tried z when x was the
    /// longest: every axis is tried here). Leaves `axis` < 0 when a leaf is cheaper and allowed.
    void findSplit(std::uint32_t begin, std::uint32_t end, const Aabb& box, const Aabb& centroidBox, int depthNow,
                   int& axis, std::uint32_t& mid)
    {
        const std::uint32_t count = end - begin;
        float bestCost = kInfinity;
        int bestAxis = -1, bestSplit = -1;
        const vec3 extent = centroidBox.extent();
        for (int a = 0; a < 3; ++a)
        {
            if (!(extent[a] > 0.0f))
                continue;
            std::array<Aabb, kBins> binBox{};
            std::array<std::uint32_t, kBins> binCount{};
            const float scale = kBins / extent[a];
            for (std::uint32_t i = begin; i < end; ++i)
            {
                const int b = std::min(kBins - 1, static_cast<int>((centroids[indices[i]][a] - centroidBox.min[a]) * scale));
                binBox[b].expand(bounds[indices[i]]);
                ++binCount[b];
            }
            // Sweep from the right, then from the left, to cost every split between bins.
            std::array<float, kBins - 1> rightArea{};
            std::array<std::uint32_t, kBins - 1> rightCount{};
            Aabb acc;
            std::uint32_t n = 0;
            for (int b = kBins - 1; b > 0; --b)
            {
                acc.expand(binBox[b]);
                n += binCount[b];
                rightArea[b - 1] = acc.surfaceArea();
                rightCount[b - 1] = n;
            }
            acc = Aabb();
            n = 0;
            for (int b = 0; b < kBins - 1; ++b)
            {
                acc.expand(binBox[b]);
                n += binCount[b];
                if (n == 0 || rightCount[b] == 0)
                    continue;
                const float cost = acc.surfaceArea() * packets(n) + rightArea[b] * packets(rightCount[b]);
                if (cost < bestCost)
                {
                    bestCost = cost;
                    bestAxis = a;
                    bestSplit = b;
                }
            }
        }
        if (bestAxis < 0 || depthNow >= kMaxSahDepth)
        {
            // Coincident centroids (or a pathologically deep tree): a leaf if small, else split by count,
            // which bounds the remaining depth by log2(count).
            if (count > std::uint32_t(maxLeafSize))
                splitMiddle(begin, end, box, axis, mid);
            return;
        }
        // Leaves are tested kLanes primitives at a time (Packets.h): a leaf of n costs ceil(n/kLanes) tests,
        // a split one node visit plus its children's packets weighted by the chance of entering them. Small
        // leaves are kept when that is cheaper, which for a Cornell box means no tree at all.
        if (count <= std::uint32_t(maxLeafSize) && packets(count) <= kNodeCost + bestCost / box.surfaceArea())
            return;
        const float scale = kBins / extent[bestAxis];
        const float lo = centroidBox.min[bestAxis];
        auto* first = indices.data() + begin;
        auto* split = std::partition(first, indices.data() + end, [&](std::uint32_t i) {
            return std::min(kBins - 1, static_cast<int>((centroids[i][bestAxis] - lo) * scale)) <= bestSplit;
        });
        axis = bestAxis;
        mid = static_cast<std::uint32_t>(split - indices.data());
    }

    void splitMiddle(std::uint32_t begin, std::uint32_t end, const Aabb& box, int& axis, std::uint32_t& mid)
    {
        axis = box.longestAxis();
        mid = begin + (end - begin) / 2;
        std::nth_element(indices.data() + begin, indices.data() + mid, indices.data() + end,
                         [&](std::uint32_t x, std::uint32_t y) { return centroids[x][axis] < centroids[y][axis]; });
    }
};
} // namespace

Bvh Bvh::build(std::span<const Aabb> primitiveBounds, int maxLeafSize)
{
    Bvh bvh;
    if (primitiveBounds.empty())
        return bvh;
    Builder b;
    b.bounds = primitiveBounds;
    b.maxLeafSize = maxLeafSize;
    b.centroids.reserve(primitiveBounds.size());
    for (const Aabb& box : primitiveBounds)
        b.centroids.push_back(box.centroid());
    b.indices.resize(primitiveBounds.size());
    std::iota(b.indices.begin(), b.indices.end(), 0u);
    b.nodes.reserve(2 * primitiveBounds.size());
    b.build(0, static_cast<std::uint32_t>(primitiveBounds.size()), 1);
    bvh.nodes = std::move(b.nodes);
    bvh.order = std::move(b.indices);
    bvh.maxDepth = b.maxDepth;
    return bvh;
}
} // namespace rt::cpu
