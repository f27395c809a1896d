// The 4-wide BVH traversed by kLanes rays at once: masked packet traversal (Wald, Slusallek, Benthin & Wagner,
// "Interactive Rendering with Coherent Ray Tracing", EG 2001; the active-mask form of Embree's rtcIntersect8).
// Each node tests all the lanes' rays against each child box in one pass, a child is visited with the mask of
// the rays that enter it, and a leaf tests every primitive against all lanes (Geometry/RayPackets.h). A ray takes
// the boxes it would take alone (the same slab arithmetic as Accel/Bvh4.h, NaN planes ignored alike) and more:
// a leaf is tested for all lanes once any of them enters it. So each ray finds the nearest hit its scalar
// traversal finds; only where two primitives meet it at exactly the same t may the other of the two win, as
// the leaves come in another order.
#pragma once

#include <bit>
#include <cstdint>

#include "Accel/Bvh4.h"
#include "Geometry/Lanes.h"
#include "Geometry/RayPackets.h"

namespace rt::cpu
{
/// A subtree entered by this many of the lanes' rays or fewer is traversed by each of them alone: a packet
/// whose rays have gone apart pays a box test per lane for one ray's work (the hybrid of Benthin, Wald, Woop,
/// Ernst & Mark, "Combining Single and Packet-Ray Tracing for Arbitrary Ray Distributions on the Intel MIC
/// Architecture", IEEE TVCG 18(9), 2012).
inline constexpr int kLanesAloneAtMost = kLanes / 4;

/// Visits the leaves that the rays of `rays.active` enter before their hits' t (read again after every leaf),
/// roughly nearest first. `leaf(firstSlot, count)` tests the primitives for every lane and may shrink `hitT`;
/// `alone(lane, ref)` traverses the subtree `ref` (Accel/Bvh4.h's traverseFrom) for lane `lane` alone, where
/// few lanes enter it.
template <typename LeafFn, typename AloneFn>
inline void traverseLanes(const Bvh4& bvh, const BoxLaneView& rays, const Lanes& hitT, LeafFn&& leaf, AloneFn&& alone)
{
    if (rays.active == 0)
        return;
    if (bvh.rootIsLeaf)
    {
        if (bvh.rootCount)
            leaf(0u, bvh.rootCount);
        return;
    }
    if (bvh.nodes.empty())
        return;
    struct alignas(32) Entry
    {
        Lanes enter; // where each lane's ray enters the box: a lane whose hit is nearer drops out on pop
        std::uint32_t ref;
        int mask;
        float key; // the nearest entry among the lanes that enter: the order children are visited in
    };
    Entry stack[320]; // depth < 96 (BvhBuilder.cpp), at most 3 entries left per level and 4 written: < 292
    int top = 0;
    std::uint32_t index = 0;
    int mask = rays.active;
    const Bvh4Node* nodes = bvh.nodes.data();
    const Lanes zero(0.0f), widen(1.0000004f), infinity(kInfinity); // widen: 1 + 2 gamma(3), as Bvh4.h
    for (;;)
    {
        const Bvh4Node& node = nodes[index];
        Entry hits[4];
        int n = 0;
        const Lanes tMax = hitT;
        for (int i = 0; i < 4; ++i)
        {
            if (!(node.validMask >> i & 1))
                continue;
            const Lanes loX(node.minX[i]), loY(node.minY[i]), loZ(node.minZ[i]);
            const Lanes hiX(node.maxX[i]), hiY(node.maxY[i]), hiZ(node.maxZ[i]);
            const Lanes nearX = (select(rays.negX, hiX, loX) - rays.ox) * rays.ix;
            const Lanes nearY = (select(rays.negY, hiY, loY) - rays.oy) * rays.iy;
            const Lanes nearZ = (select(rays.negZ, hiZ, loZ) - rays.oz) * rays.iz;
            const Lanes farX = (select(rays.negX, loX, hiX) - rays.ox) * rays.ix;
            const Lanes farY = (select(rays.negY, loY, hiY) - rays.oy) * rays.iy;
            const Lanes farZ = (select(rays.negZ, loZ, hiZ) - rays.oz) * rays.iz;
            // max and min return their second operand when the first is NaN (0 * inf on a slab plane): ignored.
            const Lanes enter = max(nearX, max(nearY, max(nearZ, zero)));
            const Lanes exit = min(farX, min(farY, min(farZ, tMax))) * widen;
            const Lanes enters = (enter <= exit) & rays.valid;
            const int m = movemask(enters) & mask;
            if (m == 0)
                continue;
            Entry e;
            e.enter = enter;
            e.ref = node.child[i];
            e.mask = m;
            e.key = horizontalMin(select(enters, enter, infinity))[0];
            // Pushed farthest first (insertion sort of <= 4), so the nearest pops next.
            int k = n++;
            for (; k > 0 && hits[k - 1].key < e.key; --k)
                hits[k] = hits[k - 1];
            hits[k] = e;
        }
        for (int k = 0; k < n; ++k)
            stack[top++] = hits[k];
        // Pop: a lane leaves an entry once its hit lies before the box; leaves are tested as they come off.
        for (;;)
        {
            if (top == 0)
                return;
            const Entry& e = stack[--top];
            int m = e.mask & movemask(e.enter <= hitT);
            if (m == 0)
                continue;
            if (std::popcount(static_cast<unsigned>(m)) <= kLanesAloneAtMost)
            {
                for (; m; m &= m - 1)
                    alone(std::countr_zero(static_cast<unsigned>(m)), e.ref);
                continue;
            }
            if (!isLeaf(e.ref))
            {
                index = e.ref;
                mask = m;
                break;
            }
            leaf(leafFirst(e.ref), leafCount(e.ref));
        }
    }
}
} // namespace rt::cpu
