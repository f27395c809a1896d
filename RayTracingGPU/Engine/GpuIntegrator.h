// How the GPU engine runs the path-tracing estimator: one ray-tracing invocation per camera sample looping
// over its segments (the megakernel, RayGen.rgen), or kernels per segment over a wave of paths
// (WavefrontPipeline.h). Both compute the same estimator with the same shading code (PathVertex.glsl).
#pragma once

#include <optional>
#include <string_view>

namespace rt::gpu
{
enum class GpuIntegrator
{
    Megakernel,
    Wavefront,
};

/// --integrator's names: "megakernel", "wavefront".
constexpr const char* integratorName(GpuIntegrator integrator)
{
    return integrator == GpuIntegrator::Wavefront ? "wavefront" : "megakernel";
}

/// The integrator a name gives, or nothing for an unknown name.
constexpr std::optional<GpuIntegrator> parseIntegrator(std::string_view name)
{
    if (name == "megakernel")
        return GpuIntegrator::Megakernel;
    if (name == "wavefront")
        return GpuIntegrator::Wavefront;
    return std::nullopt;
}
} // namespace rt::gpu
