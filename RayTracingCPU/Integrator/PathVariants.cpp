#include "Integrator/PathVariants.h"

#include <spdlog/fmt/fmt.h>

#include "Integrator/PathVariantInstances.h"

namespace rt::cpu
{
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
    case Estimator::BsdfOnly: return estimatorVariant<Estimator::BsdfOnly>(media, textures, rayLanes);
    case Estimator::Mixture: return estimatorVariant<Estimator::Mixture>(media, textures, rayLanes);
    case Estimator::Nee: return estimatorVariant<Estimator::Nee>(media, textures, rayLanes);
    case Estimator::NeeMis: return estimatorVariant<Estimator::NeeMis>(media, textures, rayLanes);
    case Estimator::RestirDi: break; // its passes run the general shading (Integrator/RestirPasses.h)
    }
    return {&traceJobs<PathCode{}>, PathCode{}};
}
} // namespace rt::cpu
