// Leaf storage of the BVH: up to four primitives of one type in structure-of-arrays form, so one ray is
// tested against all of them with four-wide arithmetic and no per-primitive branches (the layout of
// Embree's quad4/triangle4 leaves: Wald et al., "Embree: A Kernel Framework for Efficient CPU Ray
// Tracing", ACM TOG 33(4), 2014). The tests are the scalar ones of Intersect.h, lane by lane.
// Unused lanes repeat lane 0, so they report the same hit as lane 0 and need no masking.
#pragma once

#include <cstdint>

#include "Geometry/Intersect.h"
#include "Geometry/Primitives.h"
#include "Geometry/Simd4.h"

namespace rt::cpu
{
struct alignas(16) SpherePacket
{
    float cx[4], cy[4], cz[4]; // centre at time 0
    float vx[4], vy[4], vz[4]; // velocity over the shutter
    float radius2[4];
    std::uint32_t prim[4]; // PrimRef bits
};

struct alignas(16) QuadPacket
{
    float qx[4], qy[4], qz[4];
    float nx[4], ny[4], nz[4];
    float d[4];
    float uax[4], uay[4], uaz[4];
    float vbx[4], vby[4], vbz[4];
    std::uint32_t prim[4];
};

struct alignas(16) TrianglePacket
{
    float p[3][3][4]; // [vertex][axis][lane]
    std::uint32_t prim[4];
};

void setLane(SpherePacket& p, int lane, const SphereRec& s, std::uint32_t prim);
void setLane(QuadPacket& p, int lane, const QuadRec& q, std::uint32_t prim);
void setLane(TrianglePacket& p, int lane, const TriangleRec& t, std::uint32_t prim);
/// Fills lanes [used, 4) with copies of lane 0.
template <typename Packet>
void padPacket(Packet& p, int used)
{
    const auto* src = reinterpret_cast<const std::uint32_t*>(&p);
    auto* dst = reinterpret_cast<std::uint32_t*>(&p);
    for (std::size_t word = 0; word < sizeof(Packet) / 4; word += 4) // every member is an array of 4 lanes
        for (int lane = used; lane < 4; ++lane)
            dst[word + lane] = src[word];
}

namespace detail
{
/// Records the nearest lane of `t` among `mask` in `hit`; true if there was one.
inline bool takeNearest(F4 mask, F4 t, F4 b1, F4 b2, const std::uint32_t prim[4], HitRecord& hit)
{
    const int bits = movemask(mask);
    if (bits == 0)
        return false;
    const F4 masked = select(mask, t, F4(kInfinity));
    const int lane = std::countr_zero(static_cast<unsigned>(movemask(masked == horizontalMin(masked)) & bits));
    hit = {t[lane], prim[lane], b1[lane], b2[lane]};
    return true;
}
} // namespace detail

/// Four spheres at once: intersectSphere's Hearn–Baker / Press arithmetic lane by lane.
inline bool intersectPacket(const SpherePacket& p, const TraceRay& r, float tMin, HitRecord& hit)
{
    const F4 time(r.time);
    const F4 fx = F4(r.origin.x) - (F4::load(p.cx) + time * F4::load(p.vx));
    const F4 fy = F4(r.origin.y) - (F4::load(p.cy) + time * F4::load(p.vy));
    const F4 fz = F4(r.origin.z) - (F4::load(p.cz) + time * F4::load(p.vz));
    const F4 dx(r.direction.x), dy(r.direction.y), dz(r.direction.z);
    const F4 b = fx * dx + fy * dy + fz * dz;
    const F4 k = b * F4(r.invDirectionLength2);
    const F4 lx = fx - k * dx, ly = fy - k * dy, lz = fz - k * dz;
    const F4 r2 = F4::load(p.radius2);
    const F4 disc = r2 - (lx * lx + ly * ly + lz * lz);
    const F4 valid = disc >= F4(0.0f);
    if (movemask(valid) == 0)
        return false;
    const F4 c = fx * fx + fy * fy + fz * fz - r2;
    const F4 q = -(b + copysign(sqrt(max(disc, F4(0.0f)) * F4(r.directionLength2)), b));
    const F4 t0 = c / q;
    const F4 t1 = q * F4(r.invDirectionLength2);
    const F4 tNear = min(t0, t1), tFar = max(t0, t1);
    const F4 rootError = F4(kSphereRootError) * (fx * fx + fy * fy + fz * fz + r2) / abs(q); // see intersectSphere
    const F4 lo = max(F4(tMin), rootError), hi(hit.t);
    const F4 t = select(tNear > lo, tNear, tFar);
    const F4 mask = valid & (t > lo) & (t < hi);
    return detail::takeNearest(mask, t, F4(0.0f), F4(0.0f), p.prim, hit);
}

/// Four parallelograms at once (intersectQuad lane by lane).
inline bool intersectPacket(const QuadPacket& p, const TraceRay& r, float tMin, HitRecord& hit)
{
    const F4 nx = F4::load(p.nx), ny = F4::load(p.ny), nz = F4::load(p.nz);
    const F4 dx(r.direction.x), dy(r.direction.y), dz(r.direction.z);
    const F4 ox(r.origin.x), oy(r.origin.y), oz(r.origin.z);
    const F4 denom = nx * dx + ny * dy + nz * dz;
    const F4 t = (F4::load(p.d) - (nx * ox + ny * oy + nz * oz)) / denom; // NaN in empty lanes: fails below
    const F4 lo(tMin), hi(hit.t);
    F4 mask = (t > lo) & (t < hi) & (abs(denom) >= F4(1e-12f));
    if (movemask(mask) == 0)
        return false;
    const F4 px = ox + t * dx - F4::load(p.qx);
    const F4 py = oy + t * dy - F4::load(p.qy);
    const F4 pz = oz + t * dz - F4::load(p.qz);
    const F4 alpha = px * F4::load(p.uax) + py * F4::load(p.uay) + pz * F4::load(p.uaz);
    const F4 beta = px * F4::load(p.vbx) + py * F4::load(p.vby) + pz * F4::load(p.vbz);
    const F4 zero(0.0f), one(1.0f);
    mask = mask & (alpha >= zero) & (alpha <= one) & (beta >= zero) & (beta <= one);
    return detail::takeNearest(mask, t, alpha, beta, p.prim, hit);
}

/// Four triangles at once with the watertight test (intersectTriangle lane by lane). Lanes whose edge
/// functions come out exactly 0 in float are left out and returned in `undecided` (a lane bit mask): the
/// caller redoes them with the scalar test, which falls back to double.
inline bool intersectPacket(const TrianglePacket& p, const TraceRay& r, float tMin, HitRecord& hit, int& undecidedLanes)
{
    const F4 okx(r.origin[r.kx]), oky(r.origin[r.ky]), okz(r.origin[r.kz]);
    const F4 sx(r.sx), sy(r.sy), sz(r.sz);
    F4 x[3], y[3], z[3];
    for (int v = 0; v < 3; ++v)
    {
        const F4 az = F4::load(p.p[v][r.kz]) - okz;
        x[v] = (F4::load(p.p[v][r.kx]) - okx) - sx * az;
        y[v] = (F4::load(p.p[v][r.ky]) - oky) - sy * az;
        z[v] = sz * az;
    }
    const F4 u = x[2] * y[1] - y[2] * x[1];
    const F4 v = x[0] * y[2] - y[0] * x[2];
    const F4 w = x[1] * y[0] - y[1] * x[0];
    const F4 zero(0.0f);
    const F4 undecided = (u == zero) | (v == zero) | (w == zero);
    const F4 negative = (u < zero) | (v < zero) | (w < zero);
    const F4 positive = (u > zero) | (v > zero) | (w > zero);
    const F4 det = u + v + w;
    const F4 t = (u * z[0] + v * z[1] + w * z[2]) / det;
    F4 mask = andNot(negative & positive, andNot(det == zero, (t > F4(tMin)) & (t < F4(hit.t))));
    mask = andNot(undecided, mask);
    undecidedLanes = movemask(undecided);
    return detail::takeNearest(mask, t, v / det, w / det, p.prim, hit);
}
} // namespace rt::cpu
