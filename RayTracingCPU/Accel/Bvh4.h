// A 4-wide BVH collapsed from the binary SAH tree, laid out structure-of-arrays so one SSE pass tests a ray
// against all four child boxes (Wald, Benthin & Boulos, "Getting Rid of Packets", RT'08; Dammertz et al.,
// "Shallow Bounding Volume Hierarchies for Fast SIMD Ray Tracing of Incoherent Rays", EGSR 2008).
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <vector>

#include "Accel/Bvh.h"
#include "Geometry/TraceRay.h"

#if defined(__SSE2__) || defined(_M_X64)
#include <immintrin.h>
#define RT_BVH4_SSE 1
#endif

namespace rt::cpu
{
struct alignas(64) Bvh4Node
{
    float minX[4], minY[4], minZ[4];
    float maxX[4], maxY[4], maxZ[4];
    std::uint32_t child[4]; // an interior node index, or a leaf reference (see leafRef)
    std::uint32_t validMask; // bit i set if child i exists
};

/// A leaf packed in a child reference: the top bit marks it, then 7 bits of count and 24 of first slot.
constexpr std::uint32_t kLeafBit = 0x80000000u;
constexpr std::uint32_t leafRef(std::uint32_t first, std::uint32_t count) { return kLeafBit | (count << 24) | first; }
constexpr bool isLeaf(std::uint32_t ref) { return (ref & kLeafBit) != 0; }
constexpr std::uint32_t leafFirst(std::uint32_t ref) { return ref & 0x00FFFFFFu; }
constexpr std::uint32_t leafCount(std::uint32_t ref) { return (ref >> 24) & 0x7Fu; }

struct Bvh4
{
    std::vector<Bvh4Node> nodes;
    bool rootIsLeaf = false; // a scene of <= maxLeafSize primitives: no node, one leaf
    std::uint32_t rootCount = 0;

    /// Collapses a binary BVH (same primitive slots).
    static Bvh4 collapse(const Bvh& bvh);
};

/// traverse() below the child reference `start` (an interior node index or a leaf reference) alone.
template <typename LeafFn>
inline void traverseFrom(const Bvh4& bvh, std::uint32_t start, const TraceRay& r, const float& tMax, LeafFn&& leaf)
{
    if (isLeaf(start))
    {
        leaf(leafFirst(start), leafCount(start));
        return;
    }
    struct Entry
    {
        std::uint32_t ref; // interior node index or leafRef
        float tNear; // where the ray enters the child's box: skipped on pop if a hit is already nearer
    };
    Entry stack[512]; // 4-wide depth < 96 (see the binary builder), at most 3 entries left per level, 4 written
    int top = 0;
    std::uint32_t index = start;
    const Bvh4Node* nodes = bvh.nodes.data();
#ifdef RT_BVH4_SSE
    const __m128 ox = _mm_set1_ps(r.origin.x), oy = _mm_set1_ps(r.origin.y), oz = _mm_set1_ps(r.origin.z);
    const __m128 ix = _mm_set1_ps(r.invDirection.x), iy = _mm_set1_ps(r.invDirection.y),
                 iz = _mm_set1_ps(r.invDirection.z);
    // The near slab of a box is its max plane when the direction is negative along that axis.
    const int nx = r.directionNegative[0] ? 12 : 0, ny = r.directionNegative[1] ? 12 : 0,
              nz = r.directionNegative[2] ? 12 : 0;
#endif
    for (;;)
    {
        const Bvh4Node& node = nodes[index];
        alignas(16) float tNear[4];
        int mask;
#ifdef RT_BVH4_SSE
        const float* base = node.minX;
        const __m128 nearX = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(base + nx), ox), ix);
        const __m128 nearY = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(base + 4 + ny), oy), iy);
        const __m128 nearZ = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(base + 8 + nz), oz), iz);
        const __m128 farX = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(base + 12 - nx), ox), ix);
        const __m128 farY = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(base + 16 - ny), oy), iy);
        const __m128 farZ = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(base + 20 - nz), oz), iz);
        // maxps/minps return the second operand when the first is NaN (0 * inf on a slab plane): ignored.
        const __m128 enter = _mm_max_ps(nearX, _mm_max_ps(nearY, _mm_max_ps(nearZ, _mm_setzero_ps())));
        const __m128 exit = _mm_mul_ps(_mm_min_ps(farX, _mm_min_ps(farY, _mm_min_ps(farZ, _mm_set1_ps(tMax)))),
                                       _mm_set1_ps(1.0000004f)); // conservative: 1 + 2 gamma(3)
        mask = _mm_movemask_ps(_mm_cmple_ps(enter, exit)) & static_cast<int>(node.validMask);
        _mm_store_ps(tNear, enter);
