// Scattering at a vertex by material type (HostDevice.h MaterialType), written once for both engines: a
// host's shading scope (Shading/README.md). The materials' own sampling is Shared/DiffuseScattering.h and
// Shared/SpecularScattering.h; here the dispatch and book 3's mixture of the BSDF with light sampling. Each
// material draws its numbers before it uses any of them, the same count whatever happens, so a path's stream
// is consumed alike by every engine and every compiled variant. A material the render's scene does not use is
// dead code (kHas*). Every out parameter is set on entry: a path that left one unset gave NVIDIA's compiler
// undefined values to carry, which cost the megakernel 10-20 % on the light book scenes (docs/notebook, issue 34).
#ifndef RT_SHADING_SCATTER_H
#define RT_SHADING_SCATTER_H

#include "Shared/Bsdf/MicrofacetBsdf.h"
#include "Shared/DiffuseScattering.h"
#include "Shared/HostDevice.h"
#include "Shared/LightSampling.h"
#include "Shared/PathState.h"
#include "Shared/Random.h"
#include "Shared/SpecularScattering.h"
#include "Shared/Shading/Textures.h"

/// Book 3's estimator at a diffuse or isotropic vertex (RTTROYL §9-12): with probability 1/2 sample the BSDF
/// (`phase`: the isotropic phase function), else pick one light of the scene's list uniformly and sample a
/// direction towards it; weight by the BSDF pdf over the mixture pdf 1/2 bsdfPdf + 1/2 mean_j lightPdf_j
/// (one-sample MIS, balance heuristic). No shadow ray: the next segment finds what the direction hits. False
/// when the path must stop (the light sample failed, or the direction has no density).
RT_FN bool scatterMixture(bool phase, vec3 p, vec3 ns, vec3 albedo, RT_INOUT(Rng) rng, RT_OUT(ScatterSample) s)
{
    s.direction = vec3(0.0f);
    s.weight = vec3(0.0f);
    // Three numbers whichever strategy runs: the choice (whose upper half also picks the light) and the warp's two.
    const float choice = nextFloat(rng);
    const vec2 u = nextFloat2(rng);
    vec3 wi;
    uint picked = uniforms.lightCount; // the light sampled, whose pdf sampleLight returned; none yet
    float pickedPdf = 0.0f;
    if (choice < 0.5f)
        wi = sampleDiffuse(phase, ns, u);
    else
    {
        const float n = float(uniforms.lightCount);
        picked = uint(min((2.0f * choice - 1.0f) * n, n - 1.0f)); // the choice's bits
        LightSample ls;
        if (!sampleLight(lights[picked], p, u, ls))
            return false;
        wi = ls.wi;
        pickedPdf = ls.pdf; // = lightPdf(lights[picked], p, wi)
    }
    const float scatteringPdf = diffusePdf(phase, ns, wi);
    float lightPdfSum = 0.0f;
    // A GPU reads the first lights from a uniform buffer, which broadcasts (HostDevice.h kMixtureUniformLights).
    if (kHostHasMixtureLights && uniforms.lightCount <= kMixtureUniformLights)
        for (uint j = 0u; j < uniforms.lightCount; ++j)
            lightPdfSum += j == picked ? pickedPdf : lightPdf(mixtureLights[j], p, wi);
    else
        for (uint j = 0u; j < uniforms.lightCount; ++j)
            lightPdfSum += j == picked ? pickedPdf : lightPdf(lights[j], p, wi);
    const float pdf = 0.5f * scatteringPdf + 0.5f * lightPdfSum / float(uniforms.lightCount);
    if (!(scatteringPdf > 0.0f) || !(pdf > 0.0f))
        return false;
    s.direction = wi;
    s.weight = albedo * (scatteringPdf / pdf);
    return true;
}

/// A diffuse vertex's direction (`phase`: the isotropic phase function, else the Lambertian lobe), by BSDF
/// sampling or by book 3's mixture. Each material calls it with `phase` a constant, so that each has a copy of
/// its own with the other lobe folded away (one copy for both, `phase` decided at run time, was slower on
/// NVIDIA's compiler).
RT_FN bool scatterDiffuse(bool phase, RT_IN(MaterialData) m, RT_IN(SurfaceHit) hit, RT_INOUT(Rng) rng,
                          RT_OUT(ScatterSample) s)
{
    const vec3 albedo = evaluateTexture(m.albedoTexture, hit.uv, hit.position);
    if (settingEstimator() == RT_ENUM(Estimator, Mixture) && uniforms.lightCount > 0u)
        return scatterMixture(phase, hit.position, hit.shadingNormal, albedo, rng, s);
    s.direction = sampleDiffuse(phase, hit.shadingNormal, nextFloat2(rng));
    s.weight = albedo;
    return true;
}

