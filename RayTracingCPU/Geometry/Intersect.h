// Ray-primitive tests of the CPU engine. Each takes the open interval (tMin, hit.t) and, on a closer hit,
// updates `hit` and returns true. The GLSL twins of the sphere and medium tests are in Shaders/.
#pragma once

#include <cmath>

#include "Geometry/Primitives.h"
#include "Geometry/TraceRay.h"
#include "Random/Pcg.h"
#include "Shared/SphereQuadratic.h"

namespace rt::cpu
{
using shader::kSphereRootError;

/// Sphere at the ray's time. Hearn & Baker's discriminant (the closest approach l is formed before squaring)
/// with Press et al.'s stable roots: Haines, Günther & Akenine-Möller, "Precision Improvements for Ray/Sphere
/// Intersection", Ray Tracing Gems ch. 7, 2019. The far root is taken when the near one is out of range, so
/// rays leaving from inside (glass) hit the far wall.
inline bool intersectSphere(const SphereRec& s, const TraceRay& r, float tMin, HitRecord& hit, std::uint32_t prim)
{
    const vec3 center = s.center0 + r.time * s.velocity;
    const vec3 f = r.origin - center;
    const float b = glm::dot(f, r.direction);
    const vec3 l = f - (b * r.invDirectionLength2) * r.direction;
    const float r2 = s.radius * s.radius;
    const float disc = r2 - glm::dot(l, l); // discriminant / a
    if (disc < 0.0f)
        return false;
    const float a = r.directionLength2;
    const float q = -(b + std::copysign(std::sqrt(a * disc), b));
    // Exact where it cancels (a huge sphere's surface) and the near root lies surely ahead.
    const float c = shader::sphereQuadraticCForNearRoot(f, s.radius, q);
    float t0 = c / q;
    float t1 = q * r.invDirectionLength2;
    if (t0 > t1)
        std::swap(t0, t1);
    // A root nearer 0 than its rounding error cannot be told from the surface the ray leaves: f and the
    // re-projected hit point carry errors of ulp(|center| + radius), which the ray offset does not cover
    // near the origin of a huge sphere (the books' radius-1000 ground). c's error is gamma(8) (f.f + r^2).
    const float lo = maxf(tMin, kSphereRootError * (glm::dot(f, f) + r2) / std::fabs(q));
    float t = t0;
    if (!(t > lo && t < hit.t))
    {
        t = t1;
        if (!(t > lo && t < hit.t))
            return false;
    }
    hit.t = t;
    hit.prim = prim;
    return true;
}

inline bool intersectQuad(const QuadRec& quad, const TraceRay& r, float tMin, HitRecord& hit, std::uint32_t prim)
{
    const float denom = glm::dot(quad.normal, r.direction);
    if (std::fabs(denom) < 1e-12f)
        return false; // parallel to the plane
    const float t = (quad.d - glm::dot(quad.normal, r.origin)) / denom;
    if (!(t > tMin && t < hit.t))
        return false;
    const vec3 planar = r.origin + t * r.direction - quad.q;
    const float alpha = glm::dot(planar, quad.ua);
    const float beta = glm::dot(planar, quad.vb);
    if (alpha < 0.0f || alpha > 1.0f || beta < 0.0f || beta > 1.0f)
        return false;
    hit = {t, prim, alpha, beta};
    return true;
}

/// Watertight ray/triangle test (Woop, Benthin & Wald, JCGT 2(1), 2013): no ray passes between two triangles
/// sharing an edge. Needs -ffp-contract=off (set project-wide) so the edge functions are not fused.
inline bool intersectTriangle(const TriangleRec& tri, const TraceRay& r, float tMin, HitRecord& hit, std::uint32_t prim)
{
    const vec3 a = tri.p0 - r.origin;
    const vec3 b = tri.p1 - r.origin;
    const vec3 c = tri.p2 - r.origin;
    const float ax = a[r.kx] - r.sx * a[r.kz];
    const float ay = a[r.ky] - r.sy * a[r.kz];
    const float bx = b[r.kx] - r.sx * b[r.kz];
    const float by = b[r.ky] - r.sy * b[r.kz];
    const float cx = c[r.kx] - r.sx * c[r.kz];
    const float cy = c[r.ky] - r.sy * c[r.kz];
    float u = cx * by - cy * bx;
    float v = ax * cy - ay * cx;
    float w = bx * ay - by * ax;
    if (u == 0.0f || v == 0.0f || w == 0.0f)
    {
        // Float cannot decide the side: redo the edge functions in double (exact for these products).
        u = static_cast<float>(double(cx) * double(by) - double(cy) * double(bx));
        v = static_cast<float>(double(ax) * double(cy) - double(ay) * double(cx));
        w = static_cast<float>(double(bx) * double(ay) - double(by) * double(ax));
    }
    if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f))
        return false;
    const float det = u + v + w;
    if (det == 0.0f)
        return false;
    const float tScaled = u * (r.sz * a[r.kz]) + v * (r.sz * b[r.kz]) + w * (r.sz * c[r.kz]);
    const float invDet = 1.0f / det;
    const float t = tScaled * invDet;
    if (!(t > tMin && t < hit.t))
        return false;
    hit = {t, prim, v * invDet, w * invDet};
    return true;
}

/// Constant-density medium (RTTNW §9): clips the boundary's [entry, exit] to the ray interval, samples an
/// exponential free-flight distance with the path's generator, and reports a scattering point if it falls
/// inside. Density is per world unit; t is invariant under the object transform.
inline bool intersectMedium(const MediumRec& m, const TraceRay& r, float tMin, HitRecord& hit, std::uint32_t prim,
                            Rng& rng)
{
    const vec3 o = vec3(m.objectFromWorld * vec4(r.origin, 1.0f));
    const vec3 d = vec3(m.objectFromWorld * vec4(r.direction, 0.0f));
    float t1, t2;
    if (m.sphere)
    {
        const vec3 f = o - m.center;
        const float a = glm::dot(d, d);
        const float b = glm::dot(f, d);
        const vec3 l = f - (b / a) * d;
        const float disc = m.radius * m.radius - glm::dot(l, l);
        if (disc < 0.0f)
            return false;
        const float c = glm::dot(f, f) - m.radius * m.radius;
        const float q = -(b + std::copysign(std::sqrt(a * disc), b));
        t1 = c / q;
        t2 = q / a;
        if (t1 > t2)
            std::swap(t1, t2);
    }
    else
    {
        const vec3 inv = 1.0f / d;
        const vec3 lo = (m.boxMin - o) * inv;
        const vec3 hi = (m.boxMax - o) * inv;
        const vec3 tn = glm::min(lo, hi);
        const vec3 tf = glm::max(lo, hi);
        t1 = maxf(tn.x, maxf(tn.y, tn.z));
        t2 = minf(tf.x, minf(tf.y, tf.z));
    }
    t1 = maxf(t1, tMin);
    t2 = minf(t2, hit.t);
    if (!(t1 < t2))
        return false;
    const float inside = (t2 - t1) * r.directionLength;
    const float distance = m.negInvDensity * std::log(1.0f - rng.nextFloat());
    if (!(distance < inside))
        return false;
    hit = {t1 + distance / r.directionLength, prim, 0.0f, 0.0f};
    return true;
}
} // namespace rt::cpu
