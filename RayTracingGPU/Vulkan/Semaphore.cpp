#include "Vulkan/Semaphore.h"

#include "Vulkan/Check.h"

namespace rt::vk
{
Semaphore::Semaphore(const Device& device)
{
    const VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore semaphore = VK_NULL_HANDLE;
    check(vkCreateSemaphore(device.Handle(), &info, nullptr, &semaphore), "vkCreateSemaphore");
    m_semaphore = DeviceHandle<VkSemaphore, &vkDestroySemaphore>(device.Handle(), semaphore);
}
} // namespace rt::vk
