// The GPU engine's core, shared by its two ways to render, the batches of the render interface (GpuEngine)
// and the progressive frames a window shows (ProgressiveFrame): the path-tracing pipeline, compiled once, and
// the scene on the device (GpuScene: BLAS/TLAS, buffers, images). A caller traces into an accumulation image
// of its own with three calls: a descriptor set naming the scene and its target, the uniforms of a camera and
// settings, and the launches. It owns no image, and only setScene waits for the device. A new scene whose geometry is the
// last one's keeps its acceleration structures (GpuScene, GeometryFingerprint); the builds are counted.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <utility>

#include "Engine/GpuIntegrator.h"
#include "Engine/PathTracingPipeline.h"
#include "Engine/RestirBuffers.h"
#include "Engine/WaveBuffers.h"
#include "Render/RenderSettings.h"
#include "Scene/Scene.h"
#include "Shared/HostDevice.h"
#include "Vulkan/CommandPool.h"
#include "Vulkan/DescriptorPool.h"

namespace rt::gpu
{
class GpuScene;
class RestirPipeline;
class WavefrontPipeline;

/// A descriptor set of the pipeline's set 0 and the pool it lives in (freed together).
struct TracingDescriptors
{
    vk::DescriptorPool pool;
    VkDescriptorSet set = VK_NULL_HANDLE;
};

/// Acceleration-structure builds since the tracer was made: each counts one submission that built every BLAS
/// of a scene (blas) or its TLAS (tlas). A scene whose geometry was kept adds to neither.
struct AccelerationStructureBuilds
{
    std::uint64_t blas = 0;
    std::uint64_t tlas = 0;
};

class SceneTracer final
{
public:
    /// Loads the SPIR-V in `shaderDir`; a render's pipeline is compiled for its settings and scene when it
    /// first needs it (PathTracingPipeline), or once for all with Specialize::Off. Launches run `integrator`
    /// with waves of `waveCapacity` paths (setIntegrator; the wavefront's memory is allocated here). Throws
    /// rt::AssetError (a shader is missing), rt::DeviceError (the driver rejects a module, or an explicit
    /// wavefront cannot run: setIntegrator).
    SceneTracer(const vk::Device& device, const vk::CommandPool& pool, std::filesystem::path shaderDir,
                Specialize specialize = Specialize::Full, GpuIntegrator integrator = GpuIntegrator::Auto,
                std::uint32_t waveCapacity = 0);
    SceneTracer(const SceneTracer&) = delete;
    SceneTracer& operator=(const SceneTracer&) = delete;
    ~SceneTracer();

    /// Uploads `scene` (validated first; it must outlive the tracer's use of it) and builds its acceleration
    /// structures, or keeps the last scene's where the geometry is the same; waits for the device. Descriptor
    /// sets made for the previous scene must be dropped first. Returns the build time in seconds (0 when
    /// kept). Throws rt::SceneError, rt::DeviceError; the previous scene is gone then.
    double setScene(const Scene& scene);
    /// The scene set last; nullptr before the first.
    const Scene* scene() const { return m_sceneDesc; }
    double buildSeconds() const;
    /// The scene on the device. Throws rt::UsageError before setScene.
    const GpuScene& gpuScene() const;
    const AccelerationStructureBuilds& accelerationStructureBuilds() const { return m_builds; }

