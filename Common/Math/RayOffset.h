#pragma once

#include "Math/Math.h"
#include "Shared/RayOffset.h"

namespace rt
{
/// Shared/RayOffset.h's offsetRayOrigin, with the scale of surfaces whose intersection test errs in
/// proportion to p (spheres) by default. A quad is two triangles on the GPU, each scaled by its own three
/// corners; the CPU takes all four, so the two engines' offsets can differ on tilted quads (by a factor below
/// 2; both clear the error).
inline vec3 offsetRayOrigin(const vec3& p, const vec3& n, float scale = 1.0f)
{
    return shader::offsetRayOrigin(p, n, scale);
}

using shader::planarOffsetScale;
} // namespace rt
