// A binary semaphore: orders an acquired swapchain image, the frame's submission and its presentation.
#pragma once

#include "Vulkan/Device.h"
#include "Vulkan/DeviceHandle.h"

namespace rt::vk
{
class Semaphore final
{
public:
    Semaphore() = default;
    explicit Semaphore(const Device& device);
    RT_VK_MOVE_ONLY(Semaphore)
    ~Semaphore() = default;

    VkSemaphore Handle() const { return m_semaphore.get(); }

private:
    DeviceHandle<VkSemaphore, &vkDestroySemaphore> m_semaphore;
};
} // namespace rt::vk
