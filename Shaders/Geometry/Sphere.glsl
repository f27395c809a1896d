// Ray-sphere roots and sphere uvs. Roots: Hearn & Baker's discriminant with Press et al.'s stable
// quadratic roots (Haines, Günther & Akenine-Möller, "Precision Improvements for Ray/Sphere Intersection",
// Ray Tracing Gems ch. 7, 2019; research notes §3.1).
#ifndef RT_SPHERE_GLSL
#define RT_SPHERE_GLSL

#include "Math/Constants.glsl"

/// Both parameters t0 <= t1 where o + t d meets the sphere (center, radius); false if the line misses it.
/// d need not be unit length.
bool sphereRoots(vec3 o, vec3 d, vec3 center, float radius, out float t0, out float t1)
{
    t0 = 0.0;
    t1 = 0.0;
    vec3 f = o - center;
    float a = dot(d, d);
    float halfB = dot(f, d);
    float c = dot(f, f) - radius * radius;
    vec3 unitD = d / sqrt(a);
    vec3 l = f - dot(f, unitD) * unitD; // closest approach of the line to the centre, before squaring
    float discriminant = a * (radius * radius - dot(l, l));
    if (discriminant < 0.0)
        return false;
    float q = -halfB - (halfB >= 0.0 ? 1.0 : -1.0) * sqrt(discriminant);
    if (q == 0.0)
        return false; // the origin is on the sphere and the line only grazes it
    float r0 = c / q;
    float r1 = q / a;
    t0 = min(r0, r1);
    t1 = max(r0, r1);
    return true;
}

/// The nearest root in (tMin, tMax): the far root for rays that start inside the sphere (glass).
bool intersectSphere(vec3 o, vec3 d, vec3 center, float radius, float tMin, float tMax, out float t)
{
    float t0;
    float t1;
    t = 0.0;
    if (!sphereRoots(o, d, center, radius, t0, t1))
        return false;
    if (t0 > tMin && t0 < tMax)
        t = t0;
    else if (t1 > tMin && t1 < tMax)
        t = t1;
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
