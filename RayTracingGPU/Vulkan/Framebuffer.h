// A framebuffer: the attachments (image views) one render pass draws into, of one size.
#pragma once

#include <vector>

#include "Vulkan/Device.h"
#include "Vulkan/DeviceHandle.h"

namespace rt::vk
{
class Framebuffer final
{
public:
    Framebuffer() = default;
    Framebuffer(const Device& device, VkRenderPass renderPass, const std::vector<VkImageView>& attachments,
                VkExtent2D extent);
    RT_VK_MOVE_ONLY(Framebuffer)
    ~Framebuffer() = default;

    VkFramebuffer Handle() const { return m_framebuffer.get(); }

private:
    DeviceHandle<VkFramebuffer, &vkDestroyFramebuffer> m_framebuffer;
};
} // namespace rt::vk
