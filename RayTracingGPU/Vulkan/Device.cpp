#include "Vulkan/Device.h"

#include <atomic>
#include <utility>

#include <spdlog/fmt/fmt.h>

#include "Error.h"
#include "Vulkan/Check.h"

namespace rt::vk
{
namespace
{
// The device-level function pointers (Loader.h) belong to one device: a second live device would call
// through the first one's pointers, which breaks as soon as the two come from different drivers.
std::atomic<int> g_liveDevices{0};
} // namespace

Device::Device(const PhysicalDevice& physical, bool presentation)
    : m_physical(physical.handle), m_queueFamily(physical.queueFamily), m_properties(queryProperties(physical)),
      m_shaderClock(physical.candidate.features.shaderSubgroupClock),
      m_traceRaysIndirect(physical.candidate.features.rayTracingPipelineTraceRaysIndirect)
{
    if (g_liveDevices.load() > 0)
        throw DeviceError("a Vulkan device already exists in this process; the engine drives one device at a time");
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = m_queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;

    // Exactly the features of kRequiredFeatures, nothing the engine does not use.
    VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    v12.bufferDeviceAddress = VK_TRUE;
    v12.runtimeDescriptorArray = VK_TRUE;
    v12.shaderSampledImageArrayNonUniformIndexing = VK_TRUE;
    v12.descriptorBindingPartiallyBound = VK_TRUE;
    v12.descriptorBindingVariableDescriptorCount = VK_TRUE;
    v12.scalarBlockLayout = VK_TRUE;
    VkPhysicalDeviceAccelerationStructureFeaturesKHR as{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
    as.accelerationStructure = VK_TRUE;
    as.pNext = &v12;
    VkPhysicalDeviceRayTracingPipelineFeaturesKHR rt{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
    rt.rayTracingPipeline = VK_TRUE;
    rt.rayTracingPipelineTraceRaysIndirect = m_traceRaysIndirect ? VK_TRUE : VK_FALSE;
    rt.pNext = &as;
    VkPhysicalDeviceShaderClockFeaturesKHR clock{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_CLOCK_FEATURES_KHR};
    clock.shaderSubgroupClock = VK_TRUE;
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    features.pNext = &rt;
    std::vector<const char*> extensions(std::begin(kRequiredExtensions), std::end(kRequiredExtensions));
    if (presentation)
        extensions.push_back(kPresentationExtension);
    if (m_shaderClock)
    {
        extensions.push_back(kShaderClockExtension);
        clock.pNext = features.pNext;
        features.pNext = &clock;
    }

    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.pNext = &features;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queueInfo;
    info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    check(vkCreateDevice(physical.handle, &info, nullptr, &m_device), "vkCreateDevice");
    ++g_liveDevices;
    loadDeviceFunctions(m_device);
    vkGetDeviceQueue(m_device, m_queueFamily, 0, &m_queue);
}

Device::~Device() { destroy(); }

std::string Device::wavefrontShortfall() const
{
    std::string missing;
    if (!m_traceRaysIndirect)
        missing = "feature VkPhysicalDeviceRayTracingPipelineFeaturesKHR::rayTracingPipelineTraceRaysIndirect";
    if (!m_properties.subgroupBallotInCompute)
        missing += std::string(missing.empty() ? "" : ", ") + "subgroup ballot operations in compute shaders";
    return missing;
}

Device::Device(Device&& other) noexcept
    : m_device(std::exchange(other.m_device, VK_NULL_HANDLE)), m_physical(other.m_physical),
      m_queue(std::exchange(other.m_queue, VK_NULL_HANDLE)), m_queueFamily(other.m_queueFamily),
      m_properties(other.m_properties), m_shaderClock(other.m_shaderClock),
      m_traceRaysIndirect(other.m_traceRaysIndirect)
{
}

Device& Device::operator=(Device&& other) noexcept
{
    if (this != &other)
    {
        destroy();
        m_device = std::exchange(other.m_device, VK_NULL_HANDLE);
        m_physical = other.m_physical;
        m_queue = std::exchange(other.m_queue, VK_NULL_HANDLE);
        m_queueFamily = other.m_queueFamily;
        m_properties = other.m_properties;
        m_shaderClock = other.m_shaderClock;
        m_traceRaysIndirect = other.m_traceRaysIndirect;
    }
    return *this;
}

void Device::destroy()
{
    if (m_device != VK_NULL_HANDLE)
    {
        vkDeviceWaitIdle(m_device);
        vkDestroyDevice(m_device, nullptr);
        --g_liveDevices;
    }
    m_device = VK_NULL_HANDLE;
}

std::optional<std::uint32_t> Device::tryFindMemoryType(std::uint32_t typeBits, VkMemoryPropertyFlags required) const
{
    const VkPhysicalDeviceMemoryProperties& memory = m_properties.memory;
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & required) == required)
            return i;
    return std::nullopt;
}

std::uint32_t Device::findMemoryType(std::uint32_t typeBits, VkMemoryPropertyFlags required) const
{
    if (const auto type = tryFindMemoryType(typeBits, required))
        return *type;
    throw DeviceError(fmt::format("device '{}' has no memory type with properties 0x{:x} for this resource",
                                  m_properties.name, required));
}
} // namespace rt::vk
