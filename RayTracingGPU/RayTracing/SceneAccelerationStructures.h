// The BLASes and the TLAS of a SceneLayout, built on the device in one submission (all BLASes at once, each
// with its own region of one scratch buffer, then the TLAS). Built for fast tracing, not compacted.
#pragma once

#include <vector>

#include "RayTracing/SceneLayout.h"
#include "RayTracing/AccelerationStructure.h"
#include "Vulkan/CommandPool.h"

namespace rt::gpu
{
/// Device addresses of the SceneLayout arrays the builds read (buffers with
/// ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY and SHADER_DEVICE_ADDRESS usage).
struct GeometryAddresses
{
    VkDeviceAddress positions = 0;
    VkDeviceAddress triangles = 0;
    VkDeviceAddress aabbs = 0;
};

struct SceneAccelerationStructures
{
    std::vector<AccelerationStructure> blases; // index = SceneLayout::blases index
    vk::Buffer instances; // VkAccelerationStructureInstanceKHR[], read by the TLAS build
    AccelerationStructure tlas;
};

/// Builds everything and waits for it. Throws rt::DeviceError when the scene exceeds a device limit
/// (maxPrimitiveCount, maxInstanceCount) or the build fails.
SceneAccelerationStructures buildAccelerationStructures(const vk::Device& device, const vk::CommandPool& pool,
                                                        const SceneLayout& layout, const GeometryAddresses& geometry);
} // namespace rt::gpu
