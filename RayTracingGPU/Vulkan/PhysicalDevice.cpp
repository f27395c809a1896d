#include "Vulkan/PhysicalDevice.h"

#include <algorithm>
#include <optional>

#include "Vulkan/Check.h"

namespace rt::vk
{
namespace
{
DeviceType toDeviceType(VkPhysicalDeviceType type)
{
    switch (type)
    {
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return DeviceType::IntegratedGpu;
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return DeviceType::DiscreteGpu;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return DeviceType::VirtualGpu;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return DeviceType::Cpu;
    default: return DeviceType::Other;
    }
}

std::vector<std::string> extensionNames(VkPhysicalDevice device)
{
    std::uint32_t count = 0;
    check(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr), "vkEnumerateDeviceExtensionProperties");
    std::vector<VkExtensionProperties> properties(count);
    check(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, properties.data()),
          "vkEnumerateDeviceExtensionProperties");
    std::vector<std::string> names;
    for (const VkExtensionProperties& p : properties)
        names.emplace_back(p.extensionName);
    return names;
}

DeviceFeatures queryFeatures(VkPhysicalDevice device, std::uint32_t apiVersion, const std::vector<std::string>& extensions)
{
    DeviceFeatures f;
    // Vulkan12Features may only be chained on a 1.2 device; an older one lacks everything anyway.
    if (apiVersion < VK_API_VERSION_1_2)
        return f;
    VkPhysicalDeviceAccelerationStructureFeaturesKHR as{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
    VkPhysicalDeviceRayTracingPipelineFeaturesKHR rt{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
    VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceShaderClockFeaturesKHR clock{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_CLOCK_FEATURES_KHR};
    const auto has = [&](const char* name) {
        return std::find(extensions.begin(), extensions.end(), name) != extensions.end();
    };
    // Extension feature structs may only be chained when the device has the extension.
    void* chain = &v12;
    if (has(VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME))
    {
        as.pNext = chain;
        chain = &as;
    }
    if (has(VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME))
    {
        rt.pNext = chain;
        chain = &rt;
    }
    if (has(kShaderClockExtension))
    {
        clock.pNext = chain;
        chain = &clock;
    }
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    features.pNext = chain;
    vkGetPhysicalDeviceFeatures2(device, &features);
    f.accelerationStructure = as.accelerationStructure;
    f.rayTracingPipeline = rt.rayTracingPipeline;
    f.rayTracingPipelineTraceRaysIndirect = rt.rayTracingPipelineTraceRaysIndirect;
    f.bufferDeviceAddress = v12.bufferDeviceAddress;
    f.runtimeDescriptorArray = v12.runtimeDescriptorArray;
    f.shaderSampledImageArrayNonUniformIndexing = v12.shaderSampledImageArrayNonUniformIndexing;
    f.descriptorBindingPartiallyBound = v12.descriptorBindingPartiallyBound;
    f.descriptorBindingVariableDescriptorCount = v12.descriptorBindingVariableDescriptorCount;
    f.scalarBlockLayout = v12.scalarBlockLayout;
    f.shaderSubgroupClock = clock.shaderSubgroupClock;
    return f;
}

struct QueueChoice
{
    std::optional<std::uint32_t> family;
    bool presents = false; // the family does graphics, compute and presentation to the surface
};

/// A compute-capable family, preferring graphics + compute (the "universal" queue every driver optimises) and,
/// with a surface, one of those that can also present to it.
QueueChoice pickQueueFamily(VkPhysicalDevice device, VkSurfaceKHR surface)
{
    std::uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    std::optional<std::uint32_t> universal;
    std::optional<std::uint32_t> computeOnly;
    for (std::uint32_t i = 0; i < count; ++i)
    {
        if (!(families[i].queueFlags & VK_QUEUE_COMPUTE_BIT))
            continue;
        if (!(families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT))
        {
            computeOnly = computeOnly.value_or(i);
            continue;
        }
        VkBool32 presents = VK_FALSE;
        if (surface != VK_NULL_HANDLE &&
            vkGetPhysicalDeviceSurfaceSupportKHR(device, i, surface, &presents) == VK_SUCCESS && presents)
            return {i, true};
        universal = universal.value_or(i);
    }
    return {universal ? universal : computeOnly, false};
}
} // namespace

std::vector<PhysicalDevice> enumeratePhysicalDevices(VkInstance instance, VkSurfaceKHR surface)
{
    std::uint32_t count = 0;
    check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> handles(count);
    check(vkEnumeratePhysicalDevices(instance, &count, handles.data()), "vkEnumeratePhysicalDevices");

    std::vector<PhysicalDevice> devices;
    for (std::uint32_t i = 0; i < count; ++i)
    {
        VkPhysicalDeviceProperties properties;
        vkGetPhysicalDeviceProperties(handles[i], &properties);
        PhysicalDevice d;
        d.handle = handles[i];
        d.candidate.index = i;
        d.candidate.name = properties.deviceName;
        d.candidate.type = toDeviceType(properties.deviceType);
        d.candidate.apiVersion = properties.apiVersion;
        d.candidate.extensions = extensionNames(handles[i]);
        d.candidate.features = queryFeatures(handles[i], properties.apiVersion, d.candidate.extensions);
        const QueueChoice queue = pickQueueFamily(handles[i], surface);
        d.candidate.computeQueue = queue.family.has_value();
        d.candidate.presentQueue = queue.presents;
        d.queueFamily = queue.family.value_or(0);
        devices.push_back(std::move(d));
    }
    return devices;
}

DeviceProperties queryProperties(const PhysicalDevice& device)
{
    DeviceProperties p;
    VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
    VkPhysicalDeviceMaintenance3Properties maintenance3{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
    maintenance3.pNext = &subgroup;
    p.rayTracing.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR;
    p.rayTracing.pNext = &maintenance3;
    p.accelerationStructure.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR;
    p.accelerationStructure.pNext = &p.rayTracing;
    VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    properties.pNext = &p.accelerationStructure;
    vkGetPhysicalDeviceProperties2(device.handle, &properties);
    p.accelerationStructure.pNext = nullptr;
    p.rayTracing.pNext = nullptr;

    p.name = properties.properties.deviceName;
    p.type = toDeviceType(properties.properties.deviceType);
    p.limits = properties.properties.limits;
    p.maxMemoryAllocationSize = maintenance3.maxMemoryAllocationSize;
    p.subgroupBallotInCompute = (subgroup.supportedStages & VK_SHADER_STAGE_COMPUTE_BIT) &&
                                (subgroup.supportedOperations & VK_SUBGROUP_FEATURE_BALLOT_BIT);

    vkGetPhysicalDeviceMemoryProperties(device.handle, &p.memory);
    for (std::uint32_t i = 0; i < p.memory.memoryHeapCount; ++i)
        if (p.memory.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            p.deviceLocalHeapSize = std::max(p.deviceLocalHeapSize, p.memory.memoryHeaps[i].size);

    std::uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device.handle, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device.handle, &count, families.data());
    p.timestampValidBits = families.at(device.queueFamily).timestampValidBits;
    return p;
}
} // namespace rt::vk
