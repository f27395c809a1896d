// Constant-density media (RTTNW §9), written once for both engines (Shared/ShaderLang.h): where a ray is
// inside a medium's boundary, and where in there it scatters. The number that decides the free-flight distance
// is a hash of what a GPU intersection shader can see, which cannot read the path's random stream: the path's
// pixel, the ray in the space the test runs in (bits of origin and direction: distinct per path segment, and per
// sample, whose camera rays differ by their jitter), and the medium. Deterministic (an implementation may run an
// intersection shader more than once per ray and primitive, and must get the same answer each time), and
// independent of the order in which traversal meets primitives, so a path's shadow ray can be traced after
// its vertex has drawn the rest of its numbers. Not the sample index: a GPU shader sees only the first sample
// of its launch, and launches follow the render driver's time-cut batches, which would make a medium's image
// depend on how fast its first batch ran.
#ifndef RT_SHARED_MEDIUM_H
#define RT_SHARED_MEDIUM_H

#include "Shared/Random.h"
#include "Shared/ShaderLang.h"
#include "Shared/Sphere.h"

RT_SHADER_NAMESPACE_BEGIN

/// One 32-bit word k folded into the hash h: MurmurHash3's body step (Appleby 2011, public domain), whose
/// multiplications of the words are independent of each other, so that only three operations per word chain.
RT_FN uint murmurMix(uint h, uint k)
{
    k *= 0xcc9e2d51u;
    k = (k << 15u) | (k >> 17u);
    k *= 0x1b873593u;
    h ^= k;
    h = (h << 13u) | (h >> 19u);
    return h * 5u + 0xe6546b64u;
}

/// The part of mediumUniform's hash that a path keeps from its camera ray on: the render's seed and the pixel.
RT_FN uint mediumPathSeed(uint seed, uvec2 pixel)
{
    return murmurMix(murmurMix(seed, pixel.x), pixel.y);
}

/// MurmurHash3's finaliser (fmix32): every output bit depends on every input bit.
RT_FN uint murmurFinal(uint h)
{
    h ^= h >> 16u;
    h *= 0x85ebca6bu;
    h ^= h >> 13u;
    h *= 0xc2b2ae35u;
    h ^= h >> 16u;
    return h;
}

/// A number in (0, 1] (usable in log) for the ray (origin, direction) of the path with mediumPathSeed `pathSeed`
/// crossing primitive `primitive` of instance `instance` (each engine numbers its media its own way): the words
/// times distinct odd constants (xxHash's and MurmurHash3's), summed, then MurmurHash3's finaliser, so that every
/// bit of every word reaches every bit of the number. Two rays share a number only where their words differ by
/// multiples of the constants that cancel: for rays of continuous random points and directions, a chance of
/// 2^-32. The products are independent of each other: hashing the words one after the other with pcgHash cost
/// rtnw-final's CPU render 7 % (every ray of it crosses the fog's boundary), MurmurHash3's chain 3 %.
RT_FN float mediumUniform(uint pathSeed, vec3 origin, vec3 direction, uint instance, uint primitive)
{
    const uvec3 o = floatBitsToUint(origin);
    const uvec3 d = floatBitsToUint(direction);
    const uint h = pathSeed + o.x * 0x9e3779b1u + o.y * 0x85ebca77u + o.z * 0xc2b2ae3du + d.x * 0x27d4eb2fu +
                   d.y * 0x165667b1u + d.z * 0xcc9e2d51u + instance * 0x1b873593u + primitive * 0x7feb352du;
    return 1.0f - fixedPointToUnitFloat(murmurFinal(h));
}

/// Slab test of the line o + t d against the box [lo, hi]: the entry and exit parameters t1 < t2 of the whole
/// line, which may be negative; false if it misses or touches only an edge. An axis the line runs parallel to
/// is inside its slab for every t or never (no division by zero).
RT_FN bool boxInterval(vec3 o, vec3 d, vec3 lo, vec3 hi, RT_OUT(float) t1, RT_OUT(float) t2)
{
    t1 = -3.0e38f;
    t2 = 3.0e38f;
    for (int axis = 0; axis < 3; ++axis)
    {
        if (d[axis] == 0.0f)
        {
            if (o[axis] < lo[axis] || o[axis] > hi[axis])
                return false;
            continue;
        }
        const float inverse = 1.0f / d[axis];
        const float a = (lo[axis] - o[axis]) * inverse;
        const float b = (hi[axis] - o[axis]) * inverse;
        t1 = max(t1, min(a, b));
        t2 = min(t2, max(a, b));
    }
    return t1 < t2;
}

/// Where the line o + t d (the medium's object space) is inside its boundary, a sphere (centre, radius) or the
/// box [boxMin, boxMax]: t1 < t2, which may be negative (the ray may start inside).
RT_FN bool mediumInterval(bool sphere, vec3 centre, float radius, vec3 boxMin, vec3 boxMax, vec3 o, vec3 d,
                          RT_OUT(float) t1, RT_OUT(float) t2)
{
    if (sphere)
    {
        const float a = dot(d, d);
        SphereRoots roots;
        const bool crosses = sphereRoots(o - centre, d, a, 1.0f / a, radius, roots);
        t1 = roots.t0;
        t2 = roots.t1;
        return crosses && t1 < t2;
    }
    return boxInterval(o, d, boxMin, boxMax, t1, t2);
}

/// The ray parameter where a ray scatters inside a medium of `density` (extinction per world unit) whose
/// boundary it crosses over [t1, t2] of its open interval, or -1 when it passes through: the free-flight
/// distance -ln(u) / density, u = mediumUniform, in world units (directionLength = |d|).
RT_FN float mediumScatterT(float t1, float t2, float directionLength, float density, float u)
{
    const float inside = (t2 - t1) * directionLength;
    const float distance = -(1.0f / density) * log(u);
    return distance < inside ? t1 + distance / directionLength : -1.0f;
}

RT_SHADER_NAMESPACE_END

#endif
