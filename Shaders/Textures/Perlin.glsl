// Perlin gradient noise and turbulence (RTTNW §5; Perlin, "An Image Synthesizer", SIGGRAPH 1985): the twins
// of Common/Scene/Perlin.h, evaluating the same tables (perlinTables(), uploaded unchanged).
// Reads the global `perlinTables` (a PerlinData block, declared by Bindings.glsl).
#ifndef RT_PERLIN_GLSL
#define RT_PERLIN_GLSL

/// Noise in [-1, 1] at p: Hermite-smoothed trilinear interpolation of the lattice gradients.
float perlinNoise(vec3 p)
{
    vec3 f = floor(p);
    vec3 w = p - f;
    int i = int(f.x);
    int j = int(f.y);
    int k = int(f.z);
    vec3 s = w * w * (3.0 - 2.0 * w);
    float accum = 0.0;
    for (int di = 0; di < 2; ++di)
        for (int dj = 0; dj < 2; ++dj)
            for (int dk = 0; dk < 2; ++dk)
            {
                uint index = perlinTables.permX[(i + di) & 255] ^ perlinTables.permY[(j + dj) & 255] ^
                             perlinTables.permZ[(k + dk) & 255];
                vec3 g = perlinTables.gradients[index];
                float weight = (di != 0 ? s.x : 1.0 - s.x) * (dj != 0 ? s.y : 1.0 - s.y) * (dk != 0 ? s.z : 1.0 - s.z);
                accum += weight * dot(g, w - vec3(di, dj, dk));
            }
    return accum;
}

/// |sum of `depth` octaves with halving weights| (RTTNW §5.7).
float perlinTurbulence(vec3 p, int depth)
{
    float accum = 0.0;
    vec3 q = p;
    float weight = 1.0;
    for (int i = 0; i < depth; ++i)
    {
        accum += weight * perlinNoise(q);
        weight *= 0.5;
        q *= 2.0;
    }
    return abs(accum);
}

#endif
