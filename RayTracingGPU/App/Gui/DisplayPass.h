// Shows the ray tracer's images in the window: one triangle over the image's rectangle (Display.vert/.frag;
// WindowLayout.h places it) that reads the accumulation image, or the cost image for the heatmap, at the texel
// under each fragment, and writes it sRGB-encoded exactly as a PNG from --headless would be.
#pragma once

#include <filesystem>

#include "App/Gui/WindowLayout.h"
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
    /// Records the draw of an `image`-sized image into `rect` of the framebuffer, inside the render pass; sets
    /// push's imageOrigin and texelsPerPixel. Nothing for an empty rectangle.
    void record(VkCommandBuffer cmd, const PixelRect& rect, Extent image, shader::DisplayPushConstants push) const;

private:
    const vk::Device* m_device;
    vk::DescriptorSetLayout m_setLayout;
    vk::PipelineLayout m_layout;
    vk::Pipeline m_pipeline;
    vk::DescriptorPool m_pool;
    VkDescriptorSet m_set = VK_NULL_HANDLE;
};
} // namespace rt::gpu::gui
