// A VkBuffer with its own memory.
#pragma once

#include <cstddef>

#include "Vulkan/DeviceMemory.h"

namespace rt::vk
{
/// `value` rounded up to a multiple of `alignment` (> 0): offsets and device addresses Vulkan wants aligned.
inline VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment)
{
    return (value + alignment - 1) / alignment * alignment;
}

class Buffer final
{
public:
    Buffer() = default;
    /// A buffer of `size` bytes (at least 1: Vulkan has no empty buffers). With
    /// VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT in `usage` the memory is allocated for device addresses.
    Buffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use);
    RT_VK_MOVE_ONLY(Buffer)
    ~Buffer() = default;

    VkBuffer Handle() const { return m_buffer.get(); }
    VkDeviceSize size() const { return m_size; }
    /// vkGetBufferDeviceAddress; the buffer needs VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT.
    VkDeviceAddress address() const;
    /// Host pointer of an Upload or Readback buffer (null for DeviceLocal).
    void* mapped() const { return m_memory.mapped(); }

private:
    DeviceMemory m_memory; // declared first: freed after the buffer is destroyed
    DeviceHandle<VkBuffer, &vkDestroyBuffer> m_buffer;
    VkDeviceSize m_size = 0;
};
} // namespace rt::vk
