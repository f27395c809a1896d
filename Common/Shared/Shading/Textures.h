// Texture evaluation by type tag (HostDevice.h TextureType; RTTNW §4-5), written once for both engines: a host's
// shading scope (Shading/README.md). p is the render-space point (checker and Perlin textures are solid textures,
// evaluated at p + TextureData::origin: the scene's own coordinates),
// uv the surface coordinates; colours are linear RGB. Image texels are each engine's own fetch (`imageTexel`:
// the CPU's array, the GPU's sampler array, the same nearest texel), which the host provides: decoded from sRGB,
// or read as linear data (texel / 255) for a texture whose `linear` is set (glTF's metallic-roughness).
#ifndef RT_SHADING_TEXTURES_H
#define RT_SHADING_TEXTURES_H

#include "Shared/HostDevice.h"
#include "Shared/Perlin.h"

/// 3-D checker (RTTNW §4): cells of size `scale`, color0 where the sum of the cell indices is even.
RT_FN vec3 checkerTexture(RT_IN(TextureData) t, vec3 p)
{
    const vec3 c = floor(p / t.scale);
    const int sum = int(c.x) + int(c.y) + int(c.z);
    return (sum & 1) == 0 ? t.color0 : t.color1; // & 1: the parity of negative sums too
}

/// Texture `index` at the point p with surface coordinates uv. A texture kind the render's scene does not use
/// is dead code (kHas*): with none but solid colours, a texture is its colour.
RT_FN vec3 evaluateTexture(uint index, vec2 uv, vec3 p)
{
    if (!kHasCheckerTextures && !kHasImageTextures && !kHasNoiseTextures)
        return textures[index].color0;
    const TextureData t = textures[index];
    const vec3 q = p + t.origin; // solid textures: the point in the scene's own coordinates
    switch (t.type)
    {
    case RT_ENUM(TextureType, Solid): return t.color0;
    case RT_ENUM(TextureType, Checker):
        if (kHasCheckerTextures)
            return checkerTexture(t, q);
        break;
    case RT_ENUM(TextureType, Image):
        if (kHasImageTextures)
            return imageTexel(t.image, uv, t.linear != 0u);
        break;
    case RT_ENUM(TextureType, Noise):
        if (kHasNoiseTextures)
            return vec3(0.5f * (1.0f + perlinNoise(RT_PASS(perlinTables) t.scale * q)));
        break;
    case RT_ENUM(TextureType, Turbulence):
        if (kHasNoiseTextures)
            return vec3(perlinTurbulence(RT_PASS(perlinTables) t.scale * q, 7));
        break;
    case RT_ENUM(TextureType, Marble):
        // The books' code turbulates the unscaled point (RTTNW §5.8, v3 and v4 alike); scaling it as well
        // gives fine-grained noise instead of the books' broad veins.
        if (kHasNoiseTextures)
            return vec3(0.5f * (1.0f + sin(t.scale * q.z + 10.0f * perlinTurbulence(RT_PASS(perlinTables) q, 7))));
        break;
    }
    return vec3(0.0f);
}

#endif
