#include "SceneFile/JsonTransform.h"

#include <cmath>

#include <spdlog/fmt/fmt.h>

namespace rt
{
namespace
{
Transform readMatrix(const JsonNode& rows)
{
    const std::size_t n = rows.size();
    if (n != 3 && n != 4)
        rows.fail(fmt::format("expected 3 or 4 rows of 4 numbers, got {} rows", n));
    mat4 m(1.0f);
    for (std::size_t r = 0; r < n; ++r)
    {
        const JsonNode row = rows[r];
        if (row.size() != 4)
            row.fail(fmt::format("expected a row of 4 numbers, got {}", row.size()));
        for (std::size_t c = 0; c < 4; ++c)
        {
            const float x = row[c].number();
            if (r == 3 && x != (c == 3 ? 1.0f : 0.0f))
                row[c].fail("the fourth row of an affine matrix must be 0 0 0 1");
            m[static_cast<int>(c)][static_cast<int>(r)] = x; // glm is column-major: m[column][row]
        }
    }
    const float det = glm::determinant(mat3(m));
    if (!std::isfinite(det) || det == 0.0f)
        rows.fail("the matrix is not invertible");
    return {m};
}

Transform readRotation(const JsonNode& spec)
{
    spec.allowOnly({"axis", "degrees"});
    const vec3 axis = spec["axis"].vector3();
    if (glm::length(axis) == 0.0f)
        spec["axis"].fail("the rotation axis must not be zero");
    return Transform::rotate(axis, spec["degrees"].number());
}

Transform readStep(const JsonNode& step)
{
    if (!step.value().is_object() || step.value().size() != 1)
        step.fail("expected one step: {\"translate\": ...}, {\"scale\": ...}, {\"rotate_x\": ...}, {\"rotate_y\": "
                  "...}, {\"rotate_z\": ...}, {\"rotate\": ...} or {\"matrix\": ...}");
    step.allowOnly({"translate", "scale", "rotate_x", "rotate_y", "rotate_z", "rotate", "matrix"});
    const std::string key = step.value().begin().key();
    const JsonNode v = step[key];
    if (key == "translate")
        return Transform::translate(v.vector3());
    if (key == "scale")
    {
        const vec3 s = v.value().is_array() ? v.vector3() : vec3(v.number());
        if (s.x == 0.0f || s.y == 0.0f || s.z == 0.0f)
            v.fail("a scale factor must not be zero");
        return Transform::scale(s);
    }
    if (key == "rotate_x")
        return Transform::rotateX(v.number());
    if (key == "rotate_y")
        return Transform::rotateY(v.number());
    if (key == "rotate_z")
        return Transform::rotateZ(v.number());
    if (key == "rotate")
        return readRotation(v);
    return readMatrix(v);
}
} // namespace

Transform readTransform(const JsonNode& steps)
{
    if (steps.size() == 0)
        return Transform::identity();
    // Starting from the first step, not the identity: identity * M turns M's -0 entries into +0, and a
    // written matrix must come back bit for bit (--export-scene).
    Transform t = readStep(steps[0]);
    for (std::size_t i = 1; i < steps.size(); ++i)
        t = t * readStep(steps[i]);
    // A product of valid steps can still lose its inverse in float (a scale of 1e-30 times 1e-30).
    const float det = glm::determinant(mat3(t.m));
    if (!std::isfinite(det) || det == 0.0f)
        steps.fail("the steps multiply to a transform that is not invertible in float");
    return t;
}
} // namespace rt
