// The specular materials' scattering, written once for both engines (Shared/ShaderLang.h): glass (RTIOW §11)
// and the fuzzy mirror (RTIOW §10). Each takes its random numbers as arguments, drawn by the caller before
// the call whatever the branch, so both engines consume one stream alike (the GPU once drew glass's number
// only where refraction was possible and the CPU always: their streams drifted apart after the first TIR).
#ifndef RT_SHARED_SPECULAR_SCATTERING_H
#define RT_SHARED_SPECULAR_SCATTERING_H

#include "Shared/Fresnel.h"
#include "Shared/HostDevice.h"
#include "Shared/ShaderLang.h"
#include "Shared/Warps.h"

RT_SHADER_NAMESPACE_BEGIN

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
