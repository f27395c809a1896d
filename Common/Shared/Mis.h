// Multiple importance sampling weights, written once for both engines (Shared/ShaderLang.h).
// Veach, "Robust Monte Carlo Methods for Light Transport Simulation", PhD thesis 1997, §9.2.
#ifndef RT_SHARED_MIS_H
#define RT_SHARED_MIS_H

#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

/// Power heuristic with beta = 2 and one sample from each strategy (Veach 1997, eq. 9.13):
/// w_f = p_f^2 / (p_f^2 + p_g^2), where p_f is the density of the strategy that produced the sample and p_g
/// the other strategy's density of the same sample, both in one measure (here: solid angle). Written as
/// 1 / (1 + (p_g / p_f)^2) so that densities up to the float range (a tiny light's 1e20 per sr) do not
/// overflow when squared. 0 when p_f = 0; 1 when p_g = 0 or p_f is infinite.
RT_FN float powerHeuristic(float pdfF, float pdfG)
{
    if (!(pdfF > 0.0f))
        return 0.0f;
    const float r = pdfG / pdfF;
    return r < 1e18f ? 1.0f / (1.0f + r * r) : 0.0f;
}

RT_SHADER_NAMESPACE_END

#endif
