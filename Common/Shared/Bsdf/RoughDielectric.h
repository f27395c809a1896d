// The rough dielectric: reflection and refraction through GGX microfacets (Walter, Marschner, Li & Torrance,
// "Microfacet Models for Refraction through Rough Surfaces", EGSR 2007, eqs. 20-21 with the generalized half
// vector of eq. 16; sampled by visible normals as pbrt-v4 §9.7 does), for both engines (Shared/ShaderLang.h).
// Local frame: z the surface's outward normal, so wo.z < 0 means wo lies inside; `ior` = eta_inside /
// eta_outside. Fresnel exact (Shared/Fresnel.h). Transport of radiance: a refracted f carries the factor
// 1 / eta'^2 (eta' = eta_transmitted / eta_incident; Veach 1997 §5.2), so f(wo, wi) / eta(wo side)^2 is symmetric
// (generalized reciprocity) and the integral of (f_r + eta'^2 f_t) |cos| is at most 1 (energy).
#ifndef RT_SHARED_BSDF_ROUGH_DIELECTRIC_H
#define RT_SHARED_BSDF_ROUGH_DIELECTRIC_H

#include "Shared/Bsdf/BsdfSample.h"
#include "Shared/Fresnel.h"
#include "Shared/Microfacet.h"
#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

/// The microfacet normal (z > 0) that scatters wo into wi, with eta' (1 for a reflection) and whether the
/// pair is a reflection; false when no microfacet does (a direction in the plane, or a normal that faces
/// away from either direction: Walter 2007 §5.3's back-facing microfacets).
RT_FN bool roughDielectricHalfVector(vec3 wo, vec3 wi, float ior, RT_OUT(vec3) wm, RT_OUT(float) etaPrime,
                                     RT_OUT(bool) reflection)
{
    reflection = wo.z * wi.z > 0.0f;
    etaPrime = reflection ? 1.0f : (wo.z > 0.0f ? ior : 1.0f / ior);
    wm = vec3(0.0f, 0.0f, 1.0f);
    if (wo.z == 0.0f || wi.z == 0.0f)
        return false;
    const vec3 h = wi * etaPrime + wo;
    if (lengthSquared(h) == 0.0f)
        return false;
    wm = normalize(h);
    if (wm.z < 0.0f)
        wm = -wm;
    return dot(wm, wi) * wi.z > 0.0f && dot(wm, wo) * wo.z > 0.0f;
}

/// Probability of reflection at the microfacet wm seen from wo: the exact Fresnel reflectance.
RT_FN float roughDielectricReflectance(vec3 wo, vec3 wm, float ior)
{
    const float c = dot(wo, wm);
    return fresnelDielectric(abs(c), c > 0.0f ? 1.0f / ior : ior);
}

/// f(wo, wi) |cos theta_i| for isotropic roughness alpha (>= kMinMicrofacetAlpha) and, in `pdf`, the density
/// of sampleRoughDielectric for wi per unit solid angle.
RT_FN float evalRoughDielectric(float alpha, float ior, vec3 wo, vec3 wi, RT_OUT(float) pdf)
{
    vec3 wm;
    float etaPrime;
    bool reflection;
    pdf = 0.0f;
    if (!roughDielectricHalfVector(wo, wi, ior, wm, etaPrime, reflection))
        return 0.0f;
    const float r = roughDielectricReflectance(wo, wm, ior);
    const float dg = ggxD(wm, alpha, alpha) * ggxG2(wo, wi, alpha, alpha);
    // wm (z > 0) among the normals visible from wo's side, wo turned to z > 0.
    const float normalPdf = ggxVisibleNormalPdf(wo.z > 0.0f ? wo : -wo, wm, alpha, alpha);
    if (reflection)
    {
        pdf = normalPdf * r / (4.0f * abs(dot(wo, wm)));
        return dg * r / (4.0f * abs(wo.z));
    }
    const float s = dot(wi, wm) + dot(wo, wm) / etaPrime;
    pdf = normalPdf * (1.0f - r) * abs(dot(wi, wm)) / (s * s);
    return dg * (1.0f - r) * abs(dot(wi, wm) * dot(wo, wm) / (wo.z * s * s)) / (etaPrime * etaPrime);
}

RT_FN float evalRoughDielectric(float alpha, float ior, vec3 wo, vec3 wi)
{
    float pdf;
    return evalRoughDielectric(alpha, ior, wo, wi, pdf);
}

RT_FN float roughDielectricPdf(float alpha, float ior, vec3 wo, vec3 wi)
{
    float pdf;
    evalRoughDielectric(alpha, ior, wo, wi, pdf);
    return pdf;
}

/// A visible normal of wo (on either side, u in [0, 1)^2), then reflection with the Fresnel reflectance's
/// probability (uLobe in [0, 1)), else refraction through it. False (the path ends) when the direction falls
/// on the wrong side of the surface, which the pdf leaves out.
RT_FN bool sampleRoughDielectric(float alpha, float ior, vec3 wo, float uLobe, vec2 u, RT_OUT(BsdfSample) s)
{
    s.wi = vec3(0.0f);
    s.weight = vec3(0.0f);
    s.pdf = 0.0f;
    if (wo.z == 0.0f)
        return false;
    const float side = wo.z > 0.0f ? 1.0f : -1.0f;
    const vec3 m = sampleGgxVisibleNormal(side * wo, alpha, alpha, u); // seen from the side of wo
    const vec3 n = side * m; // the microfacet's normal, facing wo
    const float cosI = dot(wo, n);
    if (!(cosI > 0.0f))
        return false;
    const float etaRatio = wo.z > 0.0f ? 1.0f / ior : ior; // eta_incident / eta_transmitted
    const float r = fresnelDielectric(cosI, etaRatio);
    vec3 wi;
    if (uLobe < r)
        wi = 2.0f * cosI * n - wo;
    else
    {
        const float sin2T = etaRatio * etaRatio * max(0.0f, 1.0f - cosI * cosI);
        const float cosT = sqrt(max(0.0f, 1.0f - sin2T)); // sin2T < 1 here: r = 1 under total reflection
        wi = -etaRatio * wo + (etaRatio * cosI - cosT) * n;
    }
    // A reflection below the surface or a refraction back to wo's side is no sample of its lobe: the pdf would
    // read it as the other event, through another microfacet, and count it there.
    if ((uLobe < r) != (wi.z * wo.z > 0.0f))
        return false;
    s.wi = normalize(wi);
    const float f = evalRoughDielectric(alpha, ior, wo, s.wi, s.pdf);
    if (!(s.pdf > 0.0f))
        return false;
    s.weight = vec3(f / s.pdf);
    return true;
}

RT_SHADER_NAMESPACE_END

#endif
