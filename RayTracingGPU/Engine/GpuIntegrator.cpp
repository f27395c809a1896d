#include "Engine/GpuIntegrator.h"

namespace rt::gpu
{
const char* integratorName(GpuIntegrator integrator)
{
    switch (integrator)
    {
    case GpuIntegrator::Auto: return "auto";
    case GpuIntegrator::Megakernel: return "megakernel";
    case GpuIntegrator::Wavefront: return "wavefront";
    }
    return "?";
}

std::optional<GpuIntegrator> parseIntegrator(std::string_view name)
{
    for (const GpuIntegrator i : {GpuIntegrator::Auto, GpuIntegrator::Megakernel, GpuIntegrator::Wavefront})
        if (name == integratorName(i))
            return i;
    return std::nullopt;
}

GpuIntegrator resolveIntegrator(GpuIntegrator setting, bool cpuDevice, const shader::RenderUniforms& uniforms,
                                std::uint64_t primitives)
{
    if (setting != GpuIntegrator::Auto)
        return setting;
    if (cpuDevice)
        return GpuIntegrator::Megakernel;
    using shader::Estimator;
    const bool nee = uniforms.estimator == Estimator::Nee || uniforms.estimator == Estimator::NeeMis;
    const bool severalLights = (nee && uniforms.emitterCount >= 2) ||
                               (uniforms.estimator == Estimator::Mixture && uniforms.lightCount >= 2);
    return severalLights || primitives >= kWavefrontPrimitives ? GpuIntegrator::Wavefront : GpuIntegrator::Megakernel;
}
} // namespace rt::gpu
