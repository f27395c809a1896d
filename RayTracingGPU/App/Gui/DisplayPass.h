// Shows the ray tracer's images in the window: one full-screen triangle (Display.vert/.frag) that reads the
// accumulation image, or the cost image for the heatmap, at the fragment's own pixel (the images are the
// framebuffer's size), and writes it sRGB-encoded exactly as a PNG from --headless would be.
#pragma once

#include <filesystem>

#include "Shared/HostDevice.h"
#include "Vulkan/DescriptorPool.h"
#include "Vulkan/Pipeline.h"
#include "Vulkan/PipelineLayout.h"

namespace rt::gpu::gui
{
class DisplayPass final
{
public:
    DisplayPass(const vk::Device& device, const std::filesystem::path& shaderDir, VkRenderPass renderPass);
    DisplayPass(const DisplayPass&) = delete;
    DisplayPass& operator=(const DisplayPass&) = delete;
    ~DisplayPass() = default;

    /// Points the pass at the images (after they are made or remade; no frame may be using the set).
    void setImages(VkImageView accumulation, VkImageView cost) const;
    /// Records the draw inside the render pass.
    void record(VkCommandBuffer cmd, VkExtent2D extent, const shader::DisplayPushConstants& push) const;

private:
    const vk::Device* m_device;
    vk::DescriptorSetLayout m_setLayout;
    vk::PipelineLayout m_layout;
    vk::Pipeline m_pipeline;
    vk::DescriptorPool m_pool;
    VkDescriptorSet m_set = VK_NULL_HANDLE;
};
} // namespace rt::gpu::gui
