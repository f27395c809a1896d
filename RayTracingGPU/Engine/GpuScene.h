// A Common scene on the device: the storage buffers of HostDevice.h's bindings, the scene's images as
// sampled sRGB textures (none, and no sampler, for a scene without images), and the BLASes and TLAS built
// from them (SceneLayout describes the mapping). The geometry (the build inputs and the acceleration
// structures) may come from the scene before, when its GeometryFingerprint is the same: a scene that differs
// only in materials, textures or lights re-uploads those and builds nothing.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "Engine/PathTracingPipeline.h"
#include "RayTracing/GeometryFingerprint.h"
#include "RayTracing/SceneAccelerationStructures.h"
#include "RayTracing/SceneLayout.h"
#include "Scene/Scene.h"
#include "Vulkan/Buffer.h"
#include "Vulkan/CommandPool.h"
#include "Vulkan/Image.h"
#include "Vulkan/Sampler.h"

namespace rt::gpu
{
/// What the acceleration structures are built from and the structures themselves.
struct GpuGeometry
{
    vk::Buffer positions, triangles, aabbs; // build inputs; positions and triangles are read by the shaders too
    SceneAccelerationStructures structures;
    GeometryFingerprint fingerprint;
};

/// What a GpuScene did with the last scene's geometry.
enum class GeometryReuse
{
    Built, // BLASes and TLAS built anew
    TlasRebuilt, // the BLASes kept, the TLAS built anew (the instances changed)
    Reused // both kept
};

class GpuScene final
{
public:
    /// Uploads `scene` (validated, laid out as `layout`) and builds its acceleration structures, or takes the
    /// geometry in `previous` (GpuScene::releaseGeometry of the last scene, or null) where its fingerprint
    /// matches; waits for the device. `maxImages` is the size of the pipeline's sampler array. Throws
    /// rt::DeviceError when the scene exceeds a device limit.
    GpuScene(const vk::Device& device, const vk::CommandPool& pool, const Scene& scene, const SceneLayout& layout,
             std::uint32_t maxImages, std::unique_ptr<GpuGeometry> previous = nullptr);
    GpuScene(const GpuScene&) = delete;
    GpuScene& operator=(const GpuScene&) = delete;
    ~GpuScene() = default;

    /// Host seconds of the BLAS and TLAS builds (uploads excluded); 0 when the geometry was reused.
    double buildSeconds() const { return m_buildSeconds; }
    /// Host seconds of the uploads (buffers and images).
    double uploadSeconds() const { return m_uploadSeconds; }
    /// Device seconds of the builds (< 0: not built, or no timestamps).
    const AsBuildTimes& buildTimes() const { return m_buildTimes; }
    GeometryReuse geometryReuse() const { return m_reuse; }
    const GeometryFingerprint& fingerprint() const { return m_geometry->fingerprint; }
    /// Hands the geometry over to the next scene (this one cannot trace afterwards).
    std::unique_ptr<GpuGeometry> releaseGeometry() { return std::move(m_geometry); }

    /// Samples one launch may loop over: any number, except with moving spheres, whose intersection shader
    /// recomputes the ray's shutter time from push.firstSample and so needs one sample per launch.
    std::uint32_t samplesPerLaunch() const { return m_samplesPerLaunch; }
    /// The scene's features and hit records, for choosing and running a pipeline.
    const PipelineScene& pipelineScene() const { return m_pipelineScene; }

    struct Buffers
    {
        vk::Buffer materials, textures, lights, mixtureLights, lightAlias, lightBvh, lightBvhLeaves, perlin, records,
            primitiveLights, uvs, triangleMaterials, spheres, media;
    };
    const Buffers& buffers() const { return m_buffers; }
    const GpuGeometry& geometry() const { return *m_geometry; }
    VkAccelerationStructureKHR tlas() const { return m_geometry->structures.tlas.Handle(); }
    /// One view per scene image; none for a scene without images.
    const std::vector<vk::ImageView>& imageViews() const { return m_views; }
    /// The image sampler; VK_NULL_HANDLE without images.
    VkSampler sampler() const { return m_sampler.Handle(); }

private:
    Buffers m_buffers;
    std::vector<vk::Image> m_images;
    std::vector<vk::ImageView> m_views;
    vk::Sampler m_sampler;
    std::unique_ptr<GpuGeometry> m_geometry;
    PipelineScene m_pipelineScene;
    std::uint32_t m_samplesPerLaunch = 1;
    double m_buildSeconds = 0.0;
    double m_uploadSeconds = 0.0;
    AsBuildTimes m_buildTimes;
    GeometryReuse m_reuse = GeometryReuse::Built;
};
} // namespace rt::gpu
