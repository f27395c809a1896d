// The book-3 estimator (RTTROYL §9-12): with probability 1/2 sample the BSDF, else pick one light of the
// scene's list uniformly and sample a direction towards it; weight by the BSDF pdf over the mixture pdf
// 1/2 bsdfPdf + 1/2 mean_j lightPdf_j (one-sample MIS, balance heuristic). No shadow ray: the next segment
// finds what the direction hits. The twin of RayTracingCPU/Integrator/PathIntegrator.h.
// Reads the globals `uniforms`, `lights` and `mixtureLights` (Bindings.glsl).
#ifndef RT_MIXTURE_GLSL
#define RT_MIXTURE_GLSL

#include "Materials/Interaction.glsl"
#include "Shared/Onb.h"
#include "Shared/Random.h"
#include "Shared/LightSampling.h"

/// The BSDF strategy is the cosine lobe about ns, or the uniform sphere for an isotropic phase function.
/// False when the path must stop (the light sample failed, or the direction has no density).
bool scatterMixture(bool uniformSphere, vec3 p, vec3 ns, vec3 albedo, inout Rng rng, out ScatterSample s)
{
    s.direction = vec3(0.0);
    s.weight = vec3(0.0);
    // Three numbers per vertex whichever strategy runs: the choice (whose upper half also picks the light)
    // and the two of the warp. The CPU engine draws the same.
    float choice = nextFloat(rng);
    vec2 u = nextFloat2(rng);
    vec3 wi;
    uint picked = uniforms.lightCount; // the light sampled, whose pdf sampleLight returned; none yet
    float pickedPdf = 0.0;
    if (choice < 0.5)
        wi = uniformSphere ? sampleUniformSphere(u) : onbToWorld(onbFromNormal(ns), sampleCosineHemisphere(u));
    else
    {
        float n = float(uniforms.lightCount);
        float pick = min((2.0 * choice - 1.0) * n, n - 1.0);
        LightSample ls;
        picked = uint(pick);
        if (!sampleLight(lights[picked], p, u, ls))
            return false;
        wi = ls.wi;
        pickedPdf = ls.pdf; // = lightPdf(lights[picked], p, wi)
    }
    float scatteringPdf = uniformSphere ? uniformSpherePdf() : cosineHemispherePdf(dot(ns, wi));
    float lightPdfSum = 0.0;
    if (uniforms.lightCount <= kMixtureUniformLights)
        for (uint j = 0u; j < uniforms.lightCount; ++j)
            lightPdfSum += j == picked ? pickedPdf : lightPdf(mixtureLights[j], p, wi);
    else
        for (uint j = 0u; j < uniforms.lightCount; ++j)
            lightPdfSum += j == picked ? pickedPdf : lightPdf(lights[j], p, wi);
    float pdf = 0.5 * scatteringPdf + 0.5 * lightPdfSum / float(uniforms.lightCount);
    if (!(scatteringPdf > 0.0) || !(pdf > 0.0))
        return false;
    s.direction = wi;
    s.weight = albedo * (scatteringPdf / pdf);
    return true;
}

#endif
