// A render pass, described by its creator (the window's colour + depth pass).
#pragma once

#include "Vulkan/Device.h"
#include "Vulkan/DeviceHandle.h"

namespace rt::vk
{
class RenderPass final
{
public:
    RenderPass() = default;
    RenderPass(const Device& device, const VkRenderPassCreateInfo& info);
    RT_VK_MOVE_ONLY(RenderPass)
    ~RenderPass() = default;

    VkRenderPass Handle() const { return m_renderPass.get(); }

private:
    DeviceHandle<VkRenderPass, &vkDestroyRenderPass> m_renderPass;
};
} // namespace rt::vk
