#include "Vulkan/DeviceMemory.h"

#include "Vulkan/Check.h"

namespace rt::vk
{
namespace
{
std::uint32_t memoryTypeFor(const Device& device, std::uint32_t typeBits, MemoryUse use)
{
    constexpr VkMemoryPropertyFlags kHost = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    switch (use)
    {
    case MemoryUse::DeviceLocal: return device.findMemoryType(typeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    case MemoryUse::Upload: return device.findMemoryType(typeBits, kHost);
    case MemoryUse::Readback:
        // Cached memory makes host reads fast; not every device offers it.
        if (const auto cached = device.tryFindMemoryType(typeBits, kHost | VK_MEMORY_PROPERTY_HOST_CACHED_BIT))
            return *cached;
        return device.findMemoryType(typeBits, kHost);
    }
    return device.findMemoryType(typeBits, 0);
}
} // namespace

DeviceMemory::DeviceMemory(const Device& device, const VkMemoryRequirements& requirements, MemoryUse use,
                           bool deviceAddress)
{
    VkMemoryAllocateFlagsInfo flags{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
    flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.pNext = deviceAddress ? &flags : nullptr;
    info.allocationSize = requirements.size;
    info.memoryTypeIndex = memoryTypeFor(device, requirements.memoryTypeBits, use);
    VkDeviceMemory memory = VK_NULL_HANDLE;
    check(vkAllocateMemory(device.Handle(), &info, nullptr, &memory), "vkAllocateMemory");
    m_memory = DeviceHandle<VkDeviceMemory, &vkFreeMemory>(device.Handle(), memory);
    if (use != MemoryUse::DeviceLocal)
        check(vkMapMemory(device.Handle(), memory, 0, VK_WHOLE_SIZE, 0, &m_mapped), "vkMapMemory");
}
} // namespace rt::vk
