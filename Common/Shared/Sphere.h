// Ray-sphere roots and sphere uvs, written once for both engines (Shared/ShaderLang.h): Hearn & Baker's
// discriminant (the closest approach l is formed before squaring) with Press et al.'s stable roots (Haines,
// Günther & Akenine-Möller, "Precision Improvements for Ray/Sphere Intersection", Ray Tracing Gems ch. 7,
// 2019; research notes §3.1), and the exact c of Shared/SphereQuadratic.h where it cancels. The CPU's sphere
// packets (Geometry/Packets.h) run the same operations eight spheres at once and find the same roots bit for
// bit (IntersectTest).
#ifndef RT_SHARED_SPHERE_H
#define RT_SHARED_SPHERE_H

#include "Shared/ShaderLang.h"
#include "Shared/SphereQuadratic.h"

// Whether the roots take the exact c where it cancels: always, but in the GPU pipelines compiled for a scene
// without huge spheres (Shaders/Specialization.glsl), where float's c places every hit within 1e-4 of the scene.
#ifndef RT_EXACT_SPHERE_C
#define RT_EXACT_SPHERE_C true
#endif

RT_SHADER_NAMESPACE_BEGIN

struct SphereRoots
{
    float t0; // t0 <= t1
    float t1;
    float q; // -(b + sign(b) sqrt(a disc)): t0 or t1 is c / q, the other q / a
};

/// Where the line o + t d meets the sphere (centre, radius), from f = o - centre, a = d . d and invA = 1 / a
/// (which traversal computes once per ray); false if it misses. d need not be unit length.
RT_FN bool sphereRoots(vec3 f, vec3 d, float a, float invA, float radius, RT_OUT(SphereRoots) roots)
{
    roots.t0 = 0.0f;
    roots.t1 = 0.0f;
    roots.q = 0.0f;
    const float b = dot(f, d);
    const vec3 l = f - (b * invA) * d;
    const float r2 = radius * radius;
    const float disc = r2 - dot(l, l); // discriminant / a
    if (disc < 0.0f)
        return false;
    const float q = -(b + signNotZero(b) * sqrt(a * disc));
    if (q == 0.0f)
        return false; // the origin is on the sphere and the line only grazes it
    const float c = RT_EXACT_SPHERE_C ? sphereQuadraticCForNearRoot(f, radius, q) : dot(f, f) - r2;
    const float rootC = c / q;
    const float rootA = q * invA;
    roots.t0 = min(rootC, rootA); // without a branch: the GPU's threads disagree on which is nearer
    roots.t1 = max(rootC, rootA);
    roots.q = q;
    return true;
}

/// The absolute rounding error of the root near 0 (c / q) of sphereRoots(f, .., radius, roots): a root below it
/// cannot be told from 0.
RT_FN float sphereRootError(vec3 f, float radius, RT_IN(SphereRoots) roots)
{
    return kSphereRootError * (dot(f, f) + radius * radius) / abs(roots.q);
}

/// The nearest root in (tMin, tMax) that is farther from 0 than its rounding error `error` (sphereRootError),
/// or -1: the far root for rays that start inside the sphere (glass), and no hit on the surface a ray leaves. The hit point of a big
/// sphere (re-projected from a far centre) and f carry errors of ulp(|centre| + radius), more than
/// offsetRayOrigin moves a point near the world origin: without the bound, rays leaving rtow-final's
/// radius-1000 ground hit it again at t ~ 1e-5 about half of the time (research notes §3.1, §3.3).
RT_FN float nearestSphereRoot(RT_IN(SphereRoots) roots, float error, float tMin, float tMax)
{
    const float lo = max(tMin, error);
    if (roots.t0 > lo && roots.t0 < tMax)
        return roots.t0;
    if (roots.t1 > lo && roots.t1 < tMax)
        return roots.t1;
    return -1.0f;
}

/// (u, v) of the outward unit normal q, object space (RTTNW §4.3): u = phi / 2 pi, v = theta / pi with
/// theta = acos(-q.y), phi = atan(-q.z, q.x) + pi.
RT_FN vec2 sphereUv(vec3 q)
{
    const float theta = acos(clamp(-q.y, -1.0f, 1.0f));
    const float phi = atan(-q.z, q.x) + kPi;
    return vec2(phi * kInv2Pi, theta * kInvPi);
}

RT_SHADER_NAMESPACE_END

#endif
