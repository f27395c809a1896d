// The scene's background seen along a direction (HostDevice.h BackgroundType), written once for both engines:
// a host's shading scope (Shading/README.md). The path vertex adds it where a ray leaves the scene.
#ifndef RT_SHADING_BACKGROUND_H
#define RT_SHADING_BACKGROUND_H

#include "Shared/HostDevice.h"

/// Radiance arriving from the background along `direction` (any length): constant, or RTIOW §4.2's vertical
/// gradient from background0 (looking down) to background1 (looking up).
RT_FN vec3 background(vec3 direction)
{
    if (!kHasGradientBackground || uniforms.backgroundType == RT_ENUM(BackgroundType, Constant))
        return uniforms.background0;
    const float a = 0.5f * (normalize(direction).y + 1.0f);
    return (1.0f - a) * uniforms.background0 + a * uniforms.background1;
}

#endif
