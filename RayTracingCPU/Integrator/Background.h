#pragma once

#include "Scene/Scene.h"

namespace rt::cpu
{
/// Radiance arriving from the background along `direction` (any length): constant, or RTIOW §4.2's vertical
/// gradient from color0 (looking down) to color1 (looking up).
inline vec3 backgroundRadiance(const Background& bg, const vec3& direction)
{
    if (bg.type == BackgroundType::Constant)
        return bg.color0;
    const float a = 0.5f * (glm::normalize(direction).y + 1.0f);
    return (1.0f - a) * bg.color0 + a * bg.color1;
}
} // namespace rt::cpu
