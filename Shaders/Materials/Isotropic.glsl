// Isotropic phase function of constant media (RTTNW §9): uniform sphere, pdf 1/(4 pi); weight = albedo
// (BSDF only) or the mixture weight. Reads the global `uniforms` (Bindings.glsl).
#ifndef RT_ISOTROPIC_GLSL
#define RT_ISOTROPIC_GLSL

#include "Materials/Mixture.glsl"
#include "Textures/Texture.glsl"

bool scatterIsotropic(MaterialData m, SurfaceHit hit, inout Rng rng, out ScatterSample s)
{
    vec3 albedo = evaluateTexture(m.albedoTexture, hit.uv, hit.position);
    if (settingEstimator() != Estimator_Mixture || uniforms.lightCount == 0u)
    {
        s.direction = sampleUniformSphere(nextFloat2(rng));
        s.weight = albedo;
        return true;
    }
    return scatterMixture(true, hit.position, hit.shadingNormal, albedo, rng, s);
}

#endif
