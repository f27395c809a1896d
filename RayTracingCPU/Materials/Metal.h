#pragma once

#include "Sampling/Warps.h"

namespace rt::cpu
{
/// Mirror reflection of `d` about `ns` perturbed by a point of the sphere of radius `fuzz` centred on the
/// mirror direction (RTIOW §10.6): the fuzz follows the reflected direction, not a world axis. Returns false
/// when the perturbed direction points into the surface (the ray is absorbed).
inline bool scatterMetal(const vec3& d, const vec3& ns, float fuzz, const vec2& u, vec3& wi)
{
    wi = glm::normalize(reflect(d, ns)) + fuzz * sampleUniformSphere(u);
    return glm::dot(wi, ns) > 0.0f;
}
} // namespace rt::cpu
