// "Ray tracing off" in the window: the scene rasterised with the same camera (PreviewMesh.h geometry,
// Preview.vert/.frag, depth-tested), drawn into the window's render pass. Fast on any device, so the camera can
// be placed before tracing.
#pragma once

#include <cstdint>
#include <filesystem>

#include "App/Gui/WindowLayout.h"
#include "Math/Aabb.h"
#include "Scene/Scene.h"
#include "Vulkan/Buffer.h"
#include "Vulkan/CommandPool.h"
#include "Vulkan/Pipeline.h"
#include "Vulkan/PipelineLayout.h"

namespace rt::gpu::gui
{
class RasterPreview final
{
public:
    /// The pipeline for subpass 0 of `renderPass` (a colour and a depth attachment).
    RasterPreview(const vk::Device& device, const std::filesystem::path& shaderDir, VkRenderPass renderPass);
    RasterPreview(const RasterPreview&) = delete;
    RasterPreview& operator=(const RasterPreview&) = delete;
    ~RasterPreview() = default;

    /// Uploads `scene`'s preview geometry (waits for the upload; nothing may be drawing the previous one).
    void setScene(const Scene& scene, const vk::CommandPool& pool);

    /// Records the draws inside the render pass into `rect` of the framebuffer (the image's rectangle), seen
    /// by `camera` with the image's `aspect` (width / height). Nothing for an empty rectangle.
    void record(VkCommandBuffer cmd, const CameraDesc& camera, const PixelRect& rect, float aspect,
                bool encodeSrgb) const;

private:
    const vk::Device* m_device;
    vk::PipelineLayout m_layout;
    vk::Pipeline m_pipeline;
    vk::Buffer m_sphereMesh;
    vk::Buffer m_identity; // the one instance the triangles are drawn with
    vk::Buffer m_triangles;
    vk::Buffer m_spheres;
    std::uint32_t m_sphereMeshVertices = 0;
    std::uint32_t m_triangleVertices = 0;
    std::uint32_t m_sphereCount = 0;
    Aabb m_bounds;
};

/// Vulkan clip space (y down, depth 0 at `near`, 1 at `far`) from world space for `camera` and an image of
/// `aspect` = width / height. `near` and `far` enclose `sceneBounds` as seen from the camera.
mat4 clipFromWorld(const CameraDesc& camera, float aspect, const Aabb& sceneBounds);
} // namespace rt::gpu::gui
