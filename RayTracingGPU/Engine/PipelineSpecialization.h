// Which render settings a path-tracing pipeline is compiled for: one value per HostDevice.h kSpecId*
// (estimator, light sampler, light selection, pixel sampling), taken from the render's uniforms, or
// kSpecDynamic everywhere for the general pipeline that reads them at run time. Specialised, the driver folds
// away every estimator, sampler and selection the render does not use (1.1x to 5x faster on an H100,
// docs/PERFORMANCE.md §4.2); the general pipeline is what every render used before, kept for comparison
// (--specialize off).
#pragma once

#include <array>
#include <compare>
#include <cstdint>

#include "Shared/HostDevice.h"

namespace rt::gpu
{
struct PipelineSpecialization
{
    /// Constant id i's value; kSpecDynamic: the shader reads the uniform.
    std::array<std::uint32_t, shader::kSpecIdCount> constants{};

    /// Every constant kSpecDynamic.
    static PipelineSpecialization general();
    /// The settings of `uniforms` that have a constant id.
    static PipelineSpecialization of(const shader::RenderUniforms& uniforms);

    auto operator<=>(const PipelineSpecialization&) const = default;
};
} // namespace rt::gpu
