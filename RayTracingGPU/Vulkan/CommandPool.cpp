#include "Vulkan/CommandPool.h"

#include "Vulkan/Check.h"

namespace rt::vk
{
CommandPool::CommandPool(const Device& device)
{
    VkCommandPoolCreateInfo info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    info.queueFamilyIndex = device.queueFamily();
    VkCommandPool pool = VK_NULL_HANDLE;
    check(vkCreateCommandPool(device.Handle(), &info, nullptr, &pool), "vkCreateCommandPool");
    m_pool = DeviceHandle<VkCommandPool, &vkDestroyCommandPool>(device.Handle(), pool);
    m_fence = Fence(device);
}
} // namespace rt::vk
