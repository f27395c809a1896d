// Everything of the path tracer that does not depend on the scene or the image size: the descriptor set
// layout of Bindings.glsl, the pipeline layout (push constants: TracePushConstants), the ray-tracing
// pipeline and its shader binding table. Built once per engine (pipeline compilation is the slow part).
// The Cost variant (the window's heatmap) swaps in the timed ray-generation shader and adds set kSetCost.
#pragma once

#include "Scene/Scene.h"

#include <filesystem>
#include <span>
#include <vector>

#include "RayTracing/ShaderBindingTable.h"
#include "Vulkan/DescriptorSetLayout.h"
#include "Vulkan/Pipeline.h"
#include "Vulkan/PipelineLayout.h"

namespace rt::gpu
{
class GpuScene;

/// Where a render writes: bound to kBindingAccumulation, kBindingUniforms and kBindingCounters.
struct TargetBindings
{
    VkImageView accumulation = VK_NULL_HANDLE; // rgba32f storage image in GENERAL layout
    VkBuffer uniforms = VK_NULL_HANDLE; // RenderUniforms
    VkBuffer counters = VK_NULL_HANDLE; // SampleCounters
};

enum class RayGenVariant
{
    Radiance, // RayGen.rgen
    Cost // RayGenCost.rgen: also times each sample (needs vk::Device::shaderClock())
};

class PathTracingPipeline final
{
public:
    /// Throws rt::AssetError for a missing shader, rt::DeviceError when the driver rejects the pipeline.
    PathTracingPipeline(const vk::Device& device, const std::filesystem::path& shaderDir,
                        RayGenVariant variant = RayGenVariant::Radiance);
    PathTracingPipeline(const PathTracingPipeline&) = delete;
    PathTracingPipeline& operator=(const PathTracingPipeline&) = delete;
    ~PathTracingPipeline() = default;

    const std::vector<vk::DescriptorBinding>& bindings() const { return m_bindings; }
    const vk::DescriptorSetLayout& setLayout() const { return m_setLayout; }
    /// Set kSetCost of the Cost variant (kBindingCost, kBindingCostStats); empty for Radiance.
    const std::vector<vk::DescriptorBinding>& costBindings() const { return m_costBindings; }
    const vk::DescriptorSetLayout& costSetLayout() const { return m_costSetLayout; }
    const vk::PipelineLayout& layout() const { return m_layout; }
    VkPipeline Handle() const { return m_pipeline.Handle(); }
    /// Size of the variable-count sampler array (the most images a scene may have).
    std::uint32_t maxImages() const { return m_maxImages; }

    /// Points every binding of `set` at the resources of `scene` and `target`.
    void writeDescriptors(const vk::Device& device, VkDescriptorSet set, const GpuScene& scene,
                          const TargetBindings& target) const;

    /// Records launches over `extent` tracing `count` camera samples per pixel, sample indices from
    /// `firstSample` on, at most `samplesPerLaunch` of them per launch (each thread loops over its samples:
    /// on an H100 that is 1.8x faster than one launch per sample), with `sets` bound from set 0, each launch
    /// ordered before whatever comes next.
    void recordLaunch(VkCommandBuffer cmd, std::span<const VkDescriptorSet> sets, std::uint32_t firstSample,
                      std::uint32_t count, VkExtent2D extent, std::uint32_t samplesPerLaunch) const;

private:
    std::uint32_t m_maxImages;
    std::vector<vk::DescriptorBinding> m_bindings;
    vk::DescriptorSetLayout m_setLayout;
    std::vector<vk::DescriptorBinding> m_costBindings;
    vk::DescriptorSetLayout m_costSetLayout;
    vk::PipelineLayout m_layout;
    vk::Pipeline m_pipeline;
    ShaderBindingTable m_sbt;
};
} // namespace rt::gpu
