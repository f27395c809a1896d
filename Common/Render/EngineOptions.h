// What an engine is made with: the apps' engine flags, once for every engine. Each engine reads the options it
// knows (the CPU engine: `specialize`; the GPU engine: all of them) and ignores the others.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>

#include "Render/NamedEnum.h"

namespace rt
{
/// How far an engine compiles its path code for a render (--specialize).
enum class Specialize
{
    Off, // the general code for every render
    Strategy, // the render's estimator, light sampler, light selection and pixel sampling (GPU); every feature
    Full // the strategy and the scene's features (the default); on the GPU, a mixture in a scene with media
         // its strategy alone (faster)
};

template <>
struct EnumNames<Specialize>
{
    static constexpr std::array<EnumName<Specialize>, 3> values{
        {{Specialize::Off, "off"}, {Specialize::Strategy, "strategy"}, {Specialize::Full, "on"}}};
};

/// How the GPU engine runs the estimator (--integrator): one ray-tracing invocation per camera sample looping
/// over its segments (megakernel), kernels per segment over waves of paths (wavefront), or by the render (auto).
enum class GpuIntegrator
{
    Auto,
    Megakernel,
    Wavefront,
};

template <>
struct EnumNames<GpuIntegrator>
{
    static constexpr std::array<EnumName<GpuIntegrator>, 3> values{{{GpuIntegrator::Auto, "auto"},
                                                                    {GpuIntegrator::Megakernel, "megakernel"},
                                                                    {GpuIntegrator::Wavefront, "wavefront"}}};
};

struct EngineOptions
{
    Specialize specialize = Specialize::Full;
    std::optional<int> device; // GPU: --device N (vkEnumeratePhysicalDevices order); empty: the best suitable
    bool validation = false; // GPU: the Khronos validation layer and a counting messenger
    std::filesystem::path shaderDir; // GPU: --shader-dir; empty: the shaders beside the executable
    GpuIntegrator integrator = GpuIntegrator::Auto; // GPU
    std::uint32_t wavePaths = 0; // GPU: the wavefront's paths per wave; 0: by the device
    bool countRays = false; // GPU: count rays by kind (--count-rays); the CPU engines always count them
};
} // namespace rt
