// The Vulkan ray-tracing engine: rt::RenderEngine on a hardware (or software: lavapipe) ray-tracing
// pipeline. setScene uploads the scene and builds BLASes/TLAS; each batch of the render driver is one
// dispatch into an RGBA32F accumulation image (each launch loops over its samples per pixel; one sample per
// launch for scenes with moving spheres), read back for previews and at the end. A batch whose one
// submission would be long is split into bands of rows (about kBatchTargetSeconds each), so that cancel,
// polled between them, is never far away. restir-di runs its own passes instead (RestirPipeline): per sample, the
// candidates, spatial and shading passes, each over every band, on per-pixel buffers kept across batches
// (RestirBuffers).
// docs/GPU.md describes the mapping of the scene, the shader groups and the bindings.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "Engine/GpuContext.h"
#include "Engine/GpuIntegrator.h"
#include "Engine/PipelineSpecialization.h"
#include "Render/RenderEngine.h"

namespace rt::gpu
{
class SceneTracer;
struct AccelerationStructureBuilds;

struct GpuEngineOptions
{
    std::optional<int> deviceIndex; // --device N (vkEnumeratePhysicalDevices order); empty: best suitable
    int deviceShare = 0; // without deviceIndex: which of the best suitable devices (an MPI rank's index on its host)
    bool validation = false; // Khronos validation layer + counting messenger (see validationWanted())
    std::filesystem::path shaderDir; // empty: executableDir()/shaders, never the working directory
    std::uint64_t pathsPerBatch = 0; // camera paths per dispatch; 0: by device type (kPathsPerBatchGpu/Cpu)
    /// Compile a pipeline per render settings and scene features (PipelineSpecialization.h), per settings only
    /// (Strategy), or one general pipeline for everything (Off).
    Specialize specialize = Specialize::Full;
    /// How a launch runs the estimator (GpuIntegrator.h).
    GpuIntegrator integrator = GpuIntegrator::Auto;
    /// The wavefront's paths per wave; 0: by the device (waveCapacityFor).
    std::uint32_t wavePaths = 0;
    /// Count the rays traced by kind (--count-rays): pipelines compiled with the counting atomics (kSpecIdCountRays),
    /// a little slower; without it tally() reports no rays and the pipelines hold no counting code.
    bool countRays = false;
    /// The window: the device must present to its surface (GpuContext.h). Headless leaves it empty.
    std::optional<Presentation> presentation;
};

/// Camera paths one dispatch may hold. On a GPU ~268 M (745 spp of 600x600, 129 of 1920x1080), so that fast
/// renders' batches are sized by time (kBatchTargetSeconds) rather than cut by the cap: each dispatch ends in
/// the tail of its slowest threads, and a cap of 16 M cut a 600x337 render of 1024 spp into 14 of them, which
/// cost the light book scenes up to 7 % on an H200 (docs/notebook/PERFORMANCE.md §8.9; 16 M had run 15 % faster than
/// 4 M). On a CPU device such as lavapipe ~64 K (a fraction of a second at the test sizes).
inline constexpr std::uint64_t kPathsPerBatchGpu = std::uint64_t(1) << 28;
inline constexpr std::uint64_t kPathsPerBatchCpu = std::uint64_t(1) << 16;

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
    const Scene* scene() const override;
    double buildSeconds() const override;

