// Fresnel reflectance, written once for both engines (Shared/ShaderLang.h): dielectric boundaries (exact and
// Schlick's approximation) and conductors (exact from a complex index of refraction, or Schlick's from the
// reflectance at normal incidence F0). Cosines are of the incident direction to the (micro)surface's normal.
#ifndef RT_SHARED_FRESNEL_H
#define RT_SHARED_FRESNEL_H

#include "Shared/HostDevice.h"
#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

/// Schlick's approximation of the Fresnel reflectance (Schlick, "An Inexpensive BRDF Model for
/// Physically-based Rendering", Computer Graphics Forum 13(3), 1994), RTIOW §11.4. `etaRatio` = eta_incident /
/// eta_transmitted; `cosine` of the incident direction to the normal.
RT_FN float schlickReflectance(float cosine, float etaRatio)
{
    float r0 = (1.0f - etaRatio) / (1.0f + etaRatio);
    r0 *= r0;
    const float m = 1.0f - cosine;
    return r0 + (1.0f - r0) * (m * m) * (m * m) * m;
}

/// The Fresnel reflectance of unpolarised light at a smooth dielectric boundary: the mean of the squared
/// amplitude ratios r_parallel and r_perpendicular (Born & Wolf, Principles of Optics, §1.5.2; pbrt-v4
/// §9.3.1 FrDielectric). `cosine` of the incident direction to the normal, in [0, 1]; `etaRatio` =
/// eta_incident / eta_transmitted. 1 under total internal reflection.
RT_FN float fresnelDielectric(float cosine, float etaRatio)
{
    const float sin2T = etaRatio * etaRatio * max(0.0f, 1.0f - cosine * cosine);
    if (sin2T >= 1.0f)
        return 1.0f;
    const float cosT = sqrt(1.0f - sin2T);
    const float rParallel = (cosine - etaRatio * cosT) / (cosine + etaRatio * cosT);
    const float rPerpendicular = (etaRatio * cosine - cosT) / (etaRatio * cosine + cosT);
    return 0.5f * (rParallel * rParallel + rPerpendicular * rPerpendicular);
}

/// The reflectance `model` (FresnelModel) gives.
RT_FN float dielectricReflectance(float cosine, float etaRatio, RT_TAG(FresnelModel) model)
{
    return model == RT_ENUM(FresnelModel, Exact) ? fresnelDielectric(cosine, etaRatio) : schlickReflectance(cosine, etaRatio);
}

/// Schlick's approximation for a colour: f0 + (1 - f0)(1 - cosine)^5 per channel (the glTF 2.0 metal's
/// conductor_fresnel, and a conductor given by its F0 colour).
RT_FN vec3 schlickFresnel(vec3 f0, float cosine)
{
    const float m = clamp(1.0f - cosine, 0.0f, 1.0f);
    const float m5 = (m * m) * (m * m) * m;
    return f0 + (vec3(1.0f) - f0) * m5;
}

/// The exact reflectance of unpolarised light at a conductor with complex index of refraction eta + i k
/// (relative to the outside medium), per channel: the mean of |r_s|^2 and |r_p|^2 in the closed form of real
/// arithmetic (Born & Wolf §14.2; the form of Mitsuba 3's fresnel_conductor). cosine in [0, 1].
RT_FN float fresnelConductor(float cosine, float eta, float k)
{
    const float c2 = cosine * cosine;
    const float s2 = max(0.0f, 1.0f - c2);
    const float eta2 = eta * eta;
    const float k2 = k * k;
    const float t0 = eta2 - k2 - s2;
    const float a2b2 = sqrt(max(0.0f, t0 * t0 + 4.0f * eta2 * k2));
    const float a = sqrt(max(0.0f, 0.5f * (a2b2 + t0)));
    const float t1 = a2b2 + c2;
    const float t2 = 2.0f * cosine * a;
    const float rs = (t1 - t2) / (t1 + t2);
    const float t3 = c2 * a2b2 + s2 * s2;
    const float t4 = t2 * s2;
    const float rp = rs * (t3 - t4) / (t3 + t4);
    return 0.5f * (rs + rp);
}

/// fresnelConductor for each RGB channel.
RT_FN vec3 fresnelConductorRgb(float cosine, vec3 eta, vec3 k)
{
    return vec3(fresnelConductor(cosine, eta.x, k.x), fresnelConductor(cosine, eta.y, k.y),
                fresnelConductor(cosine, eta.z, k.z));
}

RT_SHADER_NAMESPACE_END

#endif
