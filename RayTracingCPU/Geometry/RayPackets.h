// kLanes rays at once against one primitive, the rays in the lanes: the transpose of Packets.h (one ray against
// kLanes primitives). For a scene that is one small BVH leaf every ray tests every primitive, and a lane of
// rays pays no lane for padding nor a horizontal min per packet: 12.7 ns per ray against 33.1 on book 3's
// final scene (rt_bench --benchmark_filter=ClosestHit, docs/PERFORMANCE.md §1). Integrator/PathStream.h
// traces paths this way.
// Each lane computes what the primitive packets compute for its ray, operation for operation, and the lanes
// keep the nearest hit with the primitives taken in the packets' order (the first of equal t wins), so a ray
// finds the hit Packets.h finds, bit for bit.
#pragma once

#include <bit>
#include <cstdint>
#include <limits>

#include "Geometry/Packets.h"
#include "Geometry/TraceRay.h"
#include "Shared/HostDevice.h"

namespace rt::cpu
{
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
};

/// The nearest hit of each lane's ray so far: HitRecord's fields, lane by lane (prim kNoIndex: none).
struct RayHits
{
    Lanes t, b1, b2;
    Lanes prim; // PrimRef bits, as float bit patterns

    explicit RayHits(float tMax)
        : t(tMax), b1(0.0f), b2(0.0f), prim(std::bit_cast<float>(shader::kNoIndex))
    {
    }
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
    void take(Lanes mask, Lanes tHit, Lanes alpha, Lanes beta, std::uint32_t primBits)
    {
        t = select(mask, tHit, t);
        b1 = select(mask, alpha, b1);
        b2 = select(mask, beta, b2);
        prim = select(mask, Lanes(std::bit_cast<float>(primBits)), prim);
    }
};

/// The lanes' rays against lane `i` of a quad packet: intersectPacket(QuadPacket) for each ray.
inline void intersectRays(const QuadPacket& p, int i, const RayLanes& r, float tMin, RayHits& hits)
{
    const Lanes nx(p.nx[i]), ny(p.ny[i]), nz(p.nz[i]);
    const Lanes dx = Lanes::load(r.dx), dy = Lanes::load(r.dy), dz = Lanes::load(r.dz);
    const Lanes ox = Lanes::load(r.ox), oy = Lanes::load(r.oy), oz = Lanes::load(r.oz);
    const Lanes denom = nx * dx + ny * dy + nz * dz;
    const Lanes t = (Lanes(p.d[i]) - (nx * ox + ny * oy + nz * oz)) / denom;
    Lanes mask = (t > Lanes(tMin)) & (t < hits.t) & (abs(denom) >= Lanes(1e-12f));
    const Lanes px = ox + t * dx - Lanes(p.qx[i]);
    const Lanes py = oy + t * dy - Lanes(p.qy[i]);
    const Lanes pz = oz + t * dz - Lanes(p.qz[i]);
    const Lanes alpha = px * Lanes(p.uax[i]) + py * Lanes(p.uay[i]) + pz * Lanes(p.uaz[i]);
    const Lanes beta = px * Lanes(p.vbx[i]) + py * Lanes(p.vby[i]) + pz * Lanes(p.vbz[i]);
    const Lanes zero(0.0f), one(1.0f);
    mask = mask & (alpha >= zero) & (alpha <= one) & (beta >= zero) & (beta <= one);
    hits.take(mask, t, alpha, beta, p.prim[i]);
}

/// The lanes' rays against lane `i` of a sphere packet: intersectPacket(SpherePacket) for each ray.
inline void intersectRays(const SpherePacket& p, int i, const RayLanes& r, float tMin, RayHits& hits)
{
    const Lanes time = Lanes::load(r.time);
    const Lanes fx = Lanes::load(r.ox) - (Lanes(p.cx[i]) + time * Lanes(p.vx[i]));
    const Lanes fy = Lanes::load(r.oy) - (Lanes(p.cy[i]) + time * Lanes(p.vy[i]));
    const Lanes fz = Lanes::load(r.oz) - (Lanes(p.cz[i]) + time * Lanes(p.vz[i]));
    const Lanes dx = Lanes::load(r.dx), dy = Lanes::load(r.dy), dz = Lanes::load(r.dz);
    const Lanes b = fx * dx + fy * dy + fz * dz;
    const Lanes invDirectionLength2 = Lanes::load(r.invDirectionLength2);
    const Lanes k = b * invDirectionLength2;
    const Lanes lx = fx - k * dx, ly = fy - k * dy, lz = fz - k * dz;
    const Lanes r2(p.radius2[i]);
    const Lanes disc = r2 - (lx * lx + ly * ly + lz * lz);
    const Lanes valid = disc >= Lanes(0.0f);
    if (movemask(valid) == 0)
        return;
    const Lanes ff = fx * fx + fy * fy + fz * fz;
    Lanes c = ff - r2;
    const Lanes q = -(b + copysign(sqrt(max(disc, Lanes(0.0f)) * Lanes::load(r.directionLength2)), b));
    const Lanes zero(0.0f);
    const Lanes surelyBehind = (abs(c) > Lanes(kSphereRootError) * (ff + r2)) &
                               (((c > zero) & (q < zero)) | ((c < zero) & (q > zero)));
    const Lanes cancelled = andNot(surelyBehind, valid & (abs(c) < Lanes(shader::kSphereCancellation) * (ff + r2)));
    if (movemask(cancelled))
        c = select(cancelled, detail::exactSphereC(fx, fy, fz, Lanes(p.radius[i])), c);
    const Lanes t0 = c / q;
    const Lanes t1 = q * invDirectionLength2;
    const Lanes tNear = min(t0, t1), tFar = max(t0, t1);
    const Lanes rootError = Lanes(kSphereRootError) * (ff + r2) / abs(q);
    const Lanes lo = max(Lanes(tMin), rootError);
    const Lanes t = select(tNear > lo, tNear, tFar);
    const Lanes mask = valid & (t > lo) & (t < hits.t);
    hits.take(mask, t, zero, zero, p.prim[i]);
}
} // namespace rt::cpu
