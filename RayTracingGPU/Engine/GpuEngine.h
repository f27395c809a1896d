// The Vulkan ray-tracing engine: rt::RenderEngine on a hardware (or software: lavapipe) ray-tracing
// pipeline. setScene uploads the scene and builds BLASes/TLAS; render traces one camera sample per pixel
// per vkCmdTraceRaysKHR into an RGBA32F accumulation image, a few samples per dispatch, and reads it back.
// docs/GPU.md describes the mapping of the scene, the shader groups and the bindings.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "Render/RenderEngine.h"

namespace rt::gpu
{
class GpuContext;

struct GpuEngineOptions
{
    std::optional<int> deviceIndex; // --device N (vkEnumeratePhysicalDevices order); empty: best suitable
    bool validation = false; // Khronos validation layer + counting messenger (see validationWanted())
    std::filesystem::path shaderDir; // empty: executableDir()/shaders, never the working directory
    std::uint64_t pathsPerDispatch = 0; // 0: by device type (DispatchPlan.h)
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

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};
} // namespace rt::gpu
