#pragma once

#include <cstdint>

#include "Vulkan/Device.h"
#include "Vulkan/DeviceHandle.h"

namespace rt::vk
{
class Fence final
{
public:
    Fence() = default;
    explicit Fence(const Device& device, bool signaled = false);
    RT_VK_MOVE_ONLY(Fence)
    ~Fence() = default;

    VkFence Handle() const { return m_fence.get(); }
    /// Blocks until the fence is signalled. Throws rt::DeviceError (device lost, ...).
    void wait() const;
    /// Unsignals the fence for another submission. Throws rt::DeviceError.
    void reset() const;

private:
    DeviceHandle<VkFence, &vkDestroyFence> m_fence;
};
} // namespace rt::vk
