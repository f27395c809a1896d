#include "Vulkan/Fence.h"

#include <limits>

#include "Vulkan/Check.h"

namespace rt::vk
{
Fence::Fence(const Device& device, bool signaled)
{
    VkFenceCreateInfo info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    info.flags = signaled ? VK_FENCE_CREATE_SIGNALED_BIT : 0;
    VkFence fence = VK_NULL_HANDLE;
    check(vkCreateFence(device.Handle(), &info, nullptr, &fence), "vkCreateFence");
    m_fence = DeviceHandle<VkFence, &vkDestroyFence>(device.Handle(), fence);
}

void Fence::wait() const
{
    const VkFence fence = m_fence.get();
    check(vkWaitForFences(m_fence.device(), 1, &fence, VK_TRUE, std::numeric_limits<std::uint64_t>::max()),
          "vkWaitForFences");
}

void Fence::reset() const
{
    const VkFence fence = m_fence.get();
    check(vkResetFences(m_fence.device(), 1, &fence), "vkResetFences");
}
} // namespace rt::vk