    std::uint64_t pathsPerBatch() const override;
    /// 2^18 on a GPU (an H100 holds 132 SMs x 2048 threads), 4096 on a CPU device (lavapipe).
    std::uint64_t concurrentPaths() const override;
    /// concurrentPaths() / spp where `settings` run on the wavefront, else concurrentPaths().
    std::uint64_t busyPixels(const RenderSettings& settings) const override;
    /// The host's hardware threads, each pipeline compiling on a thread of its own; 1 on a CPU device (lavapipe),
    /// which finishes a pipeline's compilation at its first launch, one after the other in beginFrame.
    std::size_t concurrentCompiles() const override;
    /// The pipelines of `frames` (SceneTracer::compileTogether); nothing while recording costs (their frames run
    /// the cost pipeline). Throws rt::UsageError when no scene is set, rt::DeviceError when the driver rejects
    /// one.
    void compileAhead(std::span<const RenderSettings> frames) override;
    /// Throws rt::UsageError when no scene is set, rt::DeviceError naming the limit when the image does not fit
    /// the device (dimension, memory, invocations per dispatch).
    void beginFrame(const RenderSettings& settings) override;
    /// One dispatch, waited for (never abandoned); its GPU time from timestamp queries (< 0 without them).
    BatchResult traceSamples(std::uint32_t firstSample, std::uint32_t count, RenderControl& control) override;
    /// Reads the accumulation image back (one submission, waited for).
    Image estimate(std::uint32_t samples) override;
    std::vector<double> radianceSums() override;
    SampleTally tally() const override;
    /// Where the time went, in seconds: of setScene, upload_host (buffers and images, host clock) and, where
    /// they were built, blas_build_gpu and tlas_build_gpu (device clock); of the frame, setup_host (beginFrame on
    /// the host's clock: pipeline_host and clear_gpu within it), pipeline_host (the compilation of a pipeline not
    /// cached yet, with a one-row launch of it where a driver finishes compiling at the first launch (lavapipe);
    /// absent when the pipeline was prepared before, by a frame or the window; after compileAhead, that launch
    /// alone), clear_gpu, trace_gpu (= RenderStats::gpuSeconds) within trace_host (every traceSamples: recording,
    /// submitting and waiting), the wavefront's wave_*_gpu and restir-di's restir_*_gpu within trace_gpu,
    /// readback_gpu (every copy of the sum to the host: previews and the result) within readback_host, and
    /// resolve_host (sum / samples into the image). Device times are left out on a queue without timestamps.
    std::map<std::string, double> stageSeconds() const override;
    std::map<std::string, double> frameStageSeconds() const override;
    /// restir-di's buffers per pixel while the frame runs it (RestirBuffers::bytesPerPixel), else none.
    std::map<std::string, std::uint64_t> frameBytesPerPixel() const override;
    /// Empty but for restir-di (not timed per pixel) and a device without VK_KHR_shader_clock.
    std::string costUnavailable(const RenderSettings& settings) const override;
    /// With it on, frames trace through the timed ray generation (RayGenCost.rgen, CostTarget.h): the megakernel
    /// whatever the integrator setting, each sample timed on the shader clock.
    void setCostRecording(bool on) override;
    /// Shader-clock ticks per sample: each pixel's ticks over the samples of the batches that completed (a
    /// cancelled batch's bands keep their ticks).
    CostMap costMap() override;
    /// The pipeline of the frame: PipelineSpecialization::describe() ("general", or the constants in words).
    std::string frameConfiguration() const override;

    /// The instance, device and command pool, for work beside rendering (the tests' compute kernels).
    const GpuContext& context() const;

    bool validationEnabled() const;
    /// Validation warnings and errors reported since the engine was created (0 without validation).
    std::uint64_t validationMessages() const override;
    /// The same counts, readable after the engine is destroyed (leaked objects are reported while the device
    /// is destroyed). Null without validation.
    std::shared_ptr<const vk::ValidationLog> validationLog() const;

    /// The pipeline and the scene on the device: the engine's own progressive frames (ProgressiveFrame.h) trace
    /// with it, and the tests look inside.
    const SceneTracer& tracer() const;
    /// The folder of the SPIR-V the engine loaded (GpuEngineOptions::shaderDir, or executableDir()/shaders):
    /// where a caller's own pipelines (the window's display pass) find theirs.
    const std::filesystem::path& shaderDir() const;
    /// GpuEngineOptions::specialize, from the next frame on (pipelines compiled so far are kept).
    void setSpecialize(Specialize specialize);
    /// GpuEngineOptions::integrator, from the next frame on, with waves of `waveCapacity` paths (0: by the
    /// device; SceneTracer::setIntegrator).
    void setIntegrator(GpuIntegrator integrator, std::uint32_t waveCapacity = 0);
    /// GpuEngineOptions::countRays, from the next frame on.
    void setCountRays(bool countRays);
    /// true: Specialize::Full, false: Specialize::Off.
    void setSpecialize(bool specialize) { setSpecialize(specialize ? Specialize::Full : Specialize::Off); }
    /// BLAS and TLAS builds so far: a scene whose geometry equals the last one's builds nothing.
    const AccelerationStructureBuilds& accelerationStructureBuilds() const;
    /// Rows per submission of a batch (at least 1, at most the image's height); 0, the default: sized by
    /// time, about kBatchTargetSeconds each. Tests fix it to cut a batch into known bands.
    void setBandRows(std::uint32_t rows);

private:
    struct Impl;
    /// The uniforms and the integrator of a frame of `settings` in `blocks` seed blocks: what beginFrame runs
    /// and compileAhead compiles.
    struct FrameSetup;
    FrameSetup frameOf(const RenderSettings& settings, std::uint32_t blocks) const;

    std::unique_ptr<Impl> m_impl;
};
} // namespace rt::gpu
