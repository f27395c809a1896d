#include "Engine/SceneTracer.h"

#include "Engine/GpuScene.h"
#include "Engine/Uniforms.h"
#include "Error.h"

namespace rt::gpu
{
SceneTracer::SceneTracer(const vk::Device& device, const vk::CommandPool& pool, std::filesystem::path shaderDir,
                         bool specialize)
    : m_device(&device), m_pool(&pool), m_shaderDir(std::move(shaderDir)),
      m_pipeline(device, m_shaderDir, RayGenVariant::Radiance, specialize)
{
}

SceneTracer::~SceneTracer() = default;

double SceneTracer::setScene(const Scene& scene)
{
    scene.validate();
    m_scene.reset();
    m_sceneDesc = nullptr;
    m_scene = std::make_unique<GpuScene>(*m_device, *m_pool, scene, m_pipeline.maxImages());
    m_sceneDesc = &scene;
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
    m_pipeline.writeDescriptors(*m_device, d.set, scene, target);
    return d;
}

shader::RenderUniforms SceneTracer::uniforms(const CameraDesc& camera, const RenderSettings& settings,
                                             VkExtent2D extent) const
{
    gpuScene(); // throws before setScene
    return makeUniforms(*m_sceneDesc, camera, settings, extent.width, extent.height);
}

void SceneTracer::recordLaunch(VkCommandBuffer cmd, std::span<const VkDescriptorSet> sets,
                               const shader::RenderUniforms& uniforms, std::uint32_t firstSample, std::uint32_t count,
                               VkExtent2D extent, const PathTracingPipeline* variant, std::uint32_t firstRow) const
{
    (variant ? *variant : m_pipeline)
        .recordLaunch(cmd, sets, uniforms, firstSample, count, extent, gpuScene().samplesPerLaunch(), firstRow);
}
} // namespace rt::gpu
