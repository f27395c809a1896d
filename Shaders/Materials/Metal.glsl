// Fuzzy mirror (RTIOW §10), on the shared Shared/SpecularScattering.h: absorbed when the fuzzed direction
// points into the surface. Specular: never mixed with light sampling.
#ifndef RT_METAL_GLSL
#define RT_METAL_GLSL

#include "Materials/Interaction.glsl"
#include "Shared/Random.h"
#include "Shared/SpecularScattering.h"
#include "Textures/Texture.glsl"

bool scatterMetal(MaterialData m, SurfaceHit hit, inout Rng rng, out ScatterSample s)
{
    s.weight = evaluateTexture(m.albedoTexture, hit.uv, hit.position);
    return sampleFuzzyMirror(hit.incoming, hit.shadingNormal, m.fuzz, nextFloat2(rng), s.direction);
}

#endif
