#include "Vulkan/Framebuffer.h"

#include "Vulkan/Check.h"

namespace rt::vk
{
Framebuffer::Framebuffer(const Device& device, VkRenderPass renderPass, const std::vector<VkImageView>& attachments,
                         VkExtent2D extent)
{
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = renderPass;
    info.attachmentCount = static_cast<std::uint32_t>(attachments.size());
    info.pAttachments = attachments.data();
    info.width = extent.width;
    info.height = extent.height;
    info.layers = 1;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    check(vkCreateFramebuffer(device.Handle(), &info, nullptr, &framebuffer), "vkCreateFramebuffer");
    m_framebuffer = DeviceHandle<VkFramebuffer, &vkDestroyFramebuffer>(device.Handle(), framebuffer);
}
} // namespace rt::vk
