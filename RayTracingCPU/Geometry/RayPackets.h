// kLanes rays at once against one primitive, the rays in the lanes: the transpose of Packets.h (one ray against
// kLanes primitives). For a scene that is one small BVH leaf every ray tests every primitive, and a lane of
// rays pays no lane for padding nor a horizontal min per packet: 12.7 ns per ray against 33.1 on book 3's
// final scene (rt_bench --benchmark_filter=ClosestHit, docs/notebook/PERFORMANCE.md §1). Integrator/PathStream.h
// traces paths this way.
// Each lane runs the primitive packets' own lane test (Packets.h's detail::quadLanes, sphereLanes) for its
// ray, and the lanes keep the nearest hit with the primitives taken in the packets' order (the first of equal
// t wins), so a ray finds the hit Packets.h finds, bit for bit.
#pragma once

#include <bit>
#include <cstdint>
#include <limits>

#include "Geometry/Packets.h"
#include "Geometry/TraceRay.h"
#include "Shared/HostDevice.h"

namespace rt::cpu
{
/// The lanes' rays as box tests read them: origins and inverse directions, and which lanes hold a ray.
struct BoxLaneView
{
    Lanes ox, oy, oz;
    Lanes ix, iy, iz; // 1 / d, +-inf where a component is 0
    Lanes negX, negY, negZ; // masks: the direction is negative along the axis (its near slab is the box's max)
    Lanes valid; // mask: the lane holds a ray
    int active; // movemask(valid)
};

/// kLanes rays, structure of arrays: what the quad and sphere tests read of a TraceRay. A lane without a ray
/// holds NaN directions and finds nothing.
struct alignas(32) RayLanes
{
    float ox[kLanes], oy[kLanes], oz[kLanes];
    float dx[kLanes], dy[kLanes], dz[kLanes];
    float time[kLanes];
    float directionLength2[kLanes];
    float invDirectionLength2[kLanes];

    void set(int lane, const TraceRay& r)
    {
        ox[lane] = r.origin.x;
        oy[lane] = r.origin.y;
        oz[lane] = r.origin.z;
        dx[lane] = r.direction.x;
        dy[lane] = r.direction.y;
        dz[lane] = r.direction.z;
        time[lane] = r.time;
        directionLength2[lane] = r.directionLength2;
        invDirectionLength2[lane] = r.invDirectionLength2;
    }
    void clear(int lane)
    {
        ox[lane] = oy[lane] = oz[lane] = 0.0f;
        dx[lane] = dy[lane] = dz[lane] = std::numeric_limits<float>::quiet_NaN();
        time[lane] = directionLength2[lane] = invDirectionLength2[lane] = 0.0f;
    }
    /// The rays in registers, as the lane tests read them.
    RayLaneView view() const
    {
        return {Lanes::load(ox), Lanes::load(oy),   Lanes::load(oz),
                Lanes::load(dx), Lanes::load(dy),   Lanes::load(dz),
                Lanes::load(time), Lanes::load(directionLength2), Lanes::load(invDirectionLength2)};
    }
    /// Lane l's ray as a scalar traversal reads it (a scene of quads and spheres: no triangle or medium fields).
    TraceRay ray(int l) const
    {
        return TraceRay(Ray{vec3(ox[l], oy[l], oz[l]), vec3(dx[l], dy[l], dz[l]), time[l]},
                        TraceRay::Needs{.triangles = false, .media = false, .boxes = true});
    }
    /// The rays as the box tests read them: 1 / d as TraceRay computes it, the same bits.
    BoxLaneView boxView() const
    {
        const Lanes dxs = Lanes::load(dx), dys = Lanes::load(dy), dzs = Lanes::load(dz), one(1.0f), zero(0.0f);
        const Lanes ixs = one / dxs, iys = one / dys, izs = one / dzs;
        const Lanes valid = dxs == dxs; // a cleared lane's NaN direction
        return {Lanes::load(ox), Lanes::load(oy), Lanes::load(oz), ixs, iys, izs,
                ixs < zero, iys < zero, izs < zero, valid, movemask(valid)};
    }
};

/// The nearest hit of each lane's ray so far: HitRecord's fields, lane by lane (prim kNoIndex: none).
struct RayHits
{
    Lanes t, b1, b2;
    Lanes prim; // PrimRef bits, as float bit patterns

