// The book-3 estimator (RTTROYL §9-12): with probability 1/2 sample the BSDF, else pick one light of the
// scene's list uniformly and sample a direction towards it; weight by the BSDF pdf over the mixture pdf
// 1/2 bsdfPdf + 1/2 (1/N) sum_j lightPdf_j. No shadow ray: the next segment finds what the direction hits.
// Reads the globals `uniforms` and `lights` (Bindings.glsl).
#ifndef RT_MIXTURE_GLSL
#define RT_MIXTURE_GLSL

#include "Materials/Interaction.glsl"
#include "Math/Onb.glsl"
#include "Random.glsl"
#include "Sampling/LightSampling.glsl"

/// The BSDF strategy is the cosine lobe about ns, or the uniform sphere for an isotropic phase function.
/// False when the path must stop (the light sample failed, or the direction has no density).
bool scatterMixture(bool uniformSphere, vec3 p, vec3 ns, vec3 albedo, inout Rng rng, out ScatterSample s)
{
    s.direction = vec3(0.0);
    s.weight = vec3(0.0);
    uint n = uniforms.lightCount;
    vec3 wi;
    if (nextFloat(rng) < 0.5)
    {
        vec2 u2 = nextFloat2(rng);
        wi = uniformSphere ? sampleUniformSphere(u2) : onbToWorld(onbFromNormal(ns), sampleCosineHemisphere(u2));
    }
    else
    {
        float pick = nextFloat(rng);
        uint i = min(uint(pick * float(n)), n - 1u);
        vec2 u2 = nextFloat2(rng);
        LightSample ls;
        if (!sampleLight(lights[i], p, u2, ls))
            return false;
        wi = ls.wi;
    }
    float lightPdfSum = 0.0;
    for (uint j = 0u; j < n; ++j)
        lightPdfSum += lightPdf(lights[j], p, wi);
    float scatteringPdf = uniformSphere ? uniformSpherePdf() : max(0.0, dot(ns, wi)) / kPi;
    float pdf = 0.5 * scatteringPdf + 0.5 * (1.0 / float(n)) * lightPdfSum;
    if (pdf <= 0.0 || scatteringPdf <= 0.0)
        return false;
    s.direction = wi;
    s.weight = albedo * scatteringPdf / pdf;
    return true;
}

#endif
