// Choosing which light NEE samples, written once for both engines (Shared/ShaderLang.h). The probability
// mass of every light is available (lightSelectionPmf): the MIS weight of an emitter found by a BSDF ray
// needs it. The alias table and the light BVH are built on the host (Sampling/LightPower.h,
// Sampling/LightBvh.h); GLSL reads them as the globals `lightAlias`, `lightBvh` and `lightBvhLeaves`
// (Bindings.glsl), C++ passes them (RT_ARRAY).
#ifndef RT_SHARED_LIGHT_SELECTION_H
#define RT_SHARED_LIGHT_SELECTION_H

#include "Shared/HostDevice.h"
#include "Shared/LightBvh.h"
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

/// One of `count` > 0 lights with the probabilities of the alias table (Vose 1991, "A linear algorithm for
/// generating random numbers with a given distribution", IEEE TSE 17(9)): u picks a slot and, by what
/// remains of it, the slot's light or its alias. One number, no search.
RT_FN uint selectLightAlias(RT_ARRAY(AliasEntry, lightAlias) float u, uint count)
{
    const float scaled = u * float(count);
    const uint slot = min(uint(scaled), count - 1u);
    return scaled - float(slot) < lightAlias[slot].threshold ? slot : lightAlias[slot].alias;
}

/// The light NEE samples at p (receiver normal n, 0 in a medium) by `selection`, and its probability in
/// `pmf`; kNoIndex (pmf 0) when the BVH finds that no emitter can contribute at p. `twoSided`: emitters emit
/// from both faces (the BVH's bound needs it).
RT_FN uint selectLight(RT_ARRAY(AliasEntry, lightAlias) RT_ARRAY(LightBvhNode, lightBvh)
                           RT_TAG(LightSelection) selection,
                       float u, uint count, vec3 p, vec3 n, bool twoSided, RT_OUT(float) pmf)
{
    if (selection == RT_ENUM(LightSelection, Bvh))
        return selectLightBvh(RT_PASS(lightBvh) p, n, twoSided, u, pmf);
    if (selection == RT_ENUM(LightSelection, Power))
    {
        const uint light = selectLightAlias(RT_PASS(lightAlias) u, count);
        pmf = lightAlias[light].pmf;
        return light;
    }
    pmf = uniformLightPmf(count);
    return selectLightUniform(u, count);
}

/// Probability that selectLight(.., p, n, ..) picks `light` (for the MIS weight of an emitter a BSDF ray hits).
RT_FN float lightSelectionPmf(RT_ARRAY(AliasEntry, lightAlias) RT_ARRAY(LightBvhNode, lightBvh)
                                  RT_ARRAY(uint, lightBvhLeaves) RT_TAG(LightSelection) selection,
                              uint light, uint count, vec3 p, vec3 n, bool twoSided)
{
    if (selection == RT_ENUM(LightSelection, Bvh))
        return lightBvhPmf(RT_PASS(lightBvh) RT_PASS(lightBvhLeaves) light, p, n, twoSided);
    return selection == RT_ENUM(LightSelection, Power) ? lightAlias[light].pmf : uniformLightPmf(count);
}

RT_SHADER_NAMESPACE_END

#endif
