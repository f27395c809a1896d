#include "Engine/GpuIntegrator.h"

#include "Shared/Estimator.h"

namespace rt::gpu
{
GpuIntegrator resolveIntegrator(GpuIntegrator setting, bool cpuDevice, const shader::RenderUniforms& uniforms,
                                std::uint64_t primitives, std::uint64_t paths, bool media)
{
    if (setting != GpuIntegrator::Auto)
        return setting;
    if (cpuDevice)
        return GpuIntegrator::Megakernel;
    using shader::Estimator;
    const bool nee = shader::usesNee(uniforms.estimator);
    if (nee && uniforms.emitterCount >= 2)
        return paths >= kWavefrontMinPathsNee ? GpuIntegrator::Wavefront : GpuIntegrator::Megakernel;
    // NEE at one emitter and media were measured at 92 M paths on the H100 (docs/notebook/PERFORMANCE.md §26):
    // rect-light-closeup 1.49x, sphere-light-closeup 1.65x, rtnw-cornell-smoke 1.55x in the wavefront; a scene
    // that is its emitter alone (furnace, the camera inside one sphere) 0.55x, its vertices shading next to nothing.
    const bool heavy = (uniforms.estimator == Estimator::Mixture && uniforms.lightCount >= 2) ||
                       (nee && uniforms.emitterCount == 1 && primitives >= 2) || media ||
                       primitives >= kWavefrontPrimitives;
    return heavy && paths >= kWavefrontMinPaths ? GpuIntegrator::Wavefront : GpuIntegrator::Megakernel;
}
} // namespace rt::gpu
