// Affine transforms as 4x4 matrices (last row 0 0 0 1), named by the frames they map between:
// `worldFromObject` maps object-space points to world space, so composition reads right to left.
#pragma once

#include <optional>

#include "Math/Aabb.h"
#include "Math/Math.h"

namespace rt
{
struct Transform
{
    mat4 m{1.0f};

    static Transform identity() { return {}; }
    static Transform translate(const vec3& t);
    /// Rotation about +y by `degrees`, counter-clockwise seen from +y (the books' rotate_y).
    static Transform rotateY(float degrees);
    /// Rotations about +x and +z, counter-clockwise seen from the positive axis, as rotateY.
    static Transform rotateX(float degrees);
    static Transform rotateZ(float degrees);
    /// Rotation by `degrees` about `axis` (any length > 0), counter-clockwise seen from its tip.
    static Transform rotate(const vec3& axis, float degrees);
    static Transform scale(const vec3& s);

    Transform operator*(const Transform& rhs) const { return {m * rhs.m}; }
    Transform inverse() const;

    vec3 point(const vec3& p) const { return vec3(m * vec4(p, 1.0f)); }
    vec3 vector(const vec3& v) const { return vec3(m * vec4(v, 0.0f)); }
    /// Transforms a surface normal (by the inverse transpose); the result is not normalised.
    vec3 normal(const vec3& n) const;
    Aabb bounds(const Aabb& box) const;

    bool isIdentity() const { return m == mat4(1.0f); }
    /// If the linear part is a rotation times a uniform scale s > 0, returns s. Spheres stay spheres only then.
    std::optional<float> uniformScale(float tolerance = 1e-5f) const;
};
} // namespace rt
