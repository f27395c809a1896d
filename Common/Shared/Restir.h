// restir-di's reservoirs and the shading point they are resampled for, written once for both engines
// (Shared/ShaderLang.h): weighted reservoir sampling (Bitterli, Wyman, Pharr, Shirley, Lefohn & Jarosz 2020,
// "Spatiotemporal reservoir resampling for real-time ray tracing with dynamic direct lighting", ACM TOG 39(4),
// §3, Alg. 2) and the combination of reservoirs (§4, Alg. 4 and, unbiased, Alg. 6). What reads the scene (the
// target function, candidates, shadow rays) is Shared/Shading/Restir.h; the passes are each engine's own.
//
// Every reservoir's W is an unbiased contribution weight in the area measure of the light point y: E[g(y) W] is
// the integral of g over the points its candidates can reach (Lin, Kettunen, Bitterli, Pantaleoni, Yuksel &
// Wyman 2022, "Generalized resampled importance sampling", ACM TOG 41(4), §4). The samples are points, not
// directions, so that a reservoir means the same at every pixel that reuses it.
#ifndef RT_SHARED_RESTIR_H
#define RT_SHARED_RESTIR_H

#include "Shared/Bsdf/MicrofacetBsdf.h"
#include "Shared/HostDevice.h"
#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

/// Spatial neighbours are drawn in a disk of this radius in pixels (Bitterli et al. 2020, §6).
RT_CONST(float, kRestirSpatialRadius, 30.0f)
/// The temporal input's M is capped at this multiple of the candidates per iteration (Bitterli et al. 2020, §6).
RT_CONST(float, kRestirTemporalCap, 20.0f)
/// Neighbours whose shading normals differ by more than 25 degrees are not reused: cos 25 degrees.
RT_CONST(float, kRestirMinNormalCos, 0.906307787f)

/// The shading point of a RestirSurface (Shared/Shading/Restir.h restirVertexOf): what its target function and
/// shadow rays read. Its BSDF is a diffuse lobe of `albedo` about ns (`phase`: the isotropic phase function) or,
/// when `microfacet`, `bsdf` seen from wo; NEE's (Shading/DirectLighting.h) in every respect.
struct RestirVertex
{
    bool valid; // false: the pixel has no resampled vertex
    bool phase;
    bool microfacet;
    bool transmits; // rough glass: light reaches it from both sides
    vec3 position;
    vec3 normal; // unit geometric normal, outward
    float offsetScale;
    vec3 origin; // where its shadow rays leave: NEE's origin
    vec3 receiver; // the horizon's normal: ns, or 0 in a medium and at glass
    vec3 ns; // unit shading normal, towards the incoming ray
    vec3 albedo;
    vec3 wo; // unit, towards where the incoming ray came from
    MicrofacetBsdf bsdf;
};

RT_FN Reservoir emptyReservoir()
{
    Reservoir r;
    r.point = vec3(0.0f);
    r.light = kNoIndex;
    r.weight = 0.0f;
    r.count = 0.0f;
    r.target = 0.0f;
    r.pad = 0.0f;
    return r;
}

/// Weighted reservoir sampling (Chao 1982; Bitterli et al. 2020, Alg. 2's update): offers the candidate `light`,
/// `point` (with `target`, the target function there) of resampling weight w to `r`, whose weights so far sum to
/// weightSum; it replaces r's sample with probability w / (weightSum + w), decided by u in [0, 1). Returns
/// whether it did. The caller sets r.weight and r.count once every candidate is offered.
RT_FN bool offerCandidate(RT_INOUT(Reservoir) r, RT_INOUT(float) weightSum, uint light, vec3 point, float target,
                          float w, float u)
{
    if (!(w > 0.0f))
        return false;
    weightSum += w;
    if (!(u * weightSum < w))
        return false;
    r.light = light;
    r.point = point;
    r.target = target;
    return true;
}

/// W of a combination whose weights sum to weightSum and whose chosen sample has target `target` at the combining
/// vertex, normalised by `count` (Alg. 6's Z: the M of the inputs whose domain holds the sample; Alg. 4's sum of
/// every input's M in the biased combination; the candidates' number M for plain RIS, Alg. 2, whose weights
/// are then p-hat / p). 0 where nothing was chosen.
RT_FN float contributionWeight(float weightSum, float target, float count)
{
    return target > 0.0f && count > 0.0f ? weightSum / (target * count) : 0.0f;
}

/// A combination of reservoirs in progress at one vertex (Bitterli et al. 2020, Alg. 6; Alg. 4 when biased): the
/// inputs are offered one by one (Shading/Restir.h offerInput), then each says whether its domain holds the chosen
/// point (inputDomainCount), then finishCombination gives the reservoir.
struct RestirCombination
{
    Reservoir out; // the chosen sample, its target at the combining vertex; count: the inputs' M summed
    float weightSum; // sum of M_i p-hat(y_i) W_i
    int chosen; // the input the sample came from, -1: none
};

RT_FN RestirCombination beginCombination()
{
    RestirCombination c;
    c.out = emptyReservoir();
    c.weightSum = 0.0f;
    c.chosen = -1;
    return c;
}

/// The combination's reservoir: W = weightSum / (z p-hat(y)) where z is the M of the inputs whose domain holds y
/// (Alg. 6), or every input's M (Alg. 4, `biased`); 0 when y is not visible from the combining vertex, which keeps
/// the stored reservoir's domain where its vertex sees its points (docs/RESTIR.md).
RT_FN Reservoir finishCombination(RT_IN(RestirCombination) c, float z, bool visibleHere, bool biased)
{
    Reservoir r = c.out;
    r.weight = c.chosen >= 0 && visibleHere ? contributionWeight(c.weightSum, r.target, biased ? r.count : z) : 0.0f;
    return r;
}

RT_SHADER_NAMESPACE_END

#endif
