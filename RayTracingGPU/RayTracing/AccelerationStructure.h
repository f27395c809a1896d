// A VkAccelerationStructureKHR (bottom or top level) with the buffer that stores it.
#pragma once

#include "Vulkan/Buffer.h"
#include "Vulkan/DeviceHandle.h"

namespace rt::gpu
{
class AccelerationStructure final
{
public:
    AccelerationStructure() = default;
    /// Creates an acceleration structure of `type` in a new device-local buffer of `size` bytes (the
    /// accelerationStructureSize of vkGetAccelerationStructureBuildSizesKHR). It is empty until built.
    AccelerationStructure(const vk::Device& device, VkAccelerationStructureTypeKHR type, VkDeviceSize size);
    RT_VK_MOVE_ONLY(AccelerationStructure)
    ~AccelerationStructure() = default;

    VkAccelerationStructureKHR Handle() const { return m_structure.get(); }
    /// What a TLAS instance stores to refer to this BLAS.
    VkDeviceAddress address() const { return m_address; }

private:
    vk::Buffer m_buffer; // declared first: outlives the structure that lives in it
    vk::DeviceHandle<VkAccelerationStructureKHR, &vkDestroyAccelerationStructureKHR> m_structure;
    VkDeviceAddress m_address = 0;
};
} // namespace rt::gpu
