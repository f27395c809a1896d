#pragma once

#include "Math/Math.h"

namespace rt
{
/// A ray o + t d at shutter time `time` in [0, 1). `direction` need not be unit length unless a function says so.
struct Ray
{
    vec3 origin{0.0f};
    vec3 direction{0.0f, 0.0f, 1.0f};
    float time = 0.0f;

    vec3 at(float t) const { return origin + t * direction; }
};
} // namespace rt
