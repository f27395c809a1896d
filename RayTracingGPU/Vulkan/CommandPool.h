// A command pool of the device's queue family whose buffers can be reset one by one, and the fence that
// submitAndWait's submissions of its buffers signal.
#pragma once

#include "Vulkan/Device.h"
#include "Vulkan/DeviceHandle.h"
#include "Vulkan/Fence.h"

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
    /// The fence submitAndWait resets, signals and waits on: one per pool, used under the pool's own external
    /// synchronisation (Vulkan 1.3 §6.2: a pool's buffers are recorded by one thread at a time). A fence made and
    /// destroyed at each submission cost an H200's host (driver 580) 0.7 ms a submission: 0.25 s of a 7 s
    /// render's 355 submissions (docs/notebook/PERFORMANCE.md §69).
    const Fence& submitFence() const { return m_fence; }

private:
    DeviceHandle<VkCommandPool, &vkDestroyCommandPool> m_pool;
    Fence m_fence;
};
} // namespace rt::vk
