#include "Engine/PathTracingPipeline.h"

#include <algorithm>
#include <utility>

#include <spdlog/spdlog.h>

#include "Engine/CompileTogether.h"
#include "Engine/GpuScene.h"
#include "Engine/RestirBuffers.h"
#include "Engine/WaveBuffers.h"
#include "RayTracing/RayTracingPipeline.h"
#include "Shared/HostDevice.h"
#include "Vulkan/Barriers.h"

namespace rt::gpu
{
namespace
{
using namespace shader;


// A scene with more images than this is refused; real scenes have a handful.
constexpr std::uint32_t kImageArrayCap = 1024;

std::uint32_t maxImagesOf(const vk::Device& device)
{
    const VkPhysicalDeviceLimits& limits = device.properties().limits;
    return std::min({limits.maxPerStageDescriptorSampledImages, limits.maxDescriptorSetSampledImages, kImageArrayCap});
}

std::vector<vk::DescriptorBinding> bindingsOf(std::uint32_t maxImages)
{
    std::vector<vk::DescriptorBinding> b;
    const auto add = [&](std::uint32_t binding, VkDescriptorType type, std::uint32_t count = 1,
                         VkDescriptorBindingFlags flags = 0) {
        b.push_back({binding, type, count, kPathTracerStages, flags});
    };
    add(kBindingTlas, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR);
    add(kBindingAccumulation, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);
    add(kBindingCompensation, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);
    add(kBindingUniforms, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
    add(kBindingMixtureLights, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
    for (std::uint32_t binding :
         {kBindingMaterials, kBindingTextures, kBindingLights, kBindingPerlin, kBindingInstances, kBindingPositions,
          kBindingUvs, kBindingTriangles, kBindingTriangleMaterials, kBindingSpheres, kBindingMedia, kBindingCounters,
          kBindingPrimitiveLights, kBindingLightAlias, kBindingLightBvh, kBindingLightBvhLeaves, kBindingWavePaths,
          kBindingWaveQueues, kBindingWaveCounters, kBindingRestirSurfaces, kBindingRestirTemporal, kBindingRestirFinal,
          kBindingRestirTraced, kBindingTraceCounters})
        add(binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    add(kBindingImages, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, maxImages,
        VK_DESCRIPTOR_BINDING_PARTIALLY_BOUND_BIT | VK_DESCRIPTOR_BINDING_VARIABLE_DESCRIPTOR_COUNT_BIT);
    return b;
}

std::vector<vk::DescriptorBinding> costBindingsOf(RayGenVariant variant)
{
    if (variant != RayGenVariant::Cost)
        return {};
    return {{kBindingCost, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_RAYGEN_BIT_KHR},
            {kBindingCostStats, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_RAYGEN_BIT_KHR}};
}

vk::PipelineLayout layoutOf(const vk::Device& device, const vk::DescriptorSetLayout& set,
                            const vk::DescriptorSetLayout& costSet)
{
    std::vector<VkDescriptorSetLayout> sets{set.Handle()};
    if (costSet.Handle() != VK_NULL_HANDLE)
        sets.push_back(costSet.Handle());
    static_assert(kSetCost == 1);
    return vk::PipelineLayout(device, sets, sizeof(TracePushConstants), kPathTracerStages);
}

vk::DescriptorSetLayout setLayoutOf(const vk::Device& device, const std::vector<vk::DescriptorBinding>& bindings)
{
    return bindings.empty() ? vk::DescriptorSetLayout() : vk::DescriptorSetLayout(device, bindings);
}
} // namespace

PathTracingPipeline::PathTracingPipeline(const vk::Device& device, const std::filesystem::path& shaderDir,
                                         RayGenVariant variant, Specialize specialize)
    : m_device(&device), m_specialize(specialize), m_maxImages(maxImagesOf(device)),
      m_bindings(bindingsOf(m_maxImages)), m_setLayout(device, m_bindings), m_costBindings(costBindingsOf(variant)),
      m_costSetLayout(setLayoutOf(device, m_costBindings)), m_layout(layoutOf(device, m_setLayout, m_costSetLayout)),
      m_shaders(device, shaderDir, variant == RayGenVariant::Cost ? "RayGenCost.rgen.spv" : "RayGen.rgen.spv")
{
}

PipelineSpecialization PathTracingPipeline::specializationFor(const RenderUniforms& uniforms,
                                                              const PipelineScene& scene) const
{
    return PipelineSpecialization::of(m_specialize, uniforms, scene.features, scene.hugeSpheres);
}

std::unique_ptr<PathTracingPipeline::Compiled> PathTracingPipeline::make(const PipelineSpecialization& key) const
{
    auto c = std::make_unique<Compiled>();
    c->hitGroups = key.hitGroups();
    c->pipeline = createPathTracingPipeline(*m_device, m_layout, m_shaders, key.constants, c->hitGroups);
    spdlog::debug("compiled the path-tracing pipeline {}", key.describe());
    return c;
}

const PathTracingPipeline::Compiled& PathTracingPipeline::compiled(const PipelineSpecialization& key) const
{
    auto it = m_compiled.find(key);
    if (it == m_compiled.end())
        it = m_compiled.emplace(key, make(key)).first;
    return *it->second;
}

void PathTracingPipeline::compileTogether(std::span<const PipelineSpecialization> keys) const
{
    gpu::compileTogether(m_compiled, keys, [this](const PipelineSpecialization& key) { return make(key); });
}

const ShaderBindingTable& PathTracingPipeline::sbtFor(const Compiled& c, const HitGroupLayout& scene) const
{
    auto it = c.sbts.find(scene);
    if (it == c.sbts.end())
    {
        const std::vector<std::uint32_t> hitGroups = hitRecordGroups(scene, c.hitGroups, kMissGroupCount);
        const std::uint32_t groupCount = 1 + kMissGroupCount + c.hitGroups.count();
        it = c.sbts.emplace(scene, ShaderBindingTable(*m_device, c.pipeline.Handle(), groupCount, kMissGroupCount,
                                                    hitGroups))
                 .first;
    }
    return it->second;
}

bool PathTracingPipeline::prepare(const RenderUniforms& uniforms, const PipelineScene& scene) const
{
    const Compiled& c = compiled(specializationFor(uniforms, scene));
    sbtFor(c, scene.hitGroups);
    return !std::exchange(c.prepared, true);
}

void PathTracingPipeline::recordLaunch(VkCommandBuffer cmd, std::span<const VkDescriptorSet> sets,
                                        const RenderUniforms& uniforms, const PipelineScene& scene,
                                        std::uint32_t firstSample, std::uint32_t count, VkExtent2D extent,
                                        std::uint32_t samplesPerLaunch, std::uint32_t firstRow,
                                        std::uint32_t rowInterleave) const
{
    const Compiled& c = compiled(specializationFor(uniforms, scene));
    const ShaderBindingTable& sbt = sbtFor(c, scene.hitGroups);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, c.pipeline.Handle());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, m_layout.Handle(), 0,
                            static_cast<std::uint32_t>(sets.size()), sets.data(), 0, nullptr);
    for (std::uint32_t done = 0; done < count;)
    {
        std::uint32_t samples = std::min(count - done, std::max(samplesPerLaunch, 1u));
        // A launch's samples in one seed block: the media's hash takes the block's seed from push.firstSample.
        if (const std::uint32_t block = uniforms.seedBlock; block > 0)
            samples = std::min(samples, block - (firstSample + done) % block);
        const TracePushConstants push{firstSample + done, samples, firstRow, rowInterleave};
        vkCmdPushConstants(cmd, m_layout.Handle(), kPathTracerStages, 0, sizeof(push), &push);
        vkCmdTraceRaysKHR(cmd, &sbt.raygen(), &sbt.miss(), &sbt.hit(), &sbt.callable(), extent.width,
                          extent.height, 1);
        // The launch reads and writes its pixels of the accumulation image: order it before the next one.
        vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_SHADER_WRITE_BIT,
                          VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR,
                          VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
        done += samples;
    }
}

void PathTracingPipeline::writeDescriptors(const vk::Device& device, VkDescriptorSet set, const GpuScene& scene,
                                           const TargetBindings& target, const WaveBuffers& waves,
                                           const RestirBuffers& restir) const
{
    const VkAccelerationStructureKHR tlas = scene.tlas();
    VkWriteDescriptorSetAccelerationStructureKHR tlasInfo{
        VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR};
    tlasInfo.accelerationStructureCount = 1;
    tlasInfo.pAccelerationStructures = &tlas;
    const VkDescriptorImageInfo accumulation{VK_NULL_HANDLE, target.accumulation, VK_IMAGE_LAYOUT_GENERAL};
    const VkDescriptorImageInfo compensation{VK_NULL_HANDLE, target.compensation, VK_IMAGE_LAYOUT_GENERAL};

    const GpuScene::Buffers& buffers = scene.buffers();
    const std::pair<std::uint32_t, const vk::Buffer*> storage[] = {
        {kBindingMaterials, &buffers.materials},
        {kBindingTextures, &buffers.textures},
        {kBindingLights, &buffers.lights},
        {kBindingPerlin, &buffers.perlin},
        {kBindingInstances, &buffers.records},
        {kBindingPrimitiveLights, &buffers.primitiveLights},
        {kBindingLightAlias, &buffers.lightAlias},
        {kBindingLightBvh, &buffers.lightBvh},
        {kBindingLightBvhLeaves, &buffers.lightBvhLeaves},
        {kBindingPositions, &scene.geometry().positions},
        {kBindingUvs, &buffers.uvs},
        {kBindingTriangles, &scene.geometry().triangles},
        {kBindingTriangleMaterials, &buffers.triangleMaterials},
        {kBindingSpheres, &buffers.spheres},
        {kBindingMedia, &buffers.media},
        {kBindingWavePaths, &waves.paths()},
        {kBindingWaveQueues, &waves.queues()},
        {kBindingWaveCounters, &waves.counters()},
        {kBindingRestirSurfaces, &restir.surfaces()},
        {kBindingRestirTemporal, &restir.temporal()},
        {kBindingRestirFinal, &restir.final()},
        {kBindingRestirTraced, &restir.traced()},
    };
    std::vector<VkDescriptorBufferInfo> bufferInfos;
    bufferInfos.reserve(std::size(storage) + 4);
    bufferInfos.push_back({target.uniforms, 0, VK_WHOLE_SIZE});
    bufferInfos.push_back({target.counters, 0, VK_WHOLE_SIZE});
    bufferInfos.push_back({buffers.mixtureLights.Handle(), 0, VK_WHOLE_SIZE});
    bufferInfos.push_back({target.traceCounters, 0, VK_WHOLE_SIZE});
    for (const auto& [binding, buffer] : storage)
        bufferInfos.push_back({buffer->Handle(), 0, VK_WHOLE_SIZE});
    std::vector<VkDescriptorImageInfo> imageInfos;
    for (const vk::ImageView& view : scene.imageViews())
        imageInfos.push_back({scene.sampler(), view.Handle(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});

    std::vector<VkWriteDescriptorSet> writes;
    writes.reserve(std::size(storage) + 7); // write() hands out references into it
    const auto write = [&](std::uint32_t binding, VkDescriptorType type, std::uint32_t count) -> VkWriteDescriptorSet& {
        VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        w.dstSet = set;
        w.dstBinding = binding;
        w.descriptorCount = count;
        w.descriptorType = type;
        writes.push_back(w);
        return writes.back();
    };
    write(kBindingTlas, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1).pNext = &tlasInfo;
    write(kBindingAccumulation, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1).pImageInfo = &accumulation;
    write(kBindingCompensation, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1).pImageInfo = &compensation;
    write(kBindingUniforms, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1).pBufferInfo = &bufferInfos[0];
    write(kBindingCounters, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1).pBufferInfo = &bufferInfos[1];
    write(kBindingMixtureLights, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1).pBufferInfo = &bufferInfos[2];
    write(kBindingTraceCounters, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1).pBufferInfo = &bufferInfos[3];
    for (std::size_t i = 0; i < std::size(storage); ++i)
        write(storage[i].first, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1).pBufferInfo = &bufferInfos[i + 4];
    // A scene without images binds none: the binding is partially bound with a variable count, allocated at 0
    // (no dummy texel needed), and no shader reads it (the general pipeline reads it only at image textures).
    if (!imageInfos.empty())
        write(kBindingImages, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, static_cast<std::uint32_t>(imageInfos.size()))
            .pImageInfo = imageInfos.data();
    vkUpdateDescriptorSets(device.Handle(), static_cast<std::uint32_t>(writes.size()), writes.data(), 0, nullptr);
}
} // namespace rt::gpu