/// Whether material type `type` is one of the microfacet BSDFs (Shared/Bsdf/MicrofacetBsdf.h), which the path
/// vertex samples and NEE evaluates through MicrofacetBsdf. Those the render's scene does not use are dead code.
RT_FN bool isMicrofacet(RT_TAG(MaterialType) type)
{
    return (kHasConductor && type == RT_ENUM(MaterialType, Conductor)) ||
           (kHasRoughDielectric && type == RT_ENUM(MaterialType, RoughDielectric)) ||
           (kHasGltfPbr && type == RT_ENUM(MaterialType, GltfPbr));
}

/// The microfacet BSDF of material `m` at `hit`, its textures read there and its roughness raised to
/// kMinMicrofacetAlpha.
RT_FN MicrofacetBsdf microfacetBsdfAt(RT_IN(MaterialData) m, RT_IN(SurfaceHit) hit)
{
    MicrofacetBsdf b;
    b.type = m.type;
    b.frame = onbFromNormal(m.type == RT_ENUM(MaterialType, RoughDielectric) ? hit.normal : hit.shadingNormal);
    b.conductor.alphaX = max(m.alphaX, kMinMicrofacetAlpha);
    b.conductor.alphaY = max(m.alphaY, kMinMicrofacetAlpha);
    b.conductor.schlick = m.fresnel == RT_ENUM(FresnelModel, Schlick);
    b.conductor.f0 = vec3(0.0f);
    b.conductor.eta = m.eta;
    b.conductor.k = m.k;
    b.gltf.baseColor = vec3(0.0f);
    b.gltf.metallic = m.metallic;
    b.gltf.alpha = b.conductor.alphaX;
    const float r0 = (m.ior - 1.0f) / (m.ior + 1.0f);
    b.gltf.f0 = r0 * r0;
    b.alpha = b.conductor.alphaX;
    b.ior = m.ior;
    if (m.type == RT_ENUM(MaterialType, Conductor) && b.conductor.schlick)
        b.conductor.f0 = evaluateTexture(m.albedoTexture, hit.uv, hit.position);
    if (m.type == RT_ENUM(MaterialType, GltfPbr))
    {
        b.gltf.baseColor = evaluateTexture(m.albedoTexture, hit.uv, hit.position);
        if (m.metallicRoughnessTexture != kNoIndex)
        {
            const vec3 texel = evaluateTexture(m.metallicRoughnessTexture, hit.uv, hit.position);
            b.gltf.metallic *= texel.z;
            b.gltf.alpha = max(m.alphaX * texel.y * texel.y, kMinMicrofacetAlpha);
        }
    }
    return b;
}

/// The direction leaving a vertex of material `m` and the factor it multiplies the throughput by: false when
/// the path ends here (absorbed, a light, a failed light sample). Diffuse and isotropic vertices sample their
/// lobe (BSDF only) or book 3's mixture; NEE's vertices are the path vertex's own.
RT_FN bool scatter(RT_IN(MaterialData) m, RT_IN(SurfaceHit) hit, RT_INOUT(Rng) rng, RT_OUT(ScatterSample) s)
{
    s.direction = vec3(0.0f);
    s.weight = vec3(0.0f);
    switch (m.type)
    {
    case RT_ENUM(MaterialType, Lambertian):
        if (kHasLambertian)
            return scatterDiffuse(false, m, hit, rng, s);
        break;
    case RT_ENUM(MaterialType, Isotropic):
        if (kHasIsotropic)
            return scatterDiffuse(true, m, hit, rng, s);
        break;
    case RT_ENUM(MaterialType, Metal):
        if (kHasMetal)
        {
            const vec2 u = nextFloat2(rng);
            s.weight = evaluateTexture(m.albedoTexture, hit.uv, hit.position);
            return sampleFuzzyMirror(hit.incoming, hit.shadingNormal, m.fuzz, u, s.direction);
        }
        break;
    case RT_ENUM(MaterialType, Dielectric):
        if (kHasDielectric)
        {
            s.direction = sampleDielectric(hit.incoming, hit.shadingNormal, hit.frontFace ? 1.0f / m.ior : m.ior,
                                           m.fresnel, nextFloat(rng));
            s.weight = vec3(1.0f); // clear glass
            return true;
        }
        break;
    case RT_ENUM(MaterialType, DiffuseLight): break; // emits, does not scatter
    case RT_ENUM(MaterialType, Conductor):
    case RT_ENUM(MaterialType, RoughDielectric):
    case RT_ENUM(MaterialType, GltfPbr): break; // the path vertex's own (isMicrofacet)
    }
    return false;
}

#endif
