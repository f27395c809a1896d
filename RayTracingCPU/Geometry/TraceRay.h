#pragma once

#include <cmath>

#include "Math/Math.h"
#include "Math/Ray.h"

namespace rt::cpu
{
/// A ray prepared for traversal: the quantities every box, sphere and triangle test of one ray shares,
/// computed once. The direction is not normalised; t is in units of it.
struct TraceRay
{
    vec3 origin;
    vec3 direction;
    float time;
    vec3 invDirection; // 1 / d per component (+-inf for 0 components: the slab test handles them); box tests only
    int directionNegative[3]; // box tests only
    float directionLength2; // d . d
    float invDirectionLength2; // 1 / (d . d)
    float directionLength; // |d|; only computed when the scene has media
    // Watertight triangle test (Woop, Benthin & Wald, JCGT 2(1), 2013): permutation and shear; only computed
    // when the scene has triangles.
    int kx, ky, kz;
    float sx, sy, sz;

    /// What the scene's primitives need from a ray beyond the box and sphere tests.
    struct Needs
    {
        bool triangles = true;
        bool media = true;
        bool boxes = true; // false when the scene is one BVH leaf: its rays meet no box
    };

    TraceRay(const Ray& r, Needs needs) : origin(r.origin), direction(r.direction), time(r.time)
    {
        if (needs.boxes)
        {
            invDirection = 1.0f / direction;
            for (int i = 0; i < 3; ++i)
                directionNegative[i] = invDirection[i] < 0.0f;
        }
        directionLength2 = lengthSquared(direction);
        invDirectionLength2 = 1.0f / directionLength2;
        directionLength = needs.media ? std::sqrt(directionLength2) : 0.0f;
        if (!needs.triangles)
            return;
        const vec3 a = glm::abs(direction);
        kz = (a.x > a.y) ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
        kx = kz == 2 ? 0 : kz + 1;
        ky = kx == 2 ? 0 : kx + 1;
        if (direction[kz] < 0.0f)
        {
            const int t = kx; // keep the winding: a negative major axis mirrors the shear plane
            kx = ky;
            ky = t;
        }
        sz = 1.0f / direction[kz];
        sx = direction[kx] * sz;
        sy = direction[ky] * sz;
    }
};

/// The closest hit found so far during traversal.
struct HitRecord
{
    float t;
    std::uint32_t prim; // PrimRef bits
    float b1, b2; // triangle barycentrics of p1, p2; quad (alpha, beta)
};
} // namespace rt::cpu
