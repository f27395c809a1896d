#include "App/Gui/RasterPreview.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "App/Gui/PreviewMesh.h"
#include "Shared/HostDevice.h"
#include "Vulkan/GraphicsPipeline.h"
#include "Vulkan/UploadBatch.h"

namespace rt::gpu::gui
{
namespace
{
// Fine enough that a sphere's silhouette reads as round at the preview's sizes, small for 1000 spheres.
constexpr int kSphereSlices = 24;
constexpr int kSphereStacks = 12;

vk::Pipeline createPreviewPipeline(const vk::Device& device, const std::filesystem::path& shaderDir,
                                   const vk::PipelineLayout& layout, VkRenderPass renderPass)
{
    vk::GraphicsPipelineDesc desc;
    desc.vertexShader = shaderDir / "Window" / "Preview.vert.spv";
    desc.fragmentShader = shaderDir / "Window" / "Preview.frag.spv";
    desc.layout = layout.Handle();
    desc.renderPass = renderPass;
    desc.vertexBindings = {{0, sizeof(PreviewVertex), VK_VERTEX_INPUT_RATE_VERTEX},
                           {1, sizeof(PreviewInstance), VK_VERTEX_INPUT_RATE_INSTANCE}};
    desc.vertexAttributes = {
        {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(PreviewVertex, position)},
        {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(PreviewVertex, normal)},
        {2, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(PreviewVertex, color)},
        {3, 1, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(PreviewInstance, sphere)},
        {4, 1, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(PreviewInstance, color)},
    };
    desc.depthTest = true;
    return vk::createGraphicsPipeline(device, desc);
}

template <typename T>
vk::Buffer vertexBuffer(vk::UploadBatch& batch, const std::vector<T>& data)
{
    return batch.buffer(data, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
}
} // namespace

mat4 clipFromWorld(const CameraDesc& camera, float aspect, const Aabb& sceneBounds)
{
    // Depth range from the farthest corner of the scene: near at 1e-4 of it keeps float depth precise enough.
    float farthest = 1.0f;
    if (!sceneBounds.empty())
        for (int corner = 0; corner < 8; ++corner)
        {
            const vec3 p((corner & 1) ? sceneBounds.max.x : sceneBounds.min.x,
                         (corner & 2) ? sceneBounds.max.y : sceneBounds.min.y,
                         (corner & 4) ? sceneBounds.max.z : sceneBounds.min.z);
            farthest = std::max(farthest, glm::length(p - camera.lookFrom));
        }
    const float far = 1.01f * farthest;
    const float near = 1e-4f * far;
    mat4 projection = glm::perspectiveRH_ZO(radians(camera.vfovDegrees), aspect, near, far);
    projection[1][1] = -projection[1][1]; // Vulkan's clip space has y down
    return projection * glm::lookAtRH(camera.lookFrom, camera.lookAt, camera.vup);
}

RasterPreview::RasterPreview(const vk::Device& device, const std::filesystem::path& shaderDir, VkRenderPass renderPass)
    : m_device(&device),
      m_layout(device, std::vector<VkDescriptorSetLayout>{}, sizeof(shader::PreviewPushConstants),
               VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT),
      m_pipeline(createPreviewPipeline(device, shaderDir, m_layout, renderPass))
{
}

void RasterPreview::setScene(const Scene& scene, const vk::CommandPool& pool)
{
    const PreviewGeometry geometry = buildPreviewGeometry(scene);
    vk::UploadBatch batch(*m_device);
    if (m_sphereMesh.Handle() == VK_NULL_HANDLE) // the same for every scene: uploaded with the first
    {
        const std::vector<PreviewVertex> sphere = unitSphereMesh(kSphereSlices, kSphereStacks);
        const std::vector<PreviewInstance> identity{{vec4(0.0f, 0.0f, 0.0f, 1.0f), vec4(1.0f)}};
        m_sphereMesh = vertexBuffer(batch, sphere);
        m_identity = vertexBuffer(batch, identity);
        m_sphereMeshVertices = static_cast<std::uint32_t>(sphere.size());
    }
    m_triangles = vertexBuffer(batch, geometry.triangles);
    m_spheres = vertexBuffer(batch, geometry.spheres);
    batch.submit(pool, VK_PIPELINE_STAGE_VERTEX_INPUT_BIT, VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT);
    m_triangleVertices = static_cast<std::uint32_t>(geometry.triangles.size());
    m_sphereCount = static_cast<std::uint32_t>(geometry.spheres.size());
    m_bounds = scene.bounds();
}

void RasterPreview::record(VkCommandBuffer cmd, const CameraDesc& camera, const PixelRect& rect, float aspect,
                           bool encodeSrgb) const
{
    if (rect.empty())
        return;
    const VkViewport viewport{float(rect.x), float(rect.y), float(rect.width), float(rect.height), 0.0f, 1.0f};
    const VkRect2D scissor{{rect.x, rect.y}, {std::uint32_t(rect.width), std::uint32_t(rect.height)}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, m_pipeline.Handle());
    shader::PreviewPushConstants push{};
    push.clipFromWorld = clipFromWorld(camera, aspect, m_bounds);
    push.eye = camera.lookFrom;
    push.encodeSrgb = encodeSrgb ? 1u : 0u;
    vkCmdPushConstants(cmd, m_layout.Handle(), VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                       sizeof(push), &push);
    const VkDeviceSize offset = 0;
    const auto draw = [&](const vk::Buffer& vertices, std::uint32_t vertexCount, const vk::Buffer& instances,
                          std::uint32_t instanceCount) {
        if (vertexCount == 0 || instanceCount == 0)
            return;
        const VkBuffer buffers[] = {vertices.Handle(), instances.Handle()};
        const VkDeviceSize offsets[] = {offset, offset};
        vkCmdBindVertexBuffers(cmd, 0, 2, buffers, offsets);
        vkCmdDraw(cmd, vertexCount, instanceCount, 0, 0);
    };
    draw(m_triangles, m_triangleVertices, m_identity, 1);
    draw(m_sphereMesh, m_sphereMeshVertices, m_spheres, m_sphereCount);
}
} // namespace rt::gpu::gui
