#include "Engine/GpuScene.h"

#include <algorithm>
#include <chrono>
#include <limits>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "Error.h"
#include "Sampling/LightBvh.h"
#include "Sampling/LightPower.h"
#include "Scene/Perlin.h"
#include "Scene/SceneFeatures.h"
#include "Vulkan/UploadBatch.h"

namespace rt::gpu
{
namespace
{
using Clock = std::chrono::steady_clock;

constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
// Arrays that acceleration-structure builds read as well as shaders.
constexpr VkBufferUsageFlags kBuildInput = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                           VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                                           VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

void checkImageLimits(const vk::Device& device, const Scene& scene, std::uint32_t maxImages)
{
    const auto& p = device.properties();
    if (scene.images.size() > maxImages)
        throw DeviceError(fmt::format("scene '{}' has {} images; the GPU engine binds at most {} on device '{}'",
                                      scene.id, scene.images.size(), maxImages, p.name));
    for (const ImageData& image : scene.images)
        if (std::uint32_t(image.width) > p.limits.maxImageDimension2D ||
            std::uint32_t(image.height) > p.limits.maxImageDimension2D)
            throw DeviceError(fmt::format("texture '{}' is {}x{}, beyond maxImageDimension2D {} of device '{}'",
                                          image.path, image.width, image.height, p.limits.maxImageDimension2D,
                                          p.name));
}
std::uint64_t tracedPrimitivesOf(const SceneLayout& layout)
{
    std::uint64_t n = 0;
    for (const TlasInstanceDesc& instance : layout.instances)
    {
        const BlasDesc& blas = layout.blases[instance.blas];
        n += std::uint64_t(blas.triangleCount) + blas.sphereCount + blas.mediumCount;
    }
    return n;
}

/// The uniform block of kBindingMixtureLights: the scene's first kMixtureUniformLights lights, zeros after them
/// (the block's whole declared size is bound).
std::vector<LightData> mixtureLightsOf(const Scene& scene)
{
    std::vector<LightData> lights(shader::kMixtureUniformLights, LightData{});
    std::copy_n(scene.lights.begin(), std::min<std::size_t>(scene.lights.size(), lights.size()), lights.begin());
    return lights;
}
/// What the pipelines need of `scene`: its features walked once (meshes' materials and bounds included).
PipelineScene pipelineSceneOf(const Scene& scene, const SceneLayout& layout)
{
    const SceneFeatures features = featuresOf(scene);
    return {featureBitsOf(scene, features, layout.hitGroups), features.hugeSpheres, layout.hitGroups,
            tracedPrimitivesOf(layout)};
}
} // namespace

GpuScene::GpuScene(const vk::Device& device, const vk::CommandPool& pool, const Scene& scene,
                   const SceneLayout& layout, std::uint32_t maxImages, std::unique_ptr<GpuGeometry> previous)
    : m_pipelineScene{pipelineSceneOf(scene, layout)},
      m_samplesPerLaunch(scene.hasMotion() ? 1u : std::numeric_limits<std::uint32_t>::max())
{
    checkImageLimits(device, scene, maxImages);
    const GeometryFingerprint fingerprint = fingerprintOf(layout);
    const bool keepBlases = previous && previous->fingerprint.blases == fingerprint.blases;

    const Clock::time_point uploadStart = Clock::now();
    vk::UploadBatch upload(device);
    m_buffers.materials = upload.buffer(scene.materials, kStorage);
    m_buffers.textures = upload.buffer(scene.textures, kStorage);
    m_buffers.lights = upload.buffer(scene.lights, kStorage);
    m_buffers.mixtureLights = upload.buffer(mixtureLightsOf(scene), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    m_buffers.lightAlias = upload.buffer(lightAliasTable(scene), kStorage);
    const LightBvh lightBvh = buildLightBvh(scene);
    m_buffers.lightBvh = upload.buffer(lightBvh.nodes, kStorage);
    m_buffers.lightBvhLeaves = upload.buffer(lightBvh.leaves, kStorage);
    m_buffers.perlin = upload.buffer(&perlinTables(), sizeof(shader::PerlinData), kStorage);
    m_buffers.records = upload.buffer(layout.records, kStorage);
    m_buffers.primitiveLights = upload.buffer(layout.primitiveLights, kStorage);
    m_buffers.uvs = upload.buffer(layout.uvs, kStorage);
    m_buffers.triangleMaterials = upload.buffer(layout.triangleMaterials, kStorage);
    m_buffers.spheres = upload.buffer(layout.spheres, kStorage);
    m_buffers.media = upload.buffer(layout.media, kStorage);
    if (keepBlases)
        m_geometry = std::move(previous);
    else
    {
        previous.reset(); // its memory goes before the new geometry's comes
        m_geometry = std::make_unique<GpuGeometry>();
        m_geometry->positions = upload.buffer(layout.positions, kBuildInput);
        m_geometry->triangles = upload.buffer(layout.triangles, kBuildInput);
        m_geometry->aabbs = upload.buffer(layout.aabbs, kBuildInput);
    }

    // Only the scene's own images: without image textures nothing is bound (PathTracingPipeline).
    if (!scene.images.empty())
        m_sampler = vk::Sampler(device);
    for (const ImageData& image : scene.images)
    {
        const VkExtent2D extent{std::uint32_t(image.width), std::uint32_t(image.height)};
        m_images.emplace_back(device, extent, VK_FORMAT_R8G8B8A8_UNORM, // sRGB texels, decoded in ImageTexture.glsl
                              VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
        upload.image(m_images.back(), image.rgba.data(), image.rgba.size());
        m_views.emplace_back(device, m_images.back());
    }
    upload.submit(pool);
    m_uploadSeconds = secondsSince(uploadStart);

    const Clock::time_point buildStart = Clock::now();
    if (!keepBlases)
    {
        m_geometry->structures = buildAccelerationStructures(
            device, pool, layout,
            {m_geometry->positions.address(), m_geometry->triangles.address(), m_geometry->aabbs.address()},
            &m_buildTimes);
        m_reuse = GeometryReuse::Built;
    }
    else if (m_geometry->fingerprint.tlas != fingerprint.tlas)
    {
        rebuildTlas(device, pool, layout, m_geometry->structures, &m_buildTimes);
        m_reuse = GeometryReuse::TlasRebuilt;
    }
    else
        m_reuse = GeometryReuse::Reused;
    m_geometry->fingerprint = fingerprint;
    m_buildSeconds = m_reuse == GeometryReuse::Reused ? 0.0 : secondsSince(buildStart);
    spdlog::debug("scene '{}' on the device: acceleration structures {}", scene.id,
                  m_reuse == GeometryReuse::Built         ? "built"
                  : m_reuse == GeometryReuse::TlasRebuilt ? "kept (BLASes; TLAS rebuilt)"
                                                          : "kept");
}
} // namespace rt::gpu
