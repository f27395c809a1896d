#pragma once

#include <bit>
#include <cstdint>

#include "Math/Math.h"

namespace rt
{
/// Moves a surface point off the surface along the geometric normal `n` (pointing to the side the new ray
/// leaves from) by an amount that scales with the point's magnitude, so that the new ray, started with
/// tmin = 0, does not hit the surface it leaves.
/// Wächter & Binder, "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems ch. 6, 2019:
/// 256 ulps away from the origin, 1/65536 absolute below |p| = 1/32. The GLSL twin is Shaders/RayOffset.glsl.
inline vec3 offsetRayOrigin(const vec3& p, const vec3& n)
{
    constexpr float kOrigin = 1.0f / 32.0f;
    constexpr float kFloatScale = 1.0f / 65536.0f;
    constexpr float kIntScale = 256.0f;
    vec3 out;
    for (int i = 0; i < 3; ++i)
    {
        const auto offset = static_cast<std::int32_t>(kIntScale * n[i]);
        const std::int32_t bits = std::bit_cast<std::int32_t>(p[i]);
        const float moved = std::bit_cast<float>(bits + (p[i] < 0.0f ? -offset : offset));
        out[i] = std::fabs(p[i]) < kOrigin ? p[i] + kFloatScale * n[i] : moved;
    }
    return out;
}
} // namespace rt
