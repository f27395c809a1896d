#include "Engine/PipelineSpecialization.h"

namespace rt::gpu
{
using namespace shader;

PipelineSpecialization PipelineSpecialization::general()
{
    PipelineSpecialization s;
    s.constants.fill(kSpecDynamic);
    return s;
}

PipelineSpecialization PipelineSpecialization::of(const RenderUniforms& u)
{
    PipelineSpecialization s = general();
    s.constants[kSpecIdEstimator] = static_cast<std::uint32_t>(u.estimator);
    // Only NEE samples lights: the other estimators share one pipeline whatever the sampler and selection.
    const bool nee = u.estimator == Estimator::Nee || u.estimator == Estimator::NeeMis;
    s.constants[kSpecIdLightSampler] = nee ? static_cast<std::uint32_t>(u.lightSampler) : 0u;
    s.constants[kSpecIdLightSelection] = nee ? static_cast<std::uint32_t>(u.lightSelection) : 0u;
    // Accumulate is random jitter to the shaders (the passes are the host's): one pipeline serves both.
    const PixelSampling sampling = u.sampling == PixelSampling::Accumulate ? PixelSampling::Random : u.sampling;
    s.constants[kSpecIdSampling] = static_cast<std::uint32_t>(sampling);
    static_assert(kSpecIdCount == 4, "a new constant id needs its uniform here");
    return s;
}
} // namespace rt::gpu
