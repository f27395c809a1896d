// Ray-primitive tests of the CPU engine. Each takes the open interval (tMin, hit.t) and, on a closer hit,
// updates `hit` and returns true. The sphere's roots and the medium's interval and free flight are Shared/
// code (Shared/Sphere.h, Shared/Medium.h) that the GPU's intersection shaders run too.
#pragma once

#include <cmath>

#include "Geometry/Primitives.h"
#include "Geometry/TraceRay.h"
#include "Shared/Medium.h"
#include "Shared/Sphere.h"

namespace rt::cpu
{
using shader::kSphereRootError;

/// Sphere at the ray's time (Shared/Sphere.h: the roots and the nearest one the ray may take).
inline bool intersectSphere(const SphereRec& s, const TraceRay& r, float tMin, HitRecord& hit, std::uint32_t prim)
{
    const vec3 center = s.center0 + r.time * s.velocity;
    const vec3 f = r.origin - center;
    shader::SphereRoots roots;
    if (!shader::sphereRoots(f, r.direction, r.directionLength2, r.invDirectionLength2, s.radius, roots))
        return false;
    const float t = shader::nearestSphereRoot(roots, shader::sphereRootError(f, s.radius, roots), tMin, hit.t);
    if (!(t >= 0.0f))
        return false;
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

/// Constant-density medium (RTTNW §9, Shared/Medium.h): clips the boundary's [entry, exit] to the ray interval
/// and reports a scattering point where the free-flight distance, drawn from the hash of the path's
/// `mediumSeed`, the ray and the medium, falls inside. Density is per world unit; t is invariant under the
/// object transform.
inline bool intersectMedium(const MediumRec& m, const TraceRay& r, float tMin, HitRecord& hit, std::uint32_t prim,
                            std::uint32_t mediumSeed)
{
    const vec3 o = vec3(m.objectFromWorld * vec4(r.origin, 1.0f));
    const vec3 d = vec3(m.objectFromWorld * vec4(r.direction, 0.0f));
    float t1, t2;
    if (!shader::mediumInterval(m.sphere, m.center, m.radius, m.boxMin, m.boxMax, o, d, t1, t2))
        return false;
    t1 = maxf(t1, tMin);
    t2 = minf(t2, hit.t);
    if (!(t1 < t2))
        return false;
    const float u = shader::mediumUniform(mediumSeed, o, d, 0u, prim);
    const float t = shader::mediumScatterT(t1, t2, r.directionLength, m.density, u);
    if (!(t >= 0.0f))
        return false;
    hit = {t, prim, 0.0f, 0.0f};
    return true;
}
} // namespace rt::cpu
