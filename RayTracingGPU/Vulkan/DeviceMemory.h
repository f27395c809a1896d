// One VkDeviceMemory allocation. The engine allocates one per buffer or image (no sub-allocation: scenes
// have tens of buffers, far below maxMemoryAllocationCount).
#pragma once

#include "Vulkan/Device.h"
#include "Vulkan/DeviceHandle.h"

namespace rt::vk
{
/// Where a resource lives and how the host reaches it.
enum class MemoryUse
{
    DeviceLocal, // GPU only; filled by copies
    Upload, // host-visible and coherent, persistently mapped; host writes, GPU reads
    Readback // host-visible and coherent (cached when the device offers it), persistently mapped
};

class DeviceMemory final
{
public:
    DeviceMemory() = default;
    /// Allocates for `requirements` with the properties `use` needs; `deviceAddress` adds
    /// VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT. Maps host-visible memory. Throws rt::DeviceError.
    DeviceMemory(const Device& device, const VkMemoryRequirements& requirements, MemoryUse use, bool deviceAddress);
    RT_VK_MOVE_ONLY(DeviceMemory)
    ~DeviceMemory() = default;

    VkDeviceMemory Handle() const { return m_memory.get(); }
    /// The host pointer of host-visible memory, null for device-local memory.
    void* mapped() const { return m_mapped; }

private:
    DeviceHandle<VkDeviceMemory, &vkFreeMemory> m_memory;
    void* m_mapped = nullptr; // unmapped implicitly by vkFreeMemory
};
} // namespace rt::vk
