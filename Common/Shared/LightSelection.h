// Choosing which light NEE samples, written once for both engines (Shared/ShaderLang.h). The probability
// mass of every light is available (lightSelectionPmf): the MIS weight of an emitter found by a BSDF ray
// needs it.
#ifndef RT_SHARED_LIGHT_SELECTION_H
#define RT_SHARED_LIGHT_SELECTION_H

#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

/// One of `count` > 0 lights, uniformly, from u in [0, 1).
RT_FN uint selectLightUniform(float u, uint count)
{
    return min(uint(u * float(count)), count - 1u);
}

/// Probability with which selectLightUniform picks any one light.
RT_FN float uniformLightPmf(uint count)
{
    return 1.0f / float(count);
}

RT_SHADER_NAMESPACE_END

#endif