    explicit RayHits(float tMax) : RayHits(Lanes(tMax)) {}
    explicit RayHits(Lanes tMax) : t(tMax), b1(0.0f), b2(0.0f), prim(std::bit_cast<float>(shader::kNoIndex)) {}
    /// Every lane's hit as a HitRecord.
    void store(HitRecord (&out)[kLanes]) const
    {
        alignas(32) float lanes[4][kLanes];
        t.storeTo(lanes[0]);
        b1.storeTo(lanes[1]);
        b2.storeTo(lanes[2]);
        prim.storeTo(lanes[3]);
        for (int i = 0; i < kLanes; ++i)
            out[i] = {lanes[0][i], std::bit_cast<std::uint32_t>(lanes[3][i]), lanes[1][i], lanes[2][i]};
    }
    /// Lane l's hit.
    HitRecord lane(int l) const
    {
        HitRecord all[kLanes];
        store(all);
        return all[l];
    }
    /// Lane l's hit becomes h.
    void setLane(int l, const HitRecord& h)
    {
        alignas(32) float lanes[4][kLanes];
        t.storeTo(lanes[0]);
        b1.storeTo(lanes[1]);
        b2.storeTo(lanes[2]);
        prim.storeTo(lanes[3]);
        lanes[0][l] = h.t;
        lanes[1][l] = h.b1;
        lanes[2][l] = h.b2;
        lanes[3][l] = std::bit_cast<float>(h.prim);
        t = Lanes::load(lanes[0]);
        b1 = Lanes::load(lanes[1]);
        b2 = Lanes::load(lanes[2]);
        prim = Lanes::load(lanes[3]);
    }
    /// Where h.mask is set, h's hit with primitive primBits becomes the lane's nearest.
    void take(const LaneHits& h, std::uint32_t primBits)
    {
        t = select(h.mask, h.t, t);
        b1 = select(h.mask, h.b1, b1);
        b2 = select(h.mask, h.b2, b2);
        prim = select(h.mask, Lanes(std::bit_cast<float>(primBits)), prim);
    }
};

/// The lanes' rays against lane `i` of a quad packet: intersectPacket(QuadPacket)'s arithmetic for each ray.
inline void intersectRays(const QuadPacket& p, int i, const RayLaneView& r, float tMin, RayHits& hits)
{
    const QuadLaneView q{Lanes(p.qx[i]),  Lanes(p.qy[i]),  Lanes(p.qz[i]),  Lanes(p.nx[i]), Lanes(p.ny[i]),
                         Lanes(p.nz[i]),  Lanes(p.d[i]),   Lanes(p.uax[i]), Lanes(p.uay[i]), Lanes(p.uaz[i]),
                         Lanes(p.vbx[i]), Lanes(p.vby[i]), Lanes(p.vbz[i])};
    hits.take(detail::quadLanes(q, r, tMin, hits.t), p.prim[i]);
}

/// The lanes' rays against lane `i` of a sphere packet: intersectPacket(SpherePacket)'s arithmetic for each
/// ray.
inline void intersectRays(const SpherePacket& p, int i, const RayLaneView& r, float tMin, RayHits& hits)
{
    const SphereLaneView s{Lanes(p.cx[i]), Lanes(p.cy[i]), Lanes(p.cz[i]),      Lanes(p.vx[i]),
                           Lanes(p.vy[i]), Lanes(p.vz[i]), Lanes(p.radius2[i]), Lanes(p.radius[i])};
    LaneHits h;
    if (detail::sphereLanes(s, r, tMin, hits.t, h))
        hits.take(h, p.prim[i]);
}
} // namespace rt::cpu
