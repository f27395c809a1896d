// The specialised instances of the path loop for one estimator (Integrator/PathVariants.h), compiled in a
// translation unit per estimator (PathVariants{Bsdf,Mixture,Nee,NeeMis}.cpp): each instance inlines the whole
// shared vertex, and the sixteen in one file were the longest compile of `./build.sh run` (3 CPU-minutes, alone on
// one of the two cores at the end of the build).
#pragma once

#include "Integrator/PathVariants.h"

namespace rt::cpu
{
/// The instance of estimator E with or without media and textures (which carry the microfacet materials too).
template <Estimator E>
PathVariant estimatorVariant(bool media, bool textures, bool rayLanes);

template <>
PathVariant estimatorVariant<Estimator::BsdfOnly>(bool media, bool textures, bool rayLanes);
template <>
PathVariant estimatorVariant<Estimator::Mixture>(bool media, bool textures, bool rayLanes);
template <>
PathVariant estimatorVariant<Estimator::Nee>(bool media, bool textures, bool rayLanes);
template <>
PathVariant estimatorVariant<Estimator::NeeMis>(bool media, bool textures, bool rayLanes);

namespace detail
{
template <Estimator E, bool Media, bool Textures>
PathVariant instance(bool rayLanes)
{
    constexpr PathCode code{.general = false, .estimator = E, .media = Media, .textures = Textures};
    // kLanes paths at a time where their rays are tested together (book 3's scene 1.15x; over a BVH, with masked
    // packet traversal, 1.07-1.50x: docs/notebook/PERFORMANCE.md §30). Paths merely interleaved over a BVH, each
    // ray traversing it alone, were 0.92x (rtrol-cornell-mirror) to 1.04x (rtow-final) one path at a time: not
    // kept (§1). The lanes test quads and spheres only (CpuScene::tracesRayLanes), so media scenes never test rays
    // in lanes.
    if constexpr (!Media)
        if (rayLanes)
            return {&traceJobs<code>, code, &tracePaths<code>};
    return {&traceJobs<code>, code};
}

template <Estimator E>
PathVariant forEstimator(bool media, bool textures, bool rayLanes)
{
    if (media)
        return textures ? instance<E, true, true>(rayLanes) : instance<E, true, false>(rayLanes);
    return textures ? instance<E, false, true>(rayLanes) : instance<E, false, false>(rayLanes);
}
} // namespace detail
} // namespace rt::cpu
