// What a rendered reference is: the request it is cached by and the two independent halves it is rendered in
// (Image/Metrics.h's TwoHalfReference). --compare and the windows' error column both follow it, so that a
// reference one of them rendered is found in the cache by the other (ReferenceCache.h).
#pragma once

#include <algorithm>

#include "Render/RenderRequest.h"

namespace rt::compare
{
/// --compare's reference spp without --reference-spp, as a multiple of the largest spp it measures; the windows'
/// reference for a render of N spp is the same, so that `--compare --spp-list N` shares it.
constexpr int kDefaultReferenceFactor = 4;

/// The request a reference of `referenceSpp` spp for `base` is cached by: all its spp, at base's seed + 1000.
inline RenderRequest referenceRequest(const RenderRequest& base, int referenceSpp)
{
    RenderRequest request = base;
    request.settings.spp = referenceSpp;
    request.settings.seed += 1000;
    return request;
}

/// The spp of each half: referenceSpp / 2, rounded up.
inline int referenceHalfSpp(int referenceSpp)
{
    return std::max(1, (referenceSpp + 1) / 2);
}

/// The request of half 0 or 1: referenceHalfSpp at base's seed + 1000, and + 2000 for half 1 (independent
/// streams, also for Sobol's Owen scrambling, which is seeded).
inline RenderRequest referenceHalfRequest(const RenderRequest& base, int referenceSpp, int half)
{
    RenderRequest request = referenceRequest(base, referenceSpp);
    request.settings.spp = referenceHalfSpp(referenceSpp);
    request.settings.seed += 1000 * std::uint32_t(half);
    return request;
}
} // namespace rt::compare
