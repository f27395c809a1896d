#include "Vulkan/Buffer.h"

#include <algorithm>

#include "Vulkan/Check.h"

namespace rt::vk
{
Buffer::Buffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use)
    : m_size(std::max<VkDeviceSize>(size, 1))
{
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = m_size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkBuffer buffer = VK_NULL_HANDLE;
    check(vkCreateBuffer(device.Handle(), &info, nullptr, &buffer), "vkCreateBuffer");
    m_buffer = DeviceHandle<VkBuffer, &vkDestroyBuffer>(device.Handle(), buffer);

    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device.Handle(), buffer, &requirements);
    m_memory = DeviceMemory(device, requirements, use, (usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) != 0);
    check(vkBindBufferMemory(device.Handle(), buffer, m_memory.Handle(), 0), "vkBindBufferMemory");
}

VkDeviceAddress Buffer::address() const
{
    VkBufferDeviceAddressInfo info{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
    info.buffer = m_buffer.get();
    return vkGetBufferDeviceAddress(m_buffer.device(), &info);
}
} // namespace rt::vk
