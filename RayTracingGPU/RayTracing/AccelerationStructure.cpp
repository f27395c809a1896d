#include "RayTracing/AccelerationStructure.h"

#include "Vulkan/Check.h"

namespace rt::gpu
{
AccelerationStructure::AccelerationStructure(const vk::Device& device, VkAccelerationStructureTypeKHR type,
                                             VkDeviceSize size)
    : m_buffer(device, size,
               VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
               vk::MemoryUse::DeviceLocal)
{
    VkAccelerationStructureCreateInfoKHR info{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
    info.buffer = m_buffer.Handle();
    info.size = size;
    info.type = type;
    VkAccelerationStructureKHR structure = VK_NULL_HANDLE;
    vk::check(vkCreateAccelerationStructureKHR(device.Handle(), &info, nullptr, &structure),
              "vkCreateAccelerationStructureKHR");
    m_structure = vk::DeviceHandle<VkAccelerationStructureKHR, &vkDestroyAccelerationStructureKHR>(device.Handle(),
                                                                                                  structure);
    VkAccelerationStructureDeviceAddressInfoKHR addressInfo{
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
    addressInfo.accelerationStructure = structure;
    m_address = vkGetAccelerationStructureDeviceAddressKHR(device.Handle(), &addressInfo);
}
} // namespace rt::gpu
