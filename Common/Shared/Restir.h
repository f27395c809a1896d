// restir-di's reservoirs and the shading point they are resampled for, written once for both engines
// (Shared/ShaderLang.h): weighted reservoir sampling (Bitterli, Wyman, Pharr, Shirley, Lefohn & Jarosz 2020,
// "Spatiotemporal reservoir resampling for real-time ray tracing with dynamic direct lighting", ACM TOG 39(4),
// §3, Alg. 2) and their combination (unbiased: GRIS with pairwise MIS; biased: Alg. 4). What reads the scene (the
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
#include "Shared/Warps.h"

RT_SHADER_NAMESPACE_BEGIN

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

/// The light-selection number of candidate k of `count` in a pixel's initial resampling: stratified, (k + xi) / count
/// with one uniform xi for all of them, so that the candidates spread over the selection's distribution. Unbiased:
/// candidate k's light has the pmf p_k of its stratum [k / M, (k + 1) / M), the strata's pmfs average to the
/// selection's, (1 / M) sum_k p_k = p, so the weights p-hat / (M p) are GRIS's balance heuristic over the M proposals
/// (Lin et al. 2022, §4-5) and W stays an unbiased contribution weight; M stays the candidates' count.
RT_FN float stratifiedCandidateNumber(uint k, uint count, float xi)
{
    return min((float(k) + xi) / float(count), kOneMinusEpsilon);
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
/// vertex, normalised by `count` (1 after MIS weights; Alg. 4's sum of
/// every input's M in the biased combination; the candidates' number M for plain RIS, Alg. 2, whose weights
/// are then p-hat / p). 0 where nothing was chosen.
RT_FN float contributionWeight(float weightSum, float target, float count)
{
    return target > 0.0f && count > 0.0f ? weightSum / (target * count) : 0.0f;
}

/// A combination of reservoirs in progress at one vertex q (GRIS, Lin et al. 2022, §4-5: each input offered with
/// resampling weight m_i(y_i) p-hat_q(y_i) W_i, then W = the weights' sum / p-hat_q(y)): offerInput for each input
/// in turn, then finishCombination.
struct RestirCombination
{
    Reservoir result; // the chosen sample, its target at q; count: the inputs' M summed
    float weightSum;
    int chosen; // the input the sample came from, -1: none
};

RT_FN RestirCombination beginCombination()
{
    RestirCombination c;
    c.result = emptyReservoir();
    c.weightSum = 0.0f;
    c.chosen = -1;
    return c;
}

/// Offers input `index`, reservoir r, whose point has target `targetHere` at q (0 where q cannot use it), with MIS
/// weight `mis` (or its M, in the biased combination); u in [0, 1) decides whether it replaces the sample so far.
RT_FN void offerInput(RT_INOUT(RestirCombination) c, RT_IN(Reservoir) r, float targetHere, float mis, int index, float u)
{
    c.result.count += r.count;
    if (offerCandidate(c.result, c.weightSum, r.light, r.point, targetHere, mis * targetHere * r.weight, u))
        c.chosen = index;
}

/// The combination's reservoir: W = weightSum / (p-hat_q(y) normalisation), normalisation 1 after MIS weights,
/// the inputs' summed M after the biased combination's (Bitterli et al. 2020, Alg. 4).
RT_FN Reservoir finishCombination(RT_IN(RestirCombination) c, float normalisation)
{
    Reservoir r = c.result;
    r.weight = c.chosen >= 0 ? contributionWeight(c.weightSum, r.target, normalisation) : 0.0f;
    return r;
}

// Pairwise MIS (Bitterli 2022, "Correlations and reuse for fast and accurate physically based light transport", PhD
// thesis, Dartmouth College, §9.1.3; Lin et al. 2022, §7.4): the canonical input c (the vertex's own) and k
// neighbours, each pair (c, i) weighted by the balance heuristic with confidences M_i and M_c / k, the k pairs
// averaged. The weights of an x sum to 1 over the inputs whose domain holds x (each pair's two sum to 1), so the
// combination is unbiased; each needs the other side's target of the point, with that side's visibility. Targets
// here are p-hat times visibility at the named vertex.

/// m_i(y_i) of neighbour i's own point: counts M_i, M_c; neighbourTarget = p-hat_i(y_i), canonicalTarget =
/// p-hat_c(y_i) V_c(y_i).
RT_FN float pairwiseNeighbourMis(float k, float neighbourCount, float neighbourTarget, float canonicalCount,
                                 float canonicalTarget)
{
    const float a = neighbourCount * neighbourTarget;
    const float b = canonicalCount / k * canonicalTarget;
    return a + b > 0.0f ? a / (k * (a + b)) : 0.0f;
}

/// Pair i's term of the canonical input's m_c(y_c), summed over the k neighbours: canonicalTarget = p-hat_c(y_c),
/// neighbourTarget = p-hat_i(y_c) V_i(y_c).
RT_FN float pairwiseCanonicalTerm(float k, float canonicalCount, float canonicalTarget, float neighbourCount,
                                  float neighbourTarget)
{
    const float a = canonicalCount / k * canonicalTarget;
    const float b = neighbourCount * neighbourTarget;
    return a + b > 0.0f ? a / (k * (a + b)) : 0.0f;
}

RT_SHADER_NAMESPACE_END

#endif
