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
    // kLanes paths at a time where their rays are tested together (book 3's scene 1.15x). Paths merely
    // interleaved over a BVH, each ray traversing it alone, were 0.92x (rtrol-cornell-mirror) to 1.04x
    // (rtow-final) one path at a time: not kept (docs/notebook/PERFORMANCE.md §1). The lanes test quads and spheres only
    // (CpuScene::tracesRayLanes), so media scenes never test rays in lanes.
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
} // namespace

std::string PathVariant::describe() const
{
    if (code.general)
        return "general";
    return fmt::format("{}, {}, {}{}", toString(code.estimator), code.media ? "media" : "no media",
                       code.textures ? "textures or microfacet" : "solid colours only",
                       traceLanes ? fmt::format(", {} rays at a time", kLanes) : std::string());
}

PathVariant choosePathVariant(const SceneFeatures& features, Estimator estimator, bool specialize, bool rayLanes)
{
    if (!specialize)
        return {&traceJobs<PathCode{}>, PathCode{}};
    const bool media = features.media;
    const bool textures = features.textures() || features.conductor || features.roughDielectric || features.gltfPbr;
    switch (estimator)
    {
    case Estimator::BsdfOnly: return forEstimator<Estimator::BsdfOnly>(media, textures, rayLanes);
    case Estimator::Mixture: return forEstimator<Estimator::Mixture>(media, textures, rayLanes);
    case Estimator::Nee: return forEstimator<Estimator::Nee>(media, textures, rayLanes);
    case Estimator::NeeMis: return forEstimator<Estimator::NeeMis>(media, textures, rayLanes);
    }
    return {&traceJobs<PathCode{}>, PathCode{}};
}
} // namespace rt::cpu