    const std::filesystem::path& shaderDir() const { return m_shaderDir; }
    /// The pipeline's set layouts: a variant (the window's Cost pipeline) is built against the same ones.
    const PathTracingPipeline& pipeline() const { return m_pipeline; }
    /// PathTracingPipeline::setSpecialize.
    void setSpecialize(Specialize specialize) { m_pipeline.setSpecialize(specialize); }
    /// The integrator setting (GpuIntegrator::Auto resolves per render: integratorFor).
    GpuIntegrator integrator() const { return m_integrator; }
    /// What a render of `paths` camera paths with `uniforms` of the current scene runs (resolveIntegrator):
    /// decided once per render, so that its image does not depend on how it is cut into batches.
    GpuIntegrator integratorFor(const shader::RenderUniforms& uniforms, std::uint64_t paths) const;
    /// From the next launch on, runs `integrator`, with waves of `waveCapacity` paths (0: waveCapacityFor the
    /// device, halved while the device cannot allocate them, down to 64 K). Auto runs the megakernel alone on
    /// a CPU device, on a device without what the wavefront needs (vk::Device::wavefrontShortfall) and where
    /// its memory does not fit (saying so). Descriptor sets made before must be dropped and made again: they
    /// name the old wave buffers. Throws rt::DeviceError for an explicit wavefront the device cannot run,
    /// naming what it lacks, or whose memory does not fit.
    void setIntegrator(GpuIntegrator integrator, std::uint32_t waveCapacity = 0);
    /// Paths per wave of the wavefront integrator (1 where the tracer never runs it).
    std::uint32_t waveCapacity() const { return m_waves.capacity(); }
    /// The wavefront integrator's pipelines (null until it first runs) and memory, for a caller that records
    /// its waves itself (GpuEngine: a submission per wave, stopping once its queues are empty).
    const WavefrontPipeline* wavefront() const { return m_wavefront.get(); }
    const WaveBuffers& waves() const { return m_waves; }
    /// Compiles the pipeline a render with `uniforms` of the current scene needs on `integrator`
    /// (integratorFor; PathTracingPipeline::prepare), or restir-di's (RestirPipeline) for that estimator; true at
    /// the first call for that pipeline (compiled now or by compileTogether), when its first launch is still to come.
    bool prepare(const shader::RenderUniforms& uniforms, GpuIntegrator integrator) const;
    /// The compilations of prepare for several renders (their uniforms and integrators), each pipeline on a thread
    /// of its own (PathTracingPipeline::compileTogether); restir-di's are left to prepare. Each render's prepare
    /// still returns true once. Throws rt::DeviceError as prepare, after the other pipelines are compiled.
    void compileTogether(std::span<const std::pair<shader::RenderUniforms, GpuIntegrator>> renders) const;
    /// restir-di's passes (made at the first use). Throws rt::AssetError, rt::DeviceError as the constructor.
    const RestirPipeline& restir() const;

    /// Set 0 for the current scene and `target` (restir-di's buffers: target.restir, else one pixel's). Throws
    /// rt::UsageError before setScene.
    TracingDescriptors makeDescriptors(const TargetBindings& target) const;
    /// The uniforms of an image of `extent` seen by `camera` with `settings` (the current scene's background,
    /// light count).
    shader::RenderUniforms uniforms(const CameraDesc& camera, const RenderSettings& settings, VkExtent2D extent) const;
    /// Records `count` samples per pixel of `extent` from `firstSample` on, with `sets` bound from set 0, whose
    /// uniform buffer holds `uniforms`, through `variant` (a megakernel: PathTracingPipeline::recordLaunch, with
    /// the scene's samples per launch) or else `integrator` (integratorFor: Megakernel or Wavefront). `extent`
    /// may be a band of rows, positions from `firstRow` on in the row order of `rowInterleave` (Shared/BandOrder.h). The wavefront records every wave to the render's depth
    /// (GpuEngine submits its waves itself, stopping where their queues empty).
    void recordLaunch(VkCommandBuffer cmd, std::span<const VkDescriptorSet> sets,
                      const shader::RenderUniforms& uniforms, GpuIntegrator integrator, std::uint32_t firstSample,
                      std::uint32_t count, VkExtent2D extent, const PathTracingPipeline* variant = nullptr,
                      std::uint32_t firstRow = 0, std::uint32_t rowInterleave = 1) const;

private:
    const vk::Device* m_device;
    const vk::CommandPool* m_pool;
    std::filesystem::path m_shaderDir;
    PathTracingPipeline m_pipeline;
    GpuIntegrator m_integrator;
    WaveBuffers m_waves; // one path's worth for the megakernel: the descriptors name them either way
    RestirBuffers m_noRestir; // one pixel's: what the descriptors of a frame without restir-di name
    mutable std::unique_ptr<RestirPipeline> m_restir;
    std::unique_ptr<WavefrontPipeline> m_wavefront; // made the first time the wavefront may run, then kept
    bool m_wavesReady = false; // the wavefront may run: the device has what it needs and its memory
    const Scene* m_sceneDesc = nullptr;
    std::unique_ptr<GpuScene> m_scene;
    AccelerationStructureBuilds m_builds;
};
} // namespace rt::gpu
