// Russian roulette on a path's throughput, written once for both engines (Shared/ShaderLang.h): pbrt-v4's
// rule (Pharr, Jakob & Humphreys, Physically Based Rendering, 4th ed., §13.4.3, PathIntegrator::Li), or Blender
// Cycles' gentler square root of it (intern/cycles/kernel/integrator/path_state.h,
// path_state_continuation_probability: "use sqrt() to roughly match typical view transform and do path
// termination a bit later on average").
#ifndef RT_SHARED_RUSSIAN_ROULETTE_H
#define RT_SHARED_RUSSIAN_ROULETTE_H

#include "Shared/HostDevice.h"
#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

/// Paths keep at least this many segments before the roulette may end them: it is played after scattering
/// at the vertex of segment 1 and later ones, so it decides on segment 2 (0-based, the third ray) onwards:
/// pbrt-v4's depth > 1.
RT_CONST(uint, kRouletteFirstVertex, 1u)

/// Probability that a path with throughput `beta` (after scattering at vertex `vertex`, 0 = where the camera
/// ray ended) goes on under `rule`: 1 while the throughput's largest component m is >= 1, before
/// kRouletteFirstVertex or with the roulette off; else m (Throughput) or sqrt(m) (Sqrt). The caller draws u
/// and continues iff u < p, dividing the throughput by p: E[beta'] = p beta / p = beta, so the estimator stays
/// unbiased whatever p is; the rule trades variance (1/p - 1 of what the rest of the path brings) against the
/// segments it saves. p = 0 (a black throughput) ends the path.
RT_FN float rouletteSurvival(vec3 beta, uint vertex, RT_TAG(RussianRoulette) rule)
{
    const float m = max(max(beta.x, max(beta.y, beta.z)), 0.0f);
    if (rule == RT_ENUM(RussianRoulette, Off) || vertex < kRouletteFirstVertex || m >= 1.0f)
        return 1.0f;
    return rule == RT_ENUM(RussianRoulette, Sqrt) ? sqrt(m) : m;
}

/// Whether the roulette drawn after scattering at a vertex takes effect only once the next segment's hit has
/// given its emission (or its miss the background), which counts with the throughput before the 1/p: a path
/// the roulette ends still collects the light its last direction finds, and a survivor is scaled by 1/p from
/// its next scattering on. Unbiased like pbrt-v4's placement: the emission counts with beta either way, and
/// what follows counts beta/p with probability p. For the estimators that find light only by hitting it
/// (BSDF sampling and book 3's mixture): there pbrt-v4's placement ends, before it is traced, exactly the
/// direction the mixture aimed at a light (its throughput is small there), which doubled the mixture's relMSE
/// on cornell-box-lights. With next-event estimation the light is gathered at the vertex, before the
/// roulette, and the extra segment would be traced for the MIS-weighted remainder alone: pbrt-v4's placement.
RT_FN bool rouletteAfterNextHit(RT_TAG(Estimator) estimator)
{
    return estimator == RT_ENUM(Estimator, BsdfOnly) || estimator == RT_ENUM(Estimator, Mixture);
}

RT_SHADER_NAMESPACE_END

#endif
