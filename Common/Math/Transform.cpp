#include "Math/Transform.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace rt
{
Transform Transform::translate(const vec3& t) { return {glm::translate(mat4(1.0f), t)}; }

Transform Transform::rotateY(float degrees)
{
    // Built from the exact cosine and sine rather than glm::rotate's general axis formula, so that a
    // rotation by 0 degrees is exactly the identity.
    const float c = std::cos(radians(degrees));
    const float s = std::sin(radians(degrees));
    mat4 m(1.0f);
    m[0][0] = c; // column 0 = image of +x
    m[0][2] = -s;
    m[2][0] = s; // column 2 = image of +z
    m[2][2] = c;
    return {m};
}

Transform Transform::rotateX(float degrees)
{
    const float c = std::cos(radians(degrees));
    const float s = std::sin(radians(degrees));
    mat4 m(1.0f);
    m[1][1] = c; // column 1 = image of +y
    m[1][2] = s;
    m[2][1] = -s; // column 2 = image of +z
    m[2][2] = c;
    return {m};
}

Transform Transform::rotateZ(float degrees)
{
    const float c = std::cos(radians(degrees));
    const float s = std::sin(radians(degrees));
    mat4 m(1.0f);
    m[0][0] = c; // column 0 = image of +x
    m[0][1] = s;
    m[1][0] = -s; // column 1 = image of +y
    m[1][1] = c;
    return {m};
}

Transform Transform::rotate(const vec3& axis, float degrees)
{
    return {glm::rotate(mat4(1.0f), radians(degrees), glm::normalize(axis))};
}

Transform Transform::scale(const vec3& s) { return {glm::scale(mat4(1.0f), s)}; }

Transform Transform::inverse() const { return {glm::inverse(m)}; }

vec3 Transform::normal(const vec3& n) const { return glm::transpose(glm::inverse(mat3(m))) * n; }

Aabb Transform::bounds(const Aabb& box) const
{
    Aabb out;
    for (int corner = 0; corner < 8; ++corner)
    {
        const vec3 p((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                     (corner & 4) ? box.max.z : box.min.z);
        out.expand(point(p));
    }
    return out;
}

std::optional<float> Transform::uniformScale(float tolerance) const
{
    const mat3 a(m);
    const mat3 ata = glm::transpose(a) * a; // = s^2 I for a scaled rotation
    const float s2 = ata[0][0];
    if (!(s2 > 0.0f))
        return std::nullopt;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
        {
            const float expected = (i == j) ? s2 : 0.0f;
            if (std::fabs(ata[i][j] - expected) > tolerance * s2)
                return std::nullopt;
        }
    if (glm::determinant(a) <= 0.0f)
        return std::nullopt; // a mirror flips the sphere's inside and outside: not supported
    return std::sqrt(s2);
}
} // namespace rt
