// Fuzzy mirror (RTIOW §10): the mirror direction plus `fuzz` times a uniform point of the unit sphere, so
// the fuzz is centred on the reflected direction; absorbed when it points into the surface. Specular: never
// mixed with light sampling.
#ifndef RT_METAL_GLSL
#define RT_METAL_GLSL

#include "Materials/Interaction.glsl"
#include "Random.glsl"
#include "Shared/Warps.h"
#include "Textures/Texture.glsl"

bool scatterMetal(MaterialData m, SurfaceHit hit, inout Rng rng, out ScatterSample s)
{
    vec3 albedo = evaluateTexture(m.albedoTexture, hit.uv, hit.position);
    vec3 reflected = normalize(reflect(hit.incoming, hit.shadingNormal));
    s.direction = reflected + m.fuzz * sampleUniformSphere(nextFloat2(rng));
    s.weight = albedo;
    return dot(s.direction, hit.shadingNormal) > 0.0;
}

#endif
