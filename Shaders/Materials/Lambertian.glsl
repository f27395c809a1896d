// Lambertian reflection: cosine-weighted about the shading normal; weight = albedo (BSDF only) or the
// mixture weight. Reads the global `uniforms` (Bindings.glsl).
#ifndef RT_LAMBERTIAN_GLSL
#define RT_LAMBERTIAN_GLSL

#include "Materials/Mixture.glsl"
#include "Textures/Texture.glsl"

bool scatterLambertian(MaterialData m, SurfaceHit hit, inout Rng rng, out ScatterSample s)
{
    vec3 albedo = evaluateTexture(m.albedoTexture, hit.uv, hit.position);
    if (settingEstimator() != Estimator_Mixture || uniforms.lightCount == 0u)
    {
        s.direction = onbToWorld(onbFromNormal(hit.shadingNormal), sampleCosineHemisphere(nextFloat2(rng)));
        s.weight = albedo;
        return true;
    }
    return scatterMixture(false, hit.position, hit.shadingNormal, albedo, rng, s);
}

#endif
