// Enumerating physical devices into DeviceCandidates, and the properties of the chosen one that the engine
// must query rather than assume (SBT handle size and alignments, limits, memory heaps, timestamps).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "Vulkan/DeviceSelection.h"
#include "Vulkan/Loader.h"

namespace rt::vk
{
struct PhysicalDevice
{
    VkPhysicalDevice handle = VK_NULL_HANDLE;
    DeviceCandidate candidate;
    std::uint32_t queueFamily = 0; // compute-capable, preferring one that also does graphics (and presents)
};

/// Every physical device as a candidate. With a `surface` (window mode), each candidate says whether one of
/// its queue families does graphics, compute and presentation to it, and prefers that family.
std::vector<PhysicalDevice> enumeratePhysicalDevices(VkInstance instance, VkSurfaceKHR surface = VK_NULL_HANDLE);

struct DeviceProperties
{
    std::string name;
    DeviceType type = DeviceType::Other;
    VkPhysicalDeviceLimits limits{};
    VkPhysicalDeviceRayTracingPipelinePropertiesKHR rayTracing{};
    VkPhysicalDeviceAccelerationStructurePropertiesKHR accelerationStructure{};
    VkPhysicalDeviceMemoryProperties memory{};
    VkDeviceSize maxMemoryAllocationSize = 0; // VkPhysicalDeviceMaintenance3Properties
    VkDeviceSize deviceLocalHeapSize = 0; // the largest DEVICE_LOCAL heap
    std::uint32_t timestampValidBits = 0; // of the queue family in use; 0: no timestamps
    bool subgroupBallotInCompute = false; // VkPhysicalDeviceSubgroupProperties: ballot ops in compute shaders
};

DeviceProperties queryProperties(const PhysicalDevice& device);
} // namespace rt::vk
