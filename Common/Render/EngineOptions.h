// What an engine is made with: the apps' engine flags, once for every engine. Each engine reads the options it
// knows (the CPU engine: `specialize`; the GPU engine: all of them) and ignores the others.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string_view>

namespace rt
{
/// How far an engine compiles its path code for a render (--specialize).
enum class Specialize
{
    Off, // the general code for every render
    Strategy, // the render's estimator, light sampler, light selection and pixel sampling (GPU); every feature
    Full // the strategy and the scene's features (the default); the GPU's mixture its strategy alone (faster)
};

/// "off", "strategy", "on".
const char* specializeName(Specialize specialize);
/// The mode a name gives, or nothing for an unknown name.
std::optional<Specialize> parseSpecialize(std::string_view name);

/// How the GPU engine runs the estimator (--integrator): one ray-tracing invocation per camera sample looping
/// over its segments (megakernel), kernels per segment over waves of paths (wavefront), or by the render (auto).
enum class GpuIntegrator
{
    Auto,
    Megakernel,
    Wavefront,
};

/// --integrator's names: "auto", "megakernel", "wavefront".
const char* integratorName(GpuIntegrator integrator);
/// The integrator a name gives, or nothing for an unknown name.
std::optional<GpuIntegrator> parseIntegrator(std::string_view name);

struct EngineOptions
{
    Specialize specialize = Specialize::Full;
    std::optional<int> device; // GPU: --device N (vkEnumeratePhysicalDevices order); empty: the best suitable
    bool validation = false; // GPU: the Khronos validation layer and a counting messenger
    std::filesystem::path shaderDir; // GPU: --shader-dir; empty: the shaders beside the executable
    GpuIntegrator integrator = GpuIntegrator::Auto; // GPU
    std::uint32_t wavePaths = 0; // GPU: the wavefront's paths per wave; 0: by the device
};
} // namespace rt
