// The logical device with the ray-tracing extensions and features of DeviceSelection enabled, its one queue
// and the chosen physical device's properties. In window mode it also presents (VK_KHR_swapchain); where the
// device has VK_KHR_shader_clock it enables it for the window's heatmap.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "Vulkan/Loader.h"
#include "Vulkan/PhysicalDevice.h"

namespace rt::vk
{
class Device final
{
public:
    /// Creates the device on `physical`, which selectDevice() accepted (with `presentation` as required). Loads
    /// the device-level functions, so only one Device may be alive at a time (rt::DeviceError otherwise).
    explicit Device(const PhysicalDevice& physical, bool presentation = false);
    ~Device();
    Device(const Device&) = delete;
    Device& operator=(const Device&) = delete;
    Device(Device&& other) noexcept;
    Device& operator=(Device&& other) noexcept;

    VkDevice Handle() const { return m_device; }
    VkPhysicalDevice physical() const { return m_physical; }
    VkQueue queue() const { return m_queue; }
    std::uint32_t queueFamily() const { return m_queueFamily; }
    const DeviceProperties& properties() const { return m_properties; }
    /// VK_KHR_shader_clock with shaderSubgroupClock is enabled (clockARB in shaders).
    bool shaderClock() const { return m_shaderClock; }
    /// What the wavefront integrator needs and this device lacks ("" when nothing): indirect ray-tracing
    /// launches (rayTracingPipelineTraceRaysIndirect, enabled when present) and subgroup ballots in compute
    /// shaders.
    std::string wavefrontShortfall() const;

    /// Index of a memory type allowed by `typeBits` with all of `required`. Throws rt::DeviceError if none.
    std::uint32_t findMemoryType(std::uint32_t typeBits, VkMemoryPropertyFlags required) const;
    /// The same, empty when there is none.
    std::optional<std::uint32_t> tryFindMemoryType(std::uint32_t typeBits, VkMemoryPropertyFlags required) const;

private:
    void destroy();

    VkDevice m_device = VK_NULL_HANDLE;
    VkPhysicalDevice m_physical = VK_NULL_HANDLE;
    VkQueue m_queue = VK_NULL_HANDLE;
    std::uint32_t m_queueFamily = 0;
    DeviceProperties m_properties;
    bool m_shaderClock = false;
    bool m_traceRaysIndirect = false;
};
} // namespace rt::vk
