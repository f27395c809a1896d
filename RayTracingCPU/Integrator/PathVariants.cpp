#include "Integrator/PathVariants.h"

#include <spdlog/fmt/fmt.h>

namespace rt::cpu
{
namespace
{
template <Estimator E, bool Media, bool Textures>
PathVariant instance()
{
    constexpr PathCode code{.general = false, .estimator = E, .media = Media, .textures = Textures};
    return {&tracePath<code>, code};
}

template <Estimator E>
PathVariant forEstimator(bool media, bool textures)
{
    if (media)
        return textures ? instance<E, true, true>() : instance<E, true, false>();
    return textures ? instance<E, false, true>() : instance<E, false, false>();
}
} // namespace

std::string PathVariant::describe() const
{
    if (code.general)
        return "general";
    return fmt::format("{}, {}, {}", toString(code.estimator), code.media ? "media" : "no media",
                       code.textures ? "textures" : "solid colours only");
}

PathVariant choosePathVariant(const SceneFeatures& features, Estimator estimator, bool specialize)
{
    if (!specialize)
        return {&tracePath<PathCode{}>, PathCode{}};
    const bool media = features.media;
    const bool textures = features.textures();
    switch (estimator)
    {
    case Estimator::BsdfOnly: return forEstimator<Estimator::BsdfOnly>(media, textures);
    case Estimator::Mixture: return forEstimator<Estimator::Mixture>(media, textures);
    case Estimator::Nee: return forEstimator<Estimator::Nee>(media, textures);
    case Estimator::NeeMis: return forEstimator<Estimator::NeeMis>(media, textures);
    }
    return {&tracePath<PathCode{}>, PathCode{}};
}
} // namespace rt::cpu
