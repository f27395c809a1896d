// glTF 2.0's metallic-roughness BRDF as its specification's Appendix B defines it (B.3.5 "Metal BRDF and
// Dielectric BRDF", B.3.6 "Fresnel"), for both engines (Shared/ShaderLang.h): with H the half vector of wo and wi
//   dielectric = fresnel_mix(ior, base/pi, specular) = (1 - F_d) base / pi + F_d specular,
//     F_d = f0 + (1 - f0)(1 - |wo.H|)^5, f0 = ((1 - ior) / (1 + ior))^2 (0.04 at the default ior 1.5)
//   metal = conductor_fresnel(base, specular) = (base + (1 - base)(1 - |wo.H|)^5) specular
//   f = (1 - metallic) dielectric + metallic metal
// with specular = D(H) G2(wo, wi) / (4 |cos_o| |cos_i|), GGX of alpha = roughness^2 (B.3.2; the caller squares).
// Sampled by one-sample MIS of the two lobes (the visible normals of the specular, the cosine of the diffuse)
// chosen by an estimate of their albedos at wo, and weighted by the mixture's pdf (Veach 1997 §9.2.4).
// Local frame: z the shading normal on the side of wo; reflection only.
#ifndef RT_SHARED_BSDF_GLTF_PBR_H
#define RT_SHARED_BSDF_GLTF_PBR_H

#include "Shared/Bsdf/BsdfSample.h"
#include "Shared/Fresnel.h"
#include "Shared/Microfacet.h"
#include "Shared/ShaderLang.h"
#include "Shared/Warps.h"

RT_SHADER_NAMESPACE_BEGIN

/// One shading point's glTF material, its textures already applied.
struct GltfPbrParams
{
    vec3 baseColor; // linear RGB, each channel in [0, 1]
    float metallic; // [0, 1]
    float alpha; // GGX roughness, roughness^2, >= kMinMicrofacetAlpha
    float f0; // the dielectric's reflectance at normal incidence, ((1 - ior) / (1 + ior))^2
};

/// Probability of sampling the specular lobe at wo: its estimated albedo over both lobes' (Fresnel at wo's
/// own cosine). 1 where the diffuse lobe is 0 (metallic 1 or a black base), so no direction of a non-zero f has
/// density 0.
RT_FN float gltfSpecularProbability(RT_IN(GltfPbrParams) p, float cosO)
{
    const float m = clamp(1.0f - cosO, 0.0f, 1.0f);
    const float fd = p.f0 + (1.0f - p.f0) * ((m * m) * (m * m) * m);
    const float specular = p.metallic + (1.0f - p.metallic) * fd;
    const float diffuse = (1.0f - p.metallic) * (1.0f - fd) * luminance(p.baseColor);
    return diffuse > 0.0f ? specular / (specular + diffuse) : 1.0f;
}

/// f(wo, wi) |cos theta_i| (0 unless both directions lie above the surface) and, in `pdf`, the density of
/// sampleGltfPbr for wi per unit solid angle: the lobes' mixture.
RT_FN vec3 evalGltfPbr(RT_IN(GltfPbrParams) p, vec3 wo, vec3 wi, RT_OUT(float) pdf)
{
    vec3 wm;
    pdf = 0.0f;
    if (!ggxReflectionHalfVector(wo, wi, wm))
        return vec3(0.0f);
    const float ps = gltfSpecularProbability(p, wo.z);
    pdf = ps * ggxReflectionPdf(wo, wm, p.alpha, p.alpha) + (1.0f - ps) * cosineHemispherePdf(wi.z);
    const float voh = abs(dot(wo, wm));
    const float m = clamp(1.0f - voh, 0.0f, 1.0f);
    const float m5 = (m * m) * (m * m) * m;
    const float fd = p.f0 + (1.0f - p.f0) * m5;
    const vec3 fm = p.baseColor + (vec3(1.0f) - p.baseColor) * m5;
    const float specular = ggxD(wm, p.alpha, p.alpha) * ggxG2(wo, wi, p.alpha, p.alpha) / (4.0f * wo.z); // x cos_i
    const vec3 dielectric = (1.0f - fd) * kInvPi * wi.z * p.baseColor + vec3(fd * specular);
    return (1.0f - p.metallic) * dielectric + p.metallic * specular * fm;
}

RT_FN vec3 evalGltfPbr(RT_IN(GltfPbrParams) p, vec3 wo, vec3 wi)
{
    float pdf;
    return evalGltfPbr(p, wo, wi, pdf);
}

RT_FN float gltfPbrPdf(RT_IN(GltfPbrParams) p, vec3 wo, vec3 wi)
{
    float pdf;
    evalGltfPbr(p, wo, wi, pdf);
    return pdf;
}

/// The specular lobe when uLobe in [0, 1) falls below its probability, else the diffuse; u in [0, 1)^2 places
/// the direction. False (the path ends) for wo.z <= 0 or a reflection below the surface.
RT_FN bool sampleGltfPbr(RT_IN(GltfPbrParams) p, vec3 wo, float uLobe, vec2 u, RT_OUT(BsdfSample) s)
{
    s.wi = vec3(0.0f);
    s.weight = vec3(0.0f);
    s.pdf = 0.0f;
    if (!(wo.z > 0.0f))
        return false;
    vec3 wi;
    if (uLobe < gltfSpecularProbability(p, wo.z))
    {
        const vec3 wm = sampleGgxVisibleNormal(wo, p.alpha, p.alpha, u);
        wi = 2.0f * dot(wo, wm) * wm - wo;
    }
    else
        wi = sampleCosineHemisphere(u);
    if (!(wi.z > 0.0f))
        return false;
    s.wi = normalize(wi);
    const vec3 f = evalGltfPbr(p, wo, s.wi, s.pdf);
    if (!(s.pdf > 0.0f))
        return false;
    s.weight = f / s.pdf;
    return true;
}

RT_SHADER_NAMESPACE_END

#endif
