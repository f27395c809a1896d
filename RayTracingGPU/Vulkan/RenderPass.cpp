#include "Vulkan/RenderPass.h"

#include "Vulkan/Check.h"

namespace rt::vk
{
RenderPass::RenderPass(const Device& device, const VkRenderPassCreateInfo& info)
{
    VkRenderPass renderPass = VK_NULL_HANDLE;
    check(vkCreateRenderPass(device.Handle(), &info, nullptr, &renderPass), "vkCreateRenderPass");
    m_renderPass = DeviceHandle<VkRenderPass, &vkDestroyRenderPass>(device.Handle(), renderPass);
}
} // namespace rt::vk
