#include "Engine/SceneTracer.h"

#include "Engine/GpuScene.h"
#include "Render/RenderUniforms.h"
#include "Engine/RestirPipeline.h"
#include "Engine/WavefrontPipeline.h"
#include "Error.h"

#include <vector>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

namespace rt::gpu
{
SceneTracer::SceneTracer(const vk::Device& device, const vk::CommandPool& pool, std::filesystem::path shaderDir,
                         Specialize specialize, GpuIntegrator integrator, std::uint32_t waveCapacity)
    : m_device(&device), m_pool(&pool), m_shaderDir(std::move(shaderDir)),
      m_pipeline(device, m_shaderDir, RayGenVariant::Radiance, specialize), m_integrator(GpuIntegrator::Megakernel),
      m_waves(device, 1), m_noRestir(device, 1)
{
    setIntegrator(integrator, waveCapacity);
}

void SceneTracer::setIntegrator(GpuIntegrator integrator, std::uint32_t waveCapacity)
{
    const vk::DeviceProperties& p = m_device->properties();
    const bool cpuDevice = p.type == vk::DeviceType::Cpu;
    const std::string shortfall = m_device->wavefrontShortfall();
    if (integrator == GpuIntegrator::Wavefront && !shortfall.empty())
        throw DeviceError(fmt::format("the wavefront integrator needs what device '{}' lacks: {}", p.name, shortfall));
    // Auto runs the megakernel alone where the wavefront cannot run or would be slower everywhere (a CPU device).
    const bool mayRunWaves = integrator == GpuIntegrator::Wavefront ||
                             (integrator == GpuIntegrator::Auto && !cpuDevice && shortfall.empty());
    std::uint32_t capacity = !mayRunWaves   ? 1u
                             : waveCapacity ? waveCapacity
                                            : waveCapacityFor(cpuDevice, p.deviceLocalHeapSize);
    m_integrator = GpuIntegrator::Megakernel;
    m_wavesReady = false;
    if (capacity != m_waves.capacity())
    {
        m_waves = WaveBuffers(*m_device, 1); // the old ones go first: both may not fit at once
        // Where the device cannot give that much memory, waves of half as many paths, down to 64 K; auto then
        // falls back to the megakernel alone, an explicit wavefront fails.
        while (capacity > 1)
        {
            try
            {
                m_waves = WaveBuffers(*m_device, capacity);
                break;
            }
            catch (const DeviceError& e)
            {
                if (waveCapacity == 0 && capacity > (1u << 16))
                {
                    capacity /= 2;
                    continue;
                }
                if (integrator == GpuIntegrator::Wavefront)
                    throw;
                spdlog::warn("the wavefront integrator's memory does not fit ({}): running the megakernel", e.what());
                integrator = GpuIntegrator::Megakernel;
                capacity = 1;
            }
        }
    }
    if (integrator != GpuIntegrator::Megakernel && mayRunWaves)
    {
        if (!m_wavefront)
            m_wavefront = std::make_unique<WavefrontPipeline>(*m_device, m_shaderDir, m_pipeline);
        m_wavesReady = true;
    }
    m_integrator = integrator;
}

GpuIntegrator SceneTracer::integratorFor(const shader::RenderUniforms& uniforms, std::uint64_t paths) const
{
    if (!m_wavesReady)
        return GpuIntegrator::Megakernel;
    const PipelineScene& scene = gpuScene().pipelineScene();
    return resolveIntegrator(m_integrator, m_device->properties().type == vk::DeviceType::Cpu, uniforms,
                             scene.tracedPrimitives, paths, (scene.features & shader::kFeatureMedia) != 0u);
}

SceneTracer::~SceneTracer() = default;

double SceneTracer::setScene(const Scene& scene)
{
    scene.validate();
    const SceneLayout layout = layoutScene(scene);
    std::unique_ptr<GpuGeometry> previous = m_scene ? m_scene->releaseGeometry() : nullptr;
    m_scene.reset();
    m_sceneDesc = nullptr;
    m_scene = std::make_unique<GpuScene>(*m_device, *m_pool, scene, layout, m_pipeline.maxImages(), std::move(previous));
    m_sceneDesc = &scene;
    m_builds.blas += m_scene->geometryReuse() == GeometryReuse::Built ? 1 : 0;
    m_builds.tlas += m_scene->geometryReuse() != GeometryReuse::Reused ? 1 : 0;
    return m_scene->buildSeconds();
}

double SceneTracer::buildSeconds() const { return m_scene ? m_scene->buildSeconds() : 0.0; }

const GpuScene& SceneTracer::gpuScene() const
{
    if (!m_scene)
        throw UsageError("the GPU engine was asked to trace before it was given a scene");
    return *m_scene;
}

TracingDescriptors SceneTracer::makeDescriptors(const TargetBindings& target) const
{
    const GpuScene& scene = gpuScene();
    const auto imageCount = static_cast<std::uint32_t>(scene.imageViews().size());
    TracingDescriptors d{vk::DescriptorPool(*m_device, m_pipeline.bindings(), imageCount)};
    d.set = d.pool.allocate(m_pipeline.setLayout(), imageCount);
    m_pipeline.writeDescriptors(*m_device, d.set, scene, target, m_waves, target.restir ? *target.restir : m_noRestir);
    return d;
}

shader::RenderUniforms SceneTracer::uniforms(const CameraDesc& camera, const RenderSettings& settings,
                                             VkExtent2D extent) const
{
    gpuScene(); // throws before setScene
    return makeUniforms(*m_sceneDesc, camera, settings, extent.width, extent.height);
}

const RestirPipeline& SceneTracer::restir() const
{
    if (!m_restir)
        m_restir = std::make_unique<RestirPipeline>(*m_device, m_shaderDir, m_pipeline);
    return *m_restir;
}

bool SceneTracer::prepare(const shader::RenderUniforms& uniforms, GpuIntegrator integrator) const
{
    if (uniforms.estimator == Estimator::RestirDi)
        return restir().prepare(uniforms, gpuScene().pipelineScene());
    if (integrator == GpuIntegrator::Wavefront)
        return m_wavefront->prepare(uniforms, gpuScene().pipelineScene());
    return m_pipeline.prepare(uniforms, gpuScene().pipelineScene());
}

void SceneTracer::compileTogether(std::span<const std::pair<shader::RenderUniforms, GpuIntegrator>> renders) const
{
    const PipelineScene& scene = gpuScene().pipelineScene();
    std::vector<PipelineSpecialization> megakernel, wavefront;
    for (const auto& [uniforms, integrator] : renders)
        if (uniforms.estimator != Estimator::RestirDi)
            (integrator == GpuIntegrator::Wavefront ? wavefront : megakernel)
                .push_back(m_pipeline.specializationFor(uniforms, scene));
    m_pipeline.compileTogether(megakernel);
    if (!wavefront.empty())
        m_wavefront->compileTogether(wavefront);
}

void SceneTracer::recordLaunch(VkCommandBuffer cmd, std::span<const VkDescriptorSet> sets,
                               const shader::RenderUniforms& uniforms, GpuIntegrator integrator,
                               std::uint32_t firstSample, std::uint32_t count, VkExtent2D extent,
                               const PathTracingPipeline* variant, std::uint32_t firstRow,
                               std::uint32_t rowInterleave) const
{
    const GpuScene& scene = gpuScene();
    if (!variant && integrator == GpuIntegrator::Wavefront)
    {
        m_wavefront->recordLaunch(cmd, sets, uniforms, scene.pipelineScene(), firstSample, count, extent, firstRow,
                                  rowInterleave, m_waves);
        return;
    }
    (variant ? *variant : m_pipeline)
        .recordLaunch(cmd, sets, uniforms, scene.pipelineScene(), firstSample, count, extent, scene.samplesPerLaunch(),
                      firstRow, rowInterleave);
}
} // namespace rt::gpu
