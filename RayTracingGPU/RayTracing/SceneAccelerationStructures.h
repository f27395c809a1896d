// The BLASes and the TLAS of a SceneLayout, built on the device in one submission (all BLASes at once, each
// with its own region of one scratch buffer, then the TLAS), or the TLAS alone over BLASes kept from the last
// scene (GeometryFingerprint). Built for fast tracing, not compacted.
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

/// The device's own time of the builds (timestamp queries); < 0 where not built or not timed.
struct AsBuildTimes
{
    double blasGpuSeconds = -1.0;
    double tlasGpuSeconds = -1.0;
};

/// Builds everything and waits for it, with its device times in `times` if given. Throws rt::DeviceError when
/// the scene exceeds a device limit (maxPrimitiveCount, maxInstanceCount) or the build fails.
SceneAccelerationStructures buildAccelerationStructures(const vk::Device& device, const vk::CommandPool& pool,
                                                        const SceneLayout& layout, const GeometryAddresses& geometry,
                                                        AsBuildTimes* times = nullptr);

/// Builds a new TLAS (and instance buffer) for the instances of `layout` over the BLASes of `structures`,
/// which must be those of `layout`'s BLAS descriptions (GeometryFingerprint::blases equal), and waits.
void rebuildTlas(const vk::Device& device, const vk::CommandPool& pool, const SceneLayout& layout,
                 SceneAccelerationStructures& structures, AsBuildTimes* times = nullptr);
} // namespace rt::gpu
