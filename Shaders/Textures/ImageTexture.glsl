// Image textures: the nearest texel of the CPU engine, fetched by integer coordinates so that no sampler
// rounding decides the texel. The images are VK_FORMAT_R8G8B8A8_UNORM holding sRGB-encoded texels, decoded
// with the CPU's formula (Srgb.glsl), or linear data (glTF's metallic-roughness: TextureData::linear) read as
// the UNORM values. Reads the global sampler array `images` (Bindings.glsl).
#ifndef RT_IMAGE_TEXTURE_GLSL
#define RT_IMAGE_TEXTURE_GLSL

#include "Textures/Srgb.glsl"

/// uv clamped to [0, 1]; texel (int(u w), int((1 - v) h)), clamped to the last column / row (row 0 on top);
/// decoded from sRGB unless `linear`.
vec3 imageTexel(uint image, vec2 uv, bool linear)
{
    ivec2 size = textureSize(images[nonuniformEXT(image)], 0);
    float u = clamp(uv.x, 0.0, 1.0);
    float v = clamp(uv.y, 0.0, 1.0);
    int i = min(int(u * float(size.x)), size.x - 1);
    int j = min(int((1.0 - v) * float(size.y)), size.y - 1);
    vec3 texel = texelFetch(images[nonuniformEXT(image)], ivec2(i, j), 0).rgb;
    return linear ? texel : srgbToLinear(texel);
}

#endif
