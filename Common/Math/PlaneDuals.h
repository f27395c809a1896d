#pragma once

#include "Math/Math.h"

namespace rt
{
/// The dual edge vectors of the parallelogram q + a u + b v: for a point x of its plane, a = (x - q) . ua and
/// b = (x - q) . vb, two dot products instead of a 2x2 solve (RTTNW §6.4, with w = n / |n|^2, n = u x v).
/// Shared by the CPU engine's quads and the light records of both engines.
struct PlaneDuals
{
    vec3 ua;
    vec3 vb;
};

inline PlaneDuals planeDuals(const vec3& u, const vec3& v)
{
    const vec3 n = glm::cross(u, v);
    const vec3 w = n / glm::dot(n, n);
    return {glm::cross(v, w), glm::cross(w, u)};
}
} // namespace rt
