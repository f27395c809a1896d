// The rough conductor: a GGX microfacet BRDF with Fresnel reflection and no transmission (Cook & Torrance 1982;
// Walter et al. 2007 eq. 20; pbrt-v4 §9.6 ConductorBxDF), for both engines (Shared/ShaderLang.h). Local shading
// frame: z the normal on the side of wo; directions unit. f = D(wm) G2(wo, wi) F(wo.wm) / (4 cos_o cos_i) with
// wm the half vector; sampled by the visible normals of wo, so f cos / pdf = F G2 / G1(wo).
#ifndef RT_SHARED_BSDF_CONDUCTOR_H
#define RT_SHARED_BSDF_CONDUCTOR_H

#include "Shared/Bsdf/BsdfSample.h"
#include "Shared/Fresnel.h"
#include "Shared/Microfacet.h"
#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

/// A conductor's roughness and Fresnel term: exact from the complex index eta + i k (per RGB channel), or, when
/// `schlick`, Schlick's from the colour f0 at normal incidence.
struct ConductorParams
{
    float alphaX; // GGX roughness along the frame's x, >= kMinMicrofacetAlpha
    float alphaY;
    bool schlick;
    vec3 f0; // when schlick
    vec3 eta; // when !schlick
    vec3 k;
};

RT_FN vec3 conductorFresnel(RT_IN(ConductorParams) c, float cosine)
{
    return c.schlick ? schlickFresnel(c.f0, cosine) : fresnelConductorRgb(cosine, c.eta, c.k);
}

/// f(wo, wi) |cos theta_i| (0 unless both directions lie above the surface) and, in `pdf`, the density of
/// sampleConductor for wi per unit solid angle: D_wo(wm) / (4 wo.wm).
RT_FN vec3 evalConductor(RT_IN(ConductorParams) c, vec3 wo, vec3 wi, RT_OUT(float) pdf)
{
    vec3 wm;
    pdf = 0.0f;
    if (!ggxReflectionHalfVector(wo, wi, wm))
        return vec3(0.0f);
    pdf = ggxReflectionPdf(wo, wm, c.alphaX, c.alphaY);
    return conductorFresnel(c, max(0.0f, dot(wo, wm))) *
           (ggxD(wm, c.alphaX, c.alphaY) * ggxG2(wo, wi, c.alphaX, c.alphaY) / (4.0f * wo.z));
}

RT_FN vec3 evalConductor(RT_IN(ConductorParams) c, vec3 wo, vec3 wi)
{
    float pdf;
    return evalConductor(c, wo, wi, pdf);
}

RT_FN float conductorPdf(RT_IN(ConductorParams) c, vec3 wo, vec3 wi)
{
    float pdf;
    evalConductor(c, wo, wi, pdf);
    return pdf;
}

/// wi: wo reflected about a visible normal (u in [0, 1)^2). False (the path ends) for wo.z <= 0 or a reflection
/// below the surface, which the pdf leaves out.
RT_FN bool sampleConductor(RT_IN(ConductorParams) c, vec3 wo, vec2 u, RT_OUT(BsdfSample) s)
{
    s.wi = vec3(0.0f);
    s.weight = vec3(0.0f);
    s.pdf = 0.0f;
    if (!(wo.z > 0.0f))
        return false;
    const vec3 wm = sampleGgxVisibleNormal(wo, c.alphaX, c.alphaY, u);
    const float cosOm = dot(wo, wm);
    const vec3 wi = 2.0f * cosOm * wm - wo;
    if (!(wi.z > 0.0f) || !(cosOm > 0.0f))
        return false;
    s.wi = normalize(wi);
    const vec3 f = evalConductor(c, wo, s.wi, s.pdf);
    if (!(s.pdf > 0.0f))
        return false;
    s.weight = f / s.pdf;
    return true;
}

RT_SHADER_NAMESPACE_END

#endif
