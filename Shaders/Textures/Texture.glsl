// Texture evaluation by type tag, the twin of the CPU engine's textures (HostDevice.h TextureType).
// p is the world-space point (checker and Perlin textures are solid textures), uv the surface coordinates.
// Reads the global `textures` (Bindings.glsl). A texture kind that no material of the pipeline's scene reads
// is dead code (kHas*, Specialization.glsl): without image textures nothing reads the sampler array.
#ifndef RT_TEXTURE_GLSL
#define RT_TEXTURE_GLSL

#include "Shared/HostDevice.h"
#include "Textures/ImageTexture.glsl"
#include "Textures/Perlin.glsl"

/// 3-D checker (RTTNW §4): cells of size `scale`, color0 where the sum of the cell indices is even.
vec3 checkerTexture(TextureData t, vec3 p)
{
    int s = int(floor(p.x / t.scale)) + int(floor(p.y / t.scale)) + int(floor(p.z / t.scale));
    return (s & 1) == 0 ? t.color0 : t.color1; // & 1: the parity of negative sums too
}

vec3 evaluateTexture(uint index, vec2 uv, vec3 p)
{
    TextureData t = textures[index];
    switch (t.type)
    {
    case TextureType_Solid: return t.color0;
    case TextureType_Checker:
        if (kHasCheckerTextures)
            return checkerTexture(t, p);
        break;
    case TextureType_Image:
        if (kHasImageTextures)
            return imageTexel(t.image, uv);
        break;
    case TextureType_Noise:
        if (kHasNoiseTextures)
            return vec3(0.5 * (1.0 + perlinNoise(t.scale * p)));
        break;
    case TextureType_Turbulence:
        if (kHasNoiseTextures)
            return vec3(perlinTurbulence(t.scale * p, 7));
        break;
    case TextureType_Marble:
        if (kHasNoiseTextures)
            return vec3(0.5 * (1.0 + sin(t.scale * p.z + 10.0 * perlinTurbulence(p, 7))));
        break;
    }
    return vec3(0.0);
}

#endif
