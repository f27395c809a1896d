// The logical device with the ray-tracing extensions and features of DeviceSelection enabled, its one queue
// and the chosen physical device's properties.
#pragma once

#include <cstdint>
#include <optional>

#include "Vulkan/Loader.h"
#include "Vulkan/PhysicalDevice.h"

namespace rt::vk
{
class Device final
{
public:
    /// Creates the device on `physical`, which selectDevice() accepted. Loads the device-level functions, so
    /// only one Device may be alive at a time (rt::DeviceError otherwise).
    explicit Device(const PhysicalDevice& physical);
    ~Device();
    Device(const Device&) = delete;
    Device& operator=(const Device&) = delete;
    Device(Device&& other) noexcept;
    Device& operator=(Device&& other) noexcept;

    VkDevice Handle() const { return m_device; }
    VkQueue queue() const { return m_queue; }
    std::uint32_t queueFamily() const { return m_queueFamily; }
    const DeviceProperties& properties() const { return m_properties; }

    /// Index of a memory type allowed by `typeBits` with all of `required`. Throws rt::DeviceError if none.
    std::uint32_t findMemoryType(std::uint32_t typeBits, VkMemoryPropertyFlags required) const;
    /// The same, empty when there is none.
    std::optional<std::uint32_t> tryFindMemoryType(std::uint32_t typeBits, VkMemoryPropertyFlags required) const;

private:
    void destroy();

    VkDevice m_device = VK_NULL_HANDLE;
    VkQueue m_queue = VK_NULL_HANDLE;
    std::uint32_t m_queueFamily = 0;
    DeviceProperties m_properties;
};
} // namespace rt::vk
