// Perlin gradient noise and turbulence (RTTNW §5; Perlin, "An Image Synthesizer", SIGGRAPH 1985: Hermite-
// smoothed trilinear interpolation of random gradients), written once for both engines (Shared/ShaderLang.h).
// The tables are generated once on the host (Scene/Perlin.h) and uploaded unchanged: GLSL reads them as the
// global `perlinTables` (Bindings.glsl), C++ passes them (RT_GLOBAL).
#ifndef RT_SHARED_PERLIN_H
#define RT_SHARED_PERLIN_H

#include "Shared/HostDevice.h"
#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

/// Noise in [-1, 1] at p (world units): the lattice gradients' planes, blended by the smoothed fractions.
RT_FN float perlinNoise(RT_GLOBAL(PerlinData, perlinTables) vec3 p)
{
    const vec3 f = floor(p);
    const vec3 w = p - f;
    const int i = int(f.x);
    const int j = int(f.y);
    const int k = int(f.z);
    const vec3 s = w * w * (3.0f - 2.0f * w); // Hermite smoothing
    float accum = 0.0f;
    for (int di = 0; di < 2; ++di)
        for (int dj = 0; dj < 2; ++dj)
            for (int dk = 0; dk < 2; ++dk)
            {
                const uint index = perlinTables.permX[(i + di) & 255] ^ perlinTables.permY[(j + dj) & 255] ^
                                   perlinTables.permZ[(k + dk) & 255];
                const vec3 g = perlinTables.gradients[index];
                const float weight =
                    (di != 0 ? s.x : 1.0f - s.x) * (dj != 0 ? s.y : 1.0f - s.y) * (dk != 0 ? s.z : 1.0f - s.z);
                accum += weight * dot(g, w - vec3(di, dj, dk));
            }
    return accum;
}

/// |sum of `depth` octaves of noise with halving weights| (RTTNW §5.7).
RT_FN float perlinTurbulence(RT_GLOBAL(PerlinData, perlinTables) vec3 p, int depth)
{
    float accum = 0.0f;
    vec3 q = p;
    float weight = 1.0f;
    for (int i = 0; i < depth; ++i)
    {
        accum += weight * perlinNoise(RT_PASS(perlinTables) q);
        weight *= 0.5f;
        q *= 2.0f;
    }
    return abs(accum);
}

RT_SHADER_NAMESPACE_END

#endif
