#include "Engine/GpuIntegrator.h"

#include "Shared/Estimator.h"

namespace rt::gpu
{
GpuIntegrator resolveIntegrator(GpuIntegrator setting, bool cpuDevice, const shader::RenderUniforms& uniforms,
                                std::uint64_t primitives, std::uint64_t paths)
{
    if (setting != GpuIntegrator::Auto)
        return setting;
    if (cpuDevice)
        return GpuIntegrator::Megakernel;
    using shader::Estimator;
    const bool nee = shader::usesNee(uniforms.estimator);
    if (nee && uniforms.emitterCount >= 2)
        return paths >= kWavefrontMinPathsNee ? GpuIntegrator::Wavefront : GpuIntegrator::Megakernel;
    const bool heavy = (uniforms.estimator == Estimator::Mixture && uniforms.lightCount >= 2) ||
                       primitives >= kWavefrontPrimitives;
    return heavy && paths >= kWavefrontMinPaths ? GpuIntegrator::Wavefront : GpuIntegrator::Megakernel;
}
} // namespace rt::gpu
