// The scene background seen along direction d (HostDevice.h BackgroundType). Reads `uniforms`.
#ifndef RT_BACKGROUND_GLSL
#define RT_BACKGROUND_GLSL

#include "Shared/HostDevice.h"

vec3 background(vec3 d)
{
    if (!kHasGradientBackground || uniforms.backgroundType == BackgroundType_Constant)
        return uniforms.background0;
    float a = 0.5 * (normalize(d).y + 1.0);
    return mix(uniforms.background0, uniforms.background1, a);
}

#endif
