// Everything of the path tracer that does not depend on the scene or the image size: the descriptor set
// layout of Bindings.glsl, the pipeline layout (push constants: TracePushConstants), the ray-tracing
// pipeline and its shader binding table. Built once per engine (pipeline compilation is the slow part).
#pragma once

#include <filesystem>
#include <vector>

#include "RayTracing/ShaderBindingTable.h"
#include "Vulkan/DescriptorSetLayout.h"
#include "Vulkan/Pipeline.h"
#include "Vulkan/PipelineLayout.h"

namespace rt::gpu
{
class GpuScene;
class RenderTarget;

class PathTracingPipeline final
{
public:
    /// Throws rt::AssetError for a missing shader, rt::DeviceError when the driver rejects the pipeline.
    PathTracingPipeline(const vk::Device& device, const std::filesystem::path& shaderDir);
    PathTracingPipeline(const PathTracingPipeline&) = delete;
    PathTracingPipeline& operator=(const PathTracingPipeline&) = delete;
    ~PathTracingPipeline() = default;

    const std::vector<vk::DescriptorBinding>& bindings() const { return m_bindings; }
    const vk::DescriptorSetLayout& setLayout() const { return m_setLayout; }
    const vk::PipelineLayout& layout() const { return m_layout; }
    VkPipeline Handle() const { return m_pipeline.Handle(); }
    const ShaderBindingTable& sbt() const { return m_sbt; }
    /// Size of the variable-count sampler array (the most images a scene may have).
    std::uint32_t maxImages() const { return m_maxImages; }

    /// Points every binding of `set` at the resources of `scene` and `target`.
    void writeDescriptors(const vk::Device& device, VkDescriptorSet set, const GpuScene& scene,
                          const RenderTarget& target) const;

private:
    std::uint32_t m_maxImages;
    std::vector<vk::DescriptorBinding> m_bindings;
    vk::DescriptorSetLayout m_setLayout;
    vk::PipelineLayout m_layout;
    vk::Pipeline m_pipeline;
    ShaderBindingTable m_sbt;
};
} // namespace rt::gpu
