#pragma once

#include "Math/Math.h"

namespace rt
{
/// Orthonormal basis around a unit vector `w`: local (x, y, z) -> world x u + y v + z w.
/// Branchless construction from Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017.
struct Onb
{
    vec3 u, v, w;

    explicit Onb(const vec3& n) : w(n)
    {
        const float sign = std::copysign(1.0f, n.z);
        const float a = -1.0f / (sign + n.z);
        const float b = n.x * n.y * a;
        u = vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
        v = vec3(b, sign + n.y * n.y * a, -n.y);
    }

    vec3 toWorld(const vec3& local) const { return local.x * u + local.y * v + local.z * w; }
};
} // namespace rt
