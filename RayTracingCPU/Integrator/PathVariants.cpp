#include "Integrator/PathVariants.h"

#include <spdlog/fmt/fmt.h>

namespace rt::cpu
{
namespace
{
template <Estimator E, bool Media, bool Textures>
PathVariant instance(bool rayLanes)
{
    constexpr PathCode code{.general = false, .estimator = E, .media = Media, .textures = Textures};
    // kLanes paths at a time: with ray lanes wherever the scene allows them (book 3's scene 1.15x), and else
    // for the estimators without shadow rays (the sphere scenes of books 1-2 1.01-1.04x, where one path at a
    // time lost 4-7 % to this loop's split into continuePath). NEE's renders of scenes with a BVH were 1-3 %
    // slower interleaved and run one path at a time (docs/PERFORMANCE.md §1).
    constexpr bool kNeeEstimator = E == Estimator::Nee || E == Estimator::NeeMis;
    if constexpr (Media)
        return {&tracePath<code>, code}; // a medium's intersection draws random numbers: one path at a time
    else if (rayLanes || !kNeeEstimator)
        return {&tracePath<code>, code, &tracePaths<code>, rayLanes};
    else
        return {&tracePath<code>, code};
}

template <Estimator E>
PathVariant forEstimator(bool media, bool textures, bool rayLanes)
{
    if (media)
        return textures ? instance<E, true, true>(rayLanes) : instance<E, true, false>(rayLanes);
    return textures ? instance<E, false, true>(rayLanes) : instance<E, false, false>(rayLanes);
}
} // namespace

std::string PathVariant::describe() const
{
    if (code.general)
        return "general";
    return fmt::format("{}, {}, {}{}", toString(code.estimator), code.media ? "media" : "no media",
                       code.textures ? "textures" : "solid colours only",
                       !traceLanes ? std::string()
                       : rayLanes  ? fmt::format(", {} rays at a time", kLanes)
                                   : fmt::format(", {} paths interleaved", kLanes));
}

PathVariant choosePathVariant(const SceneFeatures& features, Estimator estimator, bool specialize, bool rayLanes)
{
    if (!specialize)
        return {&tracePath<PathCode{}>, PathCode{}};
    const bool media = features.media;
    const bool textures = features.textures();
    switch (estimator)
    {
    case Estimator::BsdfOnly: return forEstimator<Estimator::BsdfOnly>(media, textures, rayLanes);
    case Estimator::Mixture: return forEstimator<Estimator::Mixture>(media, textures, rayLanes);
    case Estimator::Nee: return forEstimator<Estimator::Nee>(media, textures, rayLanes);
    case Estimator::NeeMis: return forEstimator<Estimator::NeeMis>(media, textures, rayLanes);
    }
    return {&tracePath<PathCode{}>, PathCode{}};
}
} // namespace rt::cpu
