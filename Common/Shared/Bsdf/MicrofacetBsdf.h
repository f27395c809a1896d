// The microfacet materials at one shading point, behind one interface for the path vertex and NEE, for both
// engines (Shared/ShaderLang.h): world-space directions in, the material's local frame inside. Which BSDF runs
// is the material's type (HostDevice.h MaterialType: Conductor, RoughDielectric, GltfPbr); each is a non-delta
// lobe whose pdf is evaluable for every direction, so NEE and MIS take part at its vertices.
#ifndef RT_SHARED_BSDF_MICROFACET_BSDF_H
#define RT_SHARED_BSDF_MICROFACET_BSDF_H

#include "Shared/Bsdf/BsdfSample.h"
#include "Shared/Bsdf/Conductor.h"
#include "Shared/Bsdf/GltfPbr.h"
#include "Shared/Bsdf/RoughDielectric.h"
#include "Shared/HostDevice.h"
#include "Shared/Onb.h"
#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

/// One shading point's microfacet BSDF, its textures applied (Shared/Shading/Scatter.h microfacetBsdfAt).
struct MicrofacetBsdf
{
    RT_TAG(MaterialType) type;
    // z: the shading normal turned towards the incoming ray (Conductor, GltfPbr), the outward normal
    // (RoughDielectric, whose frame tells inside from outside)
    Onb frame;
    ConductorParams conductor;
    GltfPbrParams gltf;
    float alpha; // RoughDielectric
    float ior; // RoughDielectric: inside / outside
};

/// f(wo, wi) |cos theta_i| for unit world directions wo (towards the incoming ray's origin) and wi, and the
/// solid-angle pdf of sampleMicrofacetBsdf for the same pair.
RT_FN vec3 evalMicrofacetBsdf(RT_IN(MicrofacetBsdf) b, vec3 wo, vec3 wi, RT_OUT(float) pdf)
{
    const vec3 o = onbToLocal(b.frame, wo);
    const vec3 i = onbToLocal(b.frame, wi);
    if (b.type == RT_ENUM(MaterialType, RoughDielectric))
        return vec3(evalRoughDielectric(b.alpha, b.ior, o, i, pdf));
    if (b.type == RT_ENUM(MaterialType, GltfPbr))
        return evalGltfPbr(b.gltf, o, i, pdf);
    return evalConductor(b.conductor, o, i, pdf);
}

/// A direction wi (world space) leaving the shading point, with its weight and pdf; uLobe picks the lobe where
/// a BSDF has two, u places the direction. False when the path ends (a sample below the surface).
RT_FN bool sampleMicrofacetBsdf(RT_IN(MicrofacetBsdf) b, vec3 wo, float uLobe, vec2 u, RT_OUT(BsdfSample) s)
{
    const vec3 o = onbToLocal(b.frame, wo);
    bool ok;
    if (b.type == RT_ENUM(MaterialType, RoughDielectric))
        ok = sampleRoughDielectric(b.alpha, b.ior, o, uLobe, u, s);
    else if (b.type == RT_ENUM(MaterialType, GltfPbr))
        ok = sampleGltfPbr(b.gltf, o, uLobe, u, s);
    else
        ok = sampleConductor(b.conductor, o, u, s);
    s.wi = onbToWorld(b.frame, s.wi);
    return ok;
}

RT_SHADER_NAMESPACE_END

#endif
