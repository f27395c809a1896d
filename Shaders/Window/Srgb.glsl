// The sRGB transfer curve (IEC 61966-2-1), as Common/Image/ImageIO.cpp applies it to PNGs: the window shows
// what `--output` would write.
#ifndef RT_SRGB_GLSL
#define RT_SRGB_GLSL

vec3 srgbEncode(vec3 linear)
{
    vec3 c = clamp(linear, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}

/// What the fragment shader writes for the linear colour `linear`: encoded here when the swapchain format does
/// not encode on write (DisplayPushConstants::encodeSrgb).
vec4 displayColor(vec3 linear, uint encodeSrgb)
{
    return vec4(encodeSrgb != 0u ? srgbEncode(linear) : clamp(linear, 0.0, 1.0), 1.0);
}

#endif
