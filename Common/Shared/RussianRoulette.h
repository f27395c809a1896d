// Russian roulette on a path's throughput, written once for both engines (Shared/ShaderLang.h): pbrt-v4's
// rule (Pharr, Jakob & Humphreys, Physically Based Rendering, 4th ed., §13.4.3, PathIntegrator::Li).
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
/// ray ended) goes on: 1 while the throughput's largest component is >= 1 or before kRouletteFirstVertex,
/// else that component. The caller draws u and continues iff u < p, dividing the throughput by p:
/// E[beta'] = p beta / p = beta, so the estimator stays unbiased. p = 0 (a black throughput) ends the path.
RT_FN float rouletteSurvival(vec3 beta, uint vertex)
{
    const float m = max(beta.x, max(beta.y, beta.z));
    return vertex >= kRouletteFirstVertex && m < 1.0f ? max(m, 0.0f) : 1.0f;
}

RT_SHADER_NAMESPACE_END

#endif