#else
        mask = 0;
        for (int i = 0; i < 4; ++i)
        {
            const vec3 lo(node.minX[i], node.minY[i], node.minZ[i]), hi(node.maxX[i], node.maxY[i], node.maxZ[i]);
            const vec3 t0 = (lo - r.origin) * r.invDirection, t1 = (hi - r.origin) * r.invDirection;
            const vec3 tn = glm::min(t0, t1), tf = glm::max(t0, t1);
            tNear[i] = maxf(tn.x, maxf(tn.y, maxf(tn.z, 0.0f)));
            const float e = minf(tf.x, minf(tf.y, minf(tf.z, tMax))) * 1.0000004f;
            if (tNear[i] <= e && (node.validMask >> i & 1))
                mask |= 1 << i;
        }
#endif
        if (mask != 0)
        {
            const int first = std::countr_zero(static_cast<unsigned>(mask));
            mask &= mask - 1;
            if (mask == 0)
            {
                // One child hit (the common case deep in the tree): no sorting, no stack traffic.
                const std::uint32_t ref = node.child[first];
                if (!isLeaf(ref))
                {
                    index = ref;
                    continue;
                }
                leaf(leafFirst(ref), leafCount(ref));
            }
            else
            {
                // Push the hit children farthest first (insertion sort of <= 4) so the nearest pops next.
                Entry hits[4] = {{node.child[first], tNear[first]}};
                int n = 1;
                do
                {
                    const int i = std::countr_zero(static_cast<unsigned>(mask));
                    mask &= mask - 1;
                    const Entry e{node.child[i], tNear[i]};
                    int k = n++;
                    for (; k > 0 && hits[k - 1].tNear < e.tNear; --k)
                        hits[k] = hits[k - 1];
                    hits[k] = e;
                } while (mask);
                // All four entries in one store, then the n that count: a copy of n entries compiled to
                // `rep movsq`, whose start-up cost took 2-7 % of a render (perf, rtnw-final).
                std::memcpy(stack + top, hits, sizeof hits);
                top += n;
            }
        }
        // Pop: leaves are tested as they come off the stack, children behind the nearest hit are dropped.
        for (;;)
        {
            if (top == 0)
                return;
            const Entry e = stack[--top];
            if (e.tNear > tMax)
                continue;
            if (!isLeaf(e.ref))
            {
                index = e.ref;
                break;
            }
            leaf(leafFirst(e.ref), leafCount(e.ref));
        }
    }
}

/// Visits the leaves whose boxes the ray enters before tMax (read again after every leaf), nearest first.
/// `leaf(firstSlot, count)` tests the primitives and may shrink tMax.
template <typename LeafFn>
inline void traverse(const Bvh4& bvh, const TraceRay& r, const float& tMax, LeafFn&& leaf)
{
    if (bvh.rootIsLeaf)
    {
        if (bvh.rootCount)
            leaf(0u, bvh.rootCount);
        return;
    }
    if (!bvh.nodes.empty())
        traverseFrom(bvh, 0u, r, tMax, leaf);
}
} // namespace rt::cpu
