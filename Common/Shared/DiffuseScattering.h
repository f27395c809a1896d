// The two diffuse lobes of the scene description, sampled and evaluated once for both engines
// (Shared/ShaderLang.h): Lambertian reflection (RTTROYL §8: cosine-weighted about the shading normal) and the
// isotropic phase function of constant media (RTTNW §9: the uniform sphere). Both are sampled exactly in
// proportion to f |cos|, so f |cos| = albedo x pdf and a sampled direction's weight is the albedo.
#ifndef RT_SHARED_DIFFUSE_SCATTERING_H
#define RT_SHARED_DIFFUSE_SCATTERING_H

#include "Shared/Onb.h"
#include "Shared/ShaderLang.h"
#include "Shared/Warps.h"

RT_SHADER_NAMESPACE_BEGIN

/// A direction leaving the vertex: the uniform sphere for a phase function, else cosine-weighted about the
/// unit shading normal `ns` (which faces the incoming ray).
RT_FN vec3 sampleDiffuse(bool phase, vec3 ns, vec2 u)
{
    return phase ? sampleUniformSphere(u) : onbToWorld(onbFromNormal(ns), sampleCosineHemisphere(u));
}

/// Solid-angle pdf of sampleDiffuse for the unit direction wi: 1 / (4 pi), or cos / pi and 0 below the surface.
RT_FN float diffusePdf(bool phase, vec3 ns, vec3 wi)
{
    return phase ? uniformSpherePdf() : cosineHemispherePdf(dot(ns, wi));
}

RT_SHADER_NAMESPACE_END

#endif
