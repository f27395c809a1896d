// Glass (RTIOW §11), on the shared Shared/SpecularScattering.h: refraction by Snell's law, reflection under
// total internal reflection or with the probability of the material's Fresnel model (Schlick's or exact).
// The weight is 1 (clear glass). The random number is drawn before the choice, as the CPU engine draws it.
#ifndef RT_DIELECTRIC_GLSL
#define RT_DIELECTRIC_GLSL

#include "Materials/Interaction.glsl"
#include "Shared/Random.h"
#include "Shared/SpecularScattering.h"

bool scatterDielectric(MaterialData m, SurfaceHit hit, inout Rng rng, out ScatterSample s)
{
    float u = nextFloat(rng);
    s.direction = sampleDielectric(hit.incoming, hit.shadingNormal, hit.frontFace ? 1.0 / m.ior : m.ior, m.fresnel, u);
    s.weight = vec3(1.0);
    return true;
}

#endif
