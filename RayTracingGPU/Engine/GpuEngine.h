// The Vulkan ray-tracing engine: rt::RenderEngine on a hardware (or software: lavapipe) ray-tracing
// pipeline. setScene uploads the scene and builds BLASes/TLAS; render traces the samples into an RGBA32F
// accumulation image in dispatches of bounded size (each launch loops over its samples per pixel; one sample
// per launch for scenes with moving spheres) and reads it back.
// docs/GPU.md describes the mapping of the scene, the shader groups and the bindings.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "Engine/GpuContext.h"
#include "Render/RenderEngine.h"

namespace rt::gpu
{
class GpuScene;
class PathTracingPipeline;

struct GpuEngineOptions
{
    std::optional<int> deviceIndex; // --device N (vkEnumeratePhysicalDevices order); empty: best suitable
    bool validation = false; // Khronos validation layer + counting messenger (see validationWanted())
    std::filesystem::path shaderDir; // empty: executableDir()/shaders, never the working directory
    std::uint64_t pathsPerDispatch = 0; // 0: by device type (DispatchPlan.h)
    /// The window: the device must present to its surface (GpuContext.h). Headless leaves it empty.
    std::optional<Presentation> presentation;
};

class GpuEngine final : public RenderEngine
{
public:
    /// Creates the device and compiles the pipeline. Throws rt::DeviceError (no Vulkan, no suitable device:
    /// the message lists every device and what it lacks), rt::UsageError (bad device index), rt::AssetError
    /// (shaders missing).
    explicit GpuEngine(const GpuEngineOptions& options = {});
    ~GpuEngine() override;
    GpuEngine(const GpuEngine&) = delete;
    GpuEngine& operator=(const GpuEngine&) = delete;

    EngineKind kind() const override { return EngineKind::Gpu; }
    std::string deviceName() const override;
    double setScene(const Scene& scene) override;
    /// Throws rt::UsageError for invalid settings or when no scene is set, rt::DeviceError naming the limit
    /// when the image does not fit the device (dimension, memory).
    RenderResult render(const RenderSettings& settings, RenderControl& control,
                        const PreviewCallback& preview = {}) override;

    /// The instance, device and command pool, for work beside rendering (the tests' compute kernels).
    const GpuContext& context() const;

    bool validationEnabled() const;
    /// Validation warnings and errors reported since the engine was created (0 without validation).
    std::uint64_t validationMessages() const;
    /// The same counts, readable after the engine is destroyed (leaked objects are reported while the device
    /// is destroyed). Null without validation.
    std::shared_ptr<const vk::ValidationLog> validationLog() const;

    // Interactive rendering (ProgressiveRenderer, RasterPreview: the window) records its own command buffers
    // with the engine's pipeline and scene, and passes its camera through makeUniforms (Uniforms.h).
    const PathTracingPipeline& pipeline() const;
    /// Where the SPIR-V files are (the window's pipelines load theirs from there too).
    const std::filesystem::path& shaderDir() const;
    /// The scene set last, on the device and as described. Throw rt::UsageError before setScene.
    const GpuScene& gpuScene() const;
    const Scene& scene() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};
} // namespace rt::gpu
