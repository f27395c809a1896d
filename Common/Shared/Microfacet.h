// The Trowbridge-Reitz (GGX) microfacet distribution with Smith masking-shadowing, written once for both engines
// (Shared/ShaderLang.h). Every direction here is in the local shading frame: z the macro-surface normal, x and
// y the tangents along which the roughnesses alphaX and alphaY apply (isotropic when equal). Directions are
// unit vectors.
//  - D: Trowbridge & Reitz 1975; Walter et al., "Microfacet Models for Refraction through Rough Surfaces",
//    EGSR 2007, eq. 33, in its anisotropic form (Heitz, "Understanding the Masking-Shadowing Function in
//    Microfacet-Based BRDFs", JCGT 3(2), 2014, eq. 85).
//  - Lambda, G1 and the height-correlated G2: Heitz 2014, eqs. 86 and 99.
//  - Visible normals: sampled exactly (Dupuy & Benyoub, "Sampling Visible GGX Normals with Spherical Caps",
//    HPG 2023: the stretched view's visible normals are a spherical cap plus the view direction), with the
//    density D_wo(wm) = G1(wo) max(0, wo.wm) D(wm) / wo.z (Heitz, "Sampling the GGX Distribution of Visible
//    Normals", JCGT 7(4), 2018, eq. 3), evaluable for every wm.
// Tested by chi-square and against float64 integrals in tests/Common/MicrofacetTest.cpp.
#ifndef RT_SHARED_MICROFACET_H
#define RT_SHARED_MICROFACET_H

#include "Shared/ShaderLang.h"
#include "Shared/Warps.h"

RT_SHADER_NAMESPACE_BEGIN

/// The smallest roughness the materials use: below it D's peak (1 / (pi alpha^2)) and its square leave float's
/// range in the BSDF's products. Scene roughness below it is raised to it (a mirror is `metal` with fuzz 0).
RT_CONST(float, kMinMicrofacetAlpha, 1e-4f)

/// GGX's distribution of normals, per unit solid angle of wm (projected onto z it integrates to 1).
RT_FN float ggxD(vec3 wm, float alphaX, float alphaY)
{
    if (!(wm.z > 0.0f))
        return 0.0f;
    const float sx = wm.x / alphaX;
    const float sy = wm.y / alphaY;
    const float t = sx * sx + sy * sy + wm.z * wm.z;
    return 1.0f / (kPi * alphaX * alphaY * t * t);
}

/// Smith's Lambda for GGX: the masked fraction of microfacets seen from w, as (-1 + sqrt(1 + alpha^2 tan^2)) / 2
/// with alpha^2 = alphaX^2 cos^2 phi + alphaY^2 sin^2 phi. 0 at normal incidence; infinite at grazing (w.z = 0).
RT_FN float ggxLambda(vec3 w, float alphaX, float alphaY)
{
    const float z2 = w.z * w.z;
    const float a2Tan2 = (alphaX * alphaX * w.x * w.x + alphaY * alphaY * w.y * w.y) / z2;
    return 0.5f * (sqrt(1.0f + a2Tan2) - 1.0f);
}

/// Smith's masking G1(w) = 1 / (1 + Lambda(w)), in [0, 1]; 0 for w in the plane.
RT_FN float ggxG1(vec3 w, float alphaX, float alphaY)
{
    return w.z == 0.0f ? 0.0f : 1.0f / (1.0f + ggxLambda(w, alphaX, alphaY));
}

/// Height-correlated masking-shadowing of the pair (wo, wi): 1 / (1 + Lambda(wo) + Lambda(wi)), in [0, 1].
RT_FN float ggxG2(vec3 wo, vec3 wi, float alphaX, float alphaY)
{
    if (wo.z == 0.0f || wi.z == 0.0f)
        return 0.0f;
    return 1.0f / (1.0f + ggxLambda(wo, alphaX, alphaY) + ggxLambda(wi, alphaX, alphaY));
}

/// A normal wm of the microfacets visible from wo (wo.z > 0), distributed by D_wo (ggxVisibleNormalPdf): the
/// view stretched to the unit-roughness configuration, a point of the spherical cap z > -wo.z added to it
/// (Dupuy & Benyoub 2023, listing 3), the sum unstretched. u in [0, 1)^2.
RT_FN vec3 sampleGgxVisibleNormal(vec3 wo, float alphaX, float alphaY, vec2 u)
{
    RT_DCHECK(wo.z > 0.0f);
    const vec3 woStd = normalize(vec3(alphaX * wo.x, alphaY * wo.y, wo.z));
    float sinPhi;
    float cosPhi;
    sinCos2Pi(u.x, sinPhi, cosPhi);
    const float z = (1.0f - u.y) * (1.0f + woStd.z) - woStd.z;
    const float sinTheta = sqrt(clamp(1.0f - z * z, 0.0f, 1.0f));
    const vec3 wmStd = vec3(sinTheta * cosPhi, sinTheta * sinPhi, z) + woStd;
    // A half vector below the plane only by rounding (wo grazing) is lifted onto it.
    return normalize(vec3(alphaX * wmStd.x, alphaY * wmStd.y, max(wmStd.z, 0.0f)));
}

/// Density of sampleGgxVisibleNormal per unit solid angle of wm: G1(wo) max(0, wo.wm) D(wm) / wo.z.
RT_FN float ggxVisibleNormalPdf(vec3 wo, vec3 wm, float alphaX, float alphaY)
{
    if (!(wo.z > 0.0f))
        return 0.0f;
    return ggxG1(wo, alphaX, alphaY) * max(0.0f, dot(wo, wm)) * ggxD(wm, alphaX, alphaY) / wo.z;
}

/// The half vector wm of a reflection from wo into wi: false unless both lie above the surface and are not
/// opposite (wm (0, 0, 1) then).
RT_FN bool ggxReflectionHalfVector(vec3 wo, vec3 wi, RT_OUT(vec3) wm)
{
    wm = vec3(0.0f, 0.0f, 1.0f);
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f))
        return false;
    const vec3 h = wo + wi;
    if (lengthSquared(h) == 0.0f)
        return false;
    wm = normalize(h);
    return true;
}

/// Density per unit solid angle of wi of wo reflected about a visible normal (ggxReflectionHalfVector's wm):
/// D_wo(wm) / (4 wo.wm), the Jacobian of the reflection (Walter et al. 2007 eq. 14).
RT_FN float ggxReflectionPdf(vec3 wo, vec3 wm, float alphaX, float alphaY)
{
    const float cosOm = dot(wo, wm);
    return cosOm > 0.0f ? ggxVisibleNormalPdf(wo, wm, alphaX, alphaY) / (4.0f * cosOm) : 0.0f;
}

RT_SHADER_NAMESPACE_END

#endif
