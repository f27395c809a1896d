// The sRGB transfer function of Common/Image/ImageIO.cpp (srgb8ToLinear), for image texels stored UNORM:
// the Vulkan spec lets a texture unit's own sRGB decode be approximate, and lavapipe's is 0.2 % dark in dark
// texels, which the heavy CPU/GPU agreement test saw on rtnw-earth.
#ifndef RT_TEXTURES_SRGB_GLSL
#define RT_TEXTURES_SRGB_GLSL

/// IEC 61966-2-1: encoded [0, 1] to linear.
vec3 srgbToLinear(vec3 c)
{
    vec3 linearPart = c / 12.92;
    vec3 powerPart = pow((c + 0.055) / 1.055, vec3(2.4));
    return mix(powerPart, linearPart, lessThanEqual(c, vec3(0.04045)));
}

#endif
