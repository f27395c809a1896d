// A Common scene on the device: the storage buffers of HostDevice.h's bindings, the scene's images as
// sampled sRGB textures, and the BLASes and TLAS built from them (SceneLayout describes the mapping).
#pragma once

#include <cstdint>
#include <vector>

#include "RayTracing/SceneLayout.h"
#include "RayTracing/SceneAccelerationStructures.h"
#include "Scene/Scene.h"
#include "Vulkan/Buffer.h"
#include "Vulkan/CommandPool.h"
#include "Vulkan/Image.h"
#include "Vulkan/Sampler.h"

namespace rt::gpu
{
class GpuScene final
{
public:
    /// Uploads `scene` (validated) and builds its acceleration structures; waits for the device.
    /// `maxImages` is the size of the pipeline's sampler array. Throws rt::DeviceError when the scene exceeds
    /// a device limit, rt::SceneError when it cannot be laid out.
    GpuScene(const vk::Device& device, const vk::CommandPool& pool, const Scene& scene, std::uint32_t maxImages);
    GpuScene(const GpuScene&) = delete;
    GpuScene& operator=(const GpuScene&) = delete;
    ~GpuScene() = default;

    /// Host seconds of the BLAS and TLAS builds (uploads excluded).
    double buildSeconds() const { return m_buildSeconds; }
    /// Samples one launch may loop over: any number, except with moving spheres, whose intersection shader
    /// recomputes the ray's shutter time from push.firstSample and so needs one sample per launch.
    std::uint32_t samplesPerLaunch() const { return m_samplesPerLaunch; }

    struct Buffers
    {
        vk::Buffer materials, textures, lights, lightAlias, lightBvh, lightBvhLeaves, perlin, records, primitiveLights, positions, uvs, triangles,
            triangleMaterials, spheres, media, aabbs;
    };
    const Buffers& buffers() const { return m_buffers; }
    VkAccelerationStructureKHR tlas() const { return m_accelerationStructures.tlas.Handle(); }
    /// One view per scene image, at least one (a white texel when the scene has none).
    const std::vector<vk::ImageView>& imageViews() const { return m_views; }
    VkSampler sampler() const { return m_sampler.Handle(); }

private:
    Buffers m_buffers;
    std::vector<vk::Image> m_images;
    std::vector<vk::ImageView> m_views;
    vk::Sampler m_sampler;
    SceneAccelerationStructures m_accelerationStructures;
    std::uint32_t m_samplesPerLaunch = 1;
    double m_buildSeconds = 0.0;
};
} // namespace rt::gpu
