// The GPU engine's per-pixel cost (--heatmap): the pipeline of RayGenCost.rgen, which times each camera sample on
// the shader clock, the r32f image of each pixel's ticks summed over its samples, the CostStats the shader also
// keeps (the window's scale), and descriptor set kSetCost naming the two. Needs VK_KHR_shader_clock.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "Engine/PathTracingPipeline.h"
#include "Vulkan/Buffer.h"
#include "Vulkan/CommandPool.h"
#include "Vulkan/DescriptorPool.h"
#include "Vulkan/Device.h"
#include "Vulkan/Image.h"

namespace rt::gpu
{
/// Points set kSetCost `set` at `image` (the r32f ticks image, in GENERAL layout) and `stats` (a CostStats buffer).
void writeCostSet(const vk::Device& device, VkDescriptorSet set, VkImageView image, VkBuffer stats);

class CostTarget
{
public:
    /// For images of `width` x `height`. Loads the timed ray-generation shader; compiles nothing yet.
    /// Precondition: device.shaderClock(). Throws rt::AssetError (shader missing), rt::DeviceError.
    CostTarget(const vk::Device& device, const std::filesystem::path& shaderDir, Specialize specialize,
               std::uint32_t width, std::uint32_t height);

    const PathTracingPipeline& pipeline() const { return m_pipeline; }
    /// Set kSetCost, to bind after the scene's set 0.
    VkDescriptorSet set() const { return m_set; }
    std::uint32_t width() const { return m_image.extent().width; }
    std::uint32_t height() const { return m_image.extent().height; }

    /// Records zeros into the image (from any layout: its contents are dropped), left in GENERAL for the tracing.
    void recordClear(VkCommandBuffer cmd) const;
    /// Each pixel's ticks summed since the last clear, row by row from the top: one submission, waited for.
    std::vector<float> readTicks(const vk::Device& device, const vk::CommandPool& pool) const;

private:
    PathTracingPipeline m_pipeline;
    vk::Image m_image;
    vk::ImageView m_view;
    vk::Buffer m_stats; // CostStats
    vk::DescriptorPool m_pool;
    VkDescriptorSet m_set = VK_NULL_HANDLE;
};
} // namespace rt::gpu
