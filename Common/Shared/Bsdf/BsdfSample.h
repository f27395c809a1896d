// What the microfacet BSDFs (Shared/Bsdf/*.h) hand back from sampling, for both engines (Shared/ShaderLang.h).
#ifndef RT_SHARED_BSDF_SAMPLE_H
#define RT_SHARED_BSDF_SAMPLE_H

#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

/// A sampled direction of a non-delta BSDF, in the frame it was sampled in.
struct BsdfSample
{
    vec3 wi; // unit
    vec3 weight; // f(wo, wi) |cos theta_i| / pdf
    float pdf; // per unit solid angle of wi; what the BSDF's pdf function returns for the same pair
};

RT_SHADER_NAMESPACE_END

#endif
