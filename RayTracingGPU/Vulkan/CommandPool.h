// A command pool of the device's queue family whose buffers can be reset one by one.
#pragma once

#include "Vulkan/Device.h"
#include "Vulkan/DeviceHandle.h"

namespace rt::vk
{
class CommandPool final
{
public:
    CommandPool() = default;
    explicit CommandPool(const Device& device);
    RT_VK_MOVE_ONLY(CommandPool)
    ~CommandPool() = default;

    VkCommandPool Handle() const { return m_pool.get(); }

private:
    DeviceHandle<VkCommandPool, &vkDestroyCommandPool> m_pool;
};
} // namespace rt::vk
