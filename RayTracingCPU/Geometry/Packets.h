// Leaf storage of the BVH: up to kLanes (8 with AVX, else 4) primitives of one type in structure-of-arrays
// form, so one ray is tested against all of them at once with no per-primitive branches (the layout of
// Embree's quad4/triangle4 leaves: Wald et al., "Embree: A Kernel Framework for Efficient CPU Ray
// Tracing", ACM TOG 33(4), 2014). The tests are the scalar ones of Intersect.h, lane by lane.
// Unused lanes hold NaN, which fails every test's comparisons: they never hit and need no masking, and a
// packet's hits are its primitives' alone (a lone sphere's hit is one lane, found without a horizontal min).
#pragma once

#include <cstdint>

#include "Geometry/Intersect.h"
#include "Geometry/Primitives.h"
#include "Geometry/Lanes.h"

namespace rt::cpu
{
struct alignas(32) SpherePacket
{
    float cx[kLanes], cy[kLanes], cz[kLanes]; // centre at time 0
    float vx[kLanes], vy[kLanes], vz[kLanes]; // velocity over the shutter
    float radius2[kLanes];
    float radius[kLanes]; // for c's exact path (Shared/SphereQuadratic.h)
    std::uint32_t prim[kLanes]; // PrimRef bits
};

struct alignas(32) QuadPacket
{
    float qx[kLanes], qy[kLanes], qz[kLanes];
    float nx[kLanes], ny[kLanes], nz[kLanes];
    float d[kLanes];
    float uax[kLanes], uay[kLanes], uaz[kLanes];
    float vbx[kLanes], vby[kLanes], vbz[kLanes];
    std::uint32_t prim[kLanes];
};

struct alignas(32) TrianglePacket
{
    float p[3][3][kLanes]; // [vertex][axis][lane]
    std::uint32_t prim[kLanes];
};

void setLane(SpherePacket& p, int lane, const SphereRec& s, std::uint32_t prim);
void setLane(QuadPacket& p, int lane, const QuadRec& q, std::uint32_t prim);
void setLane(TrianglePacket& p, int lane, const TriangleRec& t, std::uint32_t prim);
/// Fills lanes [used, kLanes) with a quiet NaN in every member (prim included: never read, as such a lane
/// never hits).
template <typename Packet>
void padPacket(Packet& p, int used)
{
    static_assert(sizeof(Packet) % (4 * kLanes) == 0); // every member is an array of kLanes 4-byte lanes
    auto* words = reinterpret_cast<std::uint32_t*>(&p);
    for (std::size_t word = 0; word < sizeof(Packet) / 4; word += kLanes)
        for (int lane = used; lane < kLanes; ++lane)
            words[word + lane] = 0x7FC00000u;
}

namespace detail
{
/// The lane of `mask` with the smallest `t` (the lowest among equals); -1 if `mask` is empty.
inline int nearestLane(Lanes mask, Lanes t)
{
    const int bits = movemask(mask);
    if (bits == 0)
        return -1;
    if ((bits & (bits - 1)) == 0) // one lane hit: the common case in a leaf of walls or of one sphere
        return std::countr_zero(static_cast<unsigned>(bits));
    const Lanes masked = select(mask, t, Lanes(kInfinity));
    return std::countr_zero(static_cast<unsigned>(movemask(masked == horizontalMin(masked)) & bits));
}

/// sphereQuadraticC's exact path (Shared/SphereQuadratic.h: Dekker's products, Knuth's sums) in every lane at
/// once: the same operations in the same order, so the same bits as the scalar function.
inline Lanes exactSphereC(Lanes fx, Lanes fy, Lanes fz, Lanes radius)
{
    struct Pair
    {
        Lanes value, error;
    };
    const auto square = [](Lanes a) {
        const Lanes split = Lanes(4097.0f) * a;
        const Lanes hi = split - (split - a);
        const Lanes lo = a - hi;
        const Lanes p = a * a;
        return Pair{p, ((hi * hi - p) + Lanes(2.0f) * hi * lo) + lo * lo};
    };
    const auto sum = [](Lanes s, Lanes t) {
        const Lanes total = s + t;
        const Lanes tPart = total - s;
        return Pair{total, (s - (total - tPart)) + (t - tPart)};
    };
    const Pair x = square(fx), y = square(fy), z = square(fz), r2 = square(radius);
    Pair s = sum(x.value, y.value);
    Lanes lost = s.error + x.error + y.error;
    s = sum(s.value, z.value);
    lost = lost + (s.error + z.error);
    s = sum(s.value, -r2.value);
    lost = lost + (s.error - r2.error);
    return s.value + lost;
}

/// Records the nearest lane of `t` among `mask` in `hit`; true if there was one.
inline bool takeNearest(Lanes mask, Lanes t, Lanes b1, Lanes b2, const std::uint32_t prim[kLanes], HitRecord& hit)
{
    const int lane = nearestLane(mask, t);
    if (lane < 0)
        return false;
    hit = {t[lane], prim[lane], b1[lane], b2[lane]};
    return true;
}
} // namespace detail

// The lane tests below are shared by the packets' tests and Geometry/RayPackets.h's. Forced inline: left to
// the compiler, the extra level kept the sphere and quad packet tests out of line where their callers are not
// flattened (rt_bench ClosestHit: 27 ns per ray against 23.5).
#if defined(__GNUC__)
#define RT_LANES_INLINE [[gnu::always_inline]] inline
#elif defined(_MSC_VER)
#define RT_LANES_INLINE __forceinline
#else
#define RT_LANES_INLINE inline
#endif

/// A ray per lane, as the lane tests read it: one ray broadcast to every lane (a primitive packet's test) or
/// kLanes rays (Geometry/RayPackets.h).
struct RayLaneView
{
    Lanes ox, oy, oz;
    Lanes dx, dy, dz;
    Lanes time, directionLength2, invDirectionLength2;
};

/// A sphere per lane: a packet's kLanes spheres, or one sphere broadcast.
struct SphereLaneView
{
    Lanes cx, cy, cz, vx, vy, vz, radius2, radius;
};

/// A parallelogram per lane: a packet's kLanes quads, or one quad broadcast.
struct QuadLaneView
{
    Lanes qx, qy, qz, nx, ny, nz, d, uax, uay, uaz, vbx, vby, vbz;
};

/// What a lane test found: where `mask` is set, the lane's ray meets its primitive at t in (tMin, tMax),
/// with edge coordinates b1, b2 (quads; 0 for spheres).
struct LaneHits
{
    Lanes mask, t, b1, b2;
};

RT_LANES_INLINE RayLaneView broadcast(const TraceRay& r)
{
    return {Lanes(r.origin.x),    Lanes(r.origin.y),         Lanes(r.origin.z),
            Lanes(r.direction.x), Lanes(r.direction.y),      Lanes(r.direction.z),
            Lanes(r.time),        Lanes(r.directionLength2), Lanes(r.invDirectionLength2)};
}

namespace detail
{
/// intersectSphere's Hearn–Baker / Press arithmetic lane by lane, for a packet's test and a ray-lane test
/// alike, so both find the same hits bit for bit. False when no lane's ray meets its sphere's line (`out`
/// then unset).
RT_LANES_INLINE bool sphereLanes(const SphereLaneView& s, const RayLaneView& r, float tMin, Lanes tMax,
                                 LaneHits& out)
{
    const Lanes fx = r.ox - (s.cx + r.time * s.vx);
    const Lanes fy = r.oy - (s.cy + r.time * s.vy);
    const Lanes fz = r.oz - (s.cz + r.time * s.vz);
    const Lanes b = fx * r.dx + fy * r.dy + fz * r.dz;
    const Lanes k = b * r.invDirectionLength2;
    const Lanes lx = fx - k * r.dx, ly = fy - k * r.dy, lz = fz - k * r.dz;
    const Lanes disc = s.radius2 - (lx * lx + ly * ly + lz * lz);
    const Lanes valid = disc >= Lanes(0.0f);
    if (movemask(valid) == 0)
        return false;
    const Lanes ff = fx * fx + fy * fy + fz * fz;
    Lanes c = ff - s.radius2;
    const Lanes q = -(b + copysign(sqrt(max(disc, Lanes(0.0f)) * r.directionLength2), b));
    // Where c cancels (near a huge sphere's surface) and the near root c / q lies surely ahead, those lanes
    // take the exact c: sphereQuadraticCForNearRoot's rule, lane by lane (a ray leaving a sphere's surface, as
    // every bounce and refraction, needs no exact c).
    const Lanes zero(0.0f);
    const Lanes absC = abs(c);
    const Lanes nearRootAhead = ((c > zero) & (q > zero)) | ((c < zero) & (q < zero));
    const Lanes cancelled = valid & nearRootAhead & (absC > Lanes(kSphereRootError) * (ff + s.radius2)) &
                            (absC < Lanes(shader::kSphereCancellation) * (ff + s.radius2));
    if (movemask(cancelled))
        c = select(cancelled, exactSphereC(fx, fy, fz, s.radius), c);
    const Lanes t0 = c / q;
    const Lanes t1 = q * r.invDirectionLength2;
    const Lanes tNear = min(t0, t1), tFar = max(t0, t1);
    const Lanes rootError = Lanes(kSphereRootError) * (ff + s.radius2) / abs(q); // see intersectSphere
    const Lanes lo = max(Lanes(tMin), rootError);
    const Lanes t = select(tNear > lo, tNear, tFar);
    out = {valid & (t > lo) & (t < tMax), t, zero, zero};
    return true;
}

/// intersectQuad lane by lane, for a packet's test and a ray-lane test alike.
RT_LANES_INLINE LaneHits quadLanes(const QuadLaneView& q, const RayLaneView& r, float tMin, Lanes tMax)
{
    const Lanes denom = q.nx * r.dx + q.ny * r.dy + q.nz * r.dz;
    const Lanes t = (q.d - (q.nx * r.ox + q.ny * r.oy + q.nz * r.oz)) / denom; // NaN in empty lanes: fails below
    // No early exit when no plane is hit: a branch on it is mispredicted often enough to cost more (3 %
    // on rtrol-cornell-glass) than the rest of the test.
    Lanes mask = (t > Lanes(tMin)) & (t < tMax) & (abs(denom) >= Lanes(1e-12f));
    const Lanes px = r.ox + t * r.dx - q.qx;
    const Lanes py = r.oy + t * r.dy - q.qy;
    const Lanes pz = r.oz + t * r.dz - q.qz;
    const Lanes alpha = px * q.uax + py * q.uay + pz * q.uaz;
    const Lanes beta = px * q.vbx + py * q.vby + pz * q.vbz;
    const Lanes zero(0.0f), one(1.0f);
    mask = mask & (alpha >= zero) & (alpha <= one) & (beta >= zero) & (beta <= one);
    return {mask, t, alpha, beta};
}
} // namespace detail

/// kLanes spheres at once: intersectSphere lane by lane.
inline bool intersectPacket(const SpherePacket& p, const TraceRay& r, float tMin, HitRecord& hit)
{
    const SphereLaneView s{Lanes::load(p.cx), Lanes::load(p.cy),      Lanes::load(p.cz),
                           Lanes::load(p.vx), Lanes::load(p.vy),      Lanes::load(p.vz),
                           Lanes::load(p.radius2), Lanes::load(p.radius)};
    LaneHits h;
    if (!detail::sphereLanes(s, broadcast(r), tMin, Lanes(hit.t), h))
        return false;
    return detail::takeNearest(h.mask, h.t, h.b1, h.b2, p.prim, hit);
}

/// kLanes parallelograms at once (intersectQuad lane by lane).
inline bool intersectPacket(const QuadPacket& p, const TraceRay& r, float tMin, HitRecord& hit)
{
    const QuadLaneView q{Lanes::load(p.qx),  Lanes::load(p.qy),  Lanes::load(p.qz),  Lanes::load(p.nx),
                         Lanes::load(p.ny),  Lanes::load(p.nz),  Lanes::load(p.d),   Lanes::load(p.uax),
                         Lanes::load(p.uay), Lanes::load(p.uaz), Lanes::load(p.vbx), Lanes::load(p.vby),
                         Lanes::load(p.vbz)};
    const LaneHits h = detail::quadLanes(q, broadcast(r), tMin, Lanes(hit.t));
    return detail::takeNearest(h.mask, h.t, h.b1, h.b2, p.prim, hit);
}

/// kLanes triangles at once with the watertight test (intersectTriangle lane by lane). Lanes whose edge
/// functions come out exactly 0 in float are left out and returned in `undecided` (a lane bit mask): the
/// caller redoes them with the scalar test, which falls back to double.
inline bool intersectPacket(const TrianglePacket& p, const TraceRay& r, float tMin, HitRecord& hit, int& undecidedLanes)
{
    const Lanes okx(r.origin[r.kx]), oky(r.origin[r.ky]), okz(r.origin[r.kz]);
    const Lanes sx(r.sx), sy(r.sy), sz(r.sz);
    Lanes x[3], y[3], z[3];
    for (int v = 0; v < 3; ++v)
    {
        const Lanes az = Lanes::load(p.p[v][r.kz]) - okz;
        x[v] = (Lanes::load(p.p[v][r.kx]) - okx) - sx * az;
        y[v] = (Lanes::load(p.p[v][r.ky]) - oky) - sy * az;
        z[v] = sz * az;
    }
    const Lanes u = x[2] * y[1] - y[2] * x[1];
    const Lanes v = x[0] * y[2] - y[0] * x[2];
    const Lanes w = x[1] * y[0] - y[1] * x[0];
    const Lanes zero(0.0f);
    const Lanes undecided = (u == zero) | (v == zero) | (w == zero);
    const Lanes negative = (u < zero) | (v < zero) | (w < zero);
    const Lanes positive = (u > zero) | (v > zero) | (w > zero);
    const Lanes det = u + v + w;
    const Lanes t = (u * z[0] + v * z[1] + w * z[2]) / det;
    Lanes mask = andNot(negative & positive, andNot(det == zero, (t > Lanes(tMin)) & (t < Lanes(hit.t))));
    mask = andNot(undecided, mask);
    undecidedLanes = movemask(undecided);
    // The barycentrics of the winning lane only: a division per lane, the same bits as dividing the vectors.
    const int lane = detail::nearestLane(mask, t);
    if (lane < 0)
        return false;
    hit = {t[lane], p.prim[lane], v[lane] / det[lane], w[lane] / det[lane]};
    return true;
}
} // namespace rt::cpu
