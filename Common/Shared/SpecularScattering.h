// The specular materials' scattering, written once for both engines (Shared/ShaderLang.h): glass (RTIOW §11)
// and the fuzzy mirror (RTIOW §10). Each takes its random numbers as arguments, drawn by the caller before
// the call whatever the branch, so both engines consume one stream alike (the GPU once drew glass's number
// only where refraction was possible and the CPU always: their streams drifted apart after the first TIR).
#ifndef RT_SHARED_SPECULAR_SCATTERING_H
#define RT_SHARED_SPECULAR_SCATTERING_H

#include "Shared/HostDevice.h"
#include "Shared/ShaderLang.h"
#include "Shared/Warps.h"

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

/// Glass (RTIOW §11): the direction after the incident direction `d` meets the surface with unit normal `ns`
/// (facing the incoming ray), `etaRatio` = eta_incident / eta_transmitted: the mirror direction on total
/// internal reflection or when u in [0, 1) falls below the reflectance (FresnelModel `model`), else Snell's
/// refraction. Weight 1.
RT_FN vec3 sampleDielectric(vec3 d, vec3 ns, float etaRatio, RT_TAG(FresnelModel) model, float u)
{
    const vec3 ud = normalize(d);
    const float cosTheta = min(dot(-ud, ns), 1.0f);
    const float sin2Theta = 1.0f - cosTheta * cosTheta;
    if (etaRatio * etaRatio * sin2Theta > 1.0f || dielectricReflectance(cosTheta, etaRatio, model) > u)
        return reflect(ud, ns);
    const vec3 perpendicular = etaRatio * (ud + cosTheta * ns);
    const vec3 parallel = -sqrt(abs(1.0f - lengthSquared(perpendicular))) * ns;
    return perpendicular + parallel;
}

/// Fuzzy mirror (RTIOW §10.6): the mirror direction of `d` about `ns` plus `fuzz` times a uniform point of the
/// unit sphere from u, so the fuzz follows the reflected direction, not a world axis. Returns false when the
/// result points into the surface (the ray is absorbed).
RT_FN bool sampleFuzzyMirror(vec3 d, vec3 ns, float fuzz, vec2 u, RT_OUT(vec3) wi)
{
    wi = normalize(reflect(d, ns)) + fuzz * sampleUniformSphere(u);
    return dot(wi, ns) > 0.0f;
}

RT_SHADER_NAMESPACE_END

#endif
