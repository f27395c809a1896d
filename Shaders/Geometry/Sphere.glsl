// Ray-sphere roots and sphere uvs. Roots: Hearn & Baker's discriminant with Press et al.'s stable
// quadratic roots (Haines, Günther & Akenine-Möller, "Precision Improvements for Ray/Sphere Intersection",
// Ray Tracing Gems ch. 7, 2019; research notes §3.1).
#ifndef RT_SPHERE_GLSL
#define RT_SPHERE_GLSL

#include "Shared/ShaderLang.h"
#include "Shared/SphereQuadratic.h"

#ifndef RT_EXACT_SPHERE_C
#define RT_EXACT_SPHERE_C true
#endif

struct SphereRoots
{
    float t0; // t0 <= t1
    float t1;
    float error; // absolute rounding error of a root near 0 (c / q): roots below it cannot be told from 0
};

/// Where the line o + t d meets the sphere (center, radius); false if it misses. d need not be unit length.
bool sphereRoots(vec3 o, vec3 d, vec3 center, float radius, out SphereRoots roots)
{
    roots = SphereRoots(0.0, 0.0, 0.0);
    vec3 f = o - center;
    float a = dot(d, d);
    float halfB = dot(f, d);
    float r2 = radius * radius;
    vec3 l = f - (halfB / a) * d; // closest approach of the line to the centre, formed before squaring
    float discriminantOverA = r2 - dot(l, l);
    if (discriminantOverA < 0.0)
        return false;
    float q = -(halfB + (halfB >= 0.0 ? 1.0 : -1.0) * sqrt(a * discriminantOverA));
    if (q == 0.0)
        return false; // the origin is on the sphere and the line only grazes it
    // Exact where it cancels and the near root is surely ahead, unless the pipeline is compiled for a scene
    // without huge spheres (Specialization.glsl), where float's c places every hit within 1e-4 of the scene.
    float c = RT_EXACT_SPHERE_C ? sphereQuadraticCForNearRoot(f, radius, q) : dot(f, f) - r2;
    float r0 = c / q;
    float r1 = q / a;
    roots.t0 = min(r0, r1);
    roots.t1 = max(r0, r1);
    roots.error = kSphereRootError * (dot(f, f) + r2) / abs(q);
    return true;
}

/// The nearest root in (tMin, tMax) that is farther from 0 than its rounding error: the far root for rays
/// that start inside the sphere (glass), and no hit on the surface a ray leaves. The hit point of a big
/// sphere (re-projected from a far centre) and f = o - center carry errors of ulp(|center| + radius), more
/// than offsetRayOrigin moves a point near the world origin: without the bound, rays leaving rtow-final's
/// radius-1000 ground hit it again at t ~ 1e-5 about half of the time (research notes §3.1, §3.3).
bool intersectSphere(vec3 o, vec3 d, vec3 center, float radius, float tMin, float tMax, out float t)
{
    t = 0.0;
    SphereRoots roots;
    if (!sphereRoots(o, d, center, radius, roots))
        return false;
    float lo = max(tMin, roots.error);
    if (roots.t0 > lo && roots.t0 < tMax)
        t = roots.t0;
    else if (roots.t1 > lo && roots.t1 < tMax)
        t = roots.t1;
    else
        return false;
    return true;
}

/// (u, v) of the outward unit normal q, object space (RTTNW §4.3): u = phi / 2 pi, v = theta / pi with
/// theta = acos(-q.y), phi = atan(-q.z, q.x) + pi.
vec2 sphereUv(vec3 q)
{
    float theta = acos(clamp(-q.y, -1.0, 1.0));
    float phi = atan(-q.z, q.x) + kPi;
    return vec2(phi / (2.0 * kPi), theta / kPi);
}

#endif
