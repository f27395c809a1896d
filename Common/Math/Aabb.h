#pragma once

#include <algorithm>

#include "Math/Math.h"

namespace rt
{
/// Axis-aligned bounding box; an empty box has min > max.
struct Aabb
{
    vec3 min{kInfinity};
    vec3 max{-kInfinity};

    Aabb() = default;
    Aabb(const vec3& a, const vec3& b) : min(glm::min(a, b)), max(glm::max(a, b)) {}

    void expand(const vec3& p)
    {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void expand(const Aabb& b)
    {
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }
    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    vec3 extent() const { return max - min; }
    vec3 centroid() const { return 0.5f * (min + max); }
    float surfaceArea() const
    {
        if (empty())
            return 0.0f;
        const vec3 d = extent();
        return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
    }
    int longestAxis() const
    {
        const vec3 d = extent();
        return (d.x >= d.y && d.x >= d.z) ? 0 : (d.y >= d.z ? 1 : 2);
    }
};
} // namespace rt
