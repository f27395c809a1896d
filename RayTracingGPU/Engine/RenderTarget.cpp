#include "Engine/RenderTarget.h"

#include <algorithm>
#include <cstring>

#include "Engine/RenderLimits.h"

namespace rt::gpu
{
RenderTarget::RenderTarget(const vk::Device& device, std::uint32_t width, std::uint32_t height)
    : m_image(device, {width, height}, VK_FORMAT_R32G32B32A32_SFLOAT,
              VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT),
      m_view(device, m_image),
      m_readback(device, kAccumulationBytesPerPixel * width * height, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                 vk::MemoryUse::Readback),
      m_uniforms(device, sizeof(shader::RenderUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, vk::MemoryUse::Upload),
      m_counters(device, sizeof(shader::SampleCounters), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Readback)
{
}

void RenderTarget::reset(const shader::RenderUniforms& uniforms)
{
    std::memcpy(m_uniforms.mapped(), &uniforms, sizeof(uniforms));
    std::memset(m_counters.mapped(), 0, sizeof(shader::SampleCounters));
}

shader::SampleCounters RenderTarget::readCounters() const
{
    shader::SampleCounters counters;
    std::memcpy(&counters, m_counters.mapped(), sizeof(counters));
    return counters;
}

void RenderTarget::recordClear(VkCommandBuffer cmd) const
{
    VkImageMemoryBarrier toGeneral{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    toGeneral.srcAccessMask = 0;
    toGeneral.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toGeneral.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    toGeneral.newLayout = VK_IMAGE_LAYOUT_GENERAL;
    toGeneral.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toGeneral.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toGeneral.image = m_image.Handle();
    toGeneral.subresourceRange = vk::kColorRange;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                         nullptr, 1, &toGeneral);
    const VkClearColorValue zero{};
    vkCmdClearColorImage(cmd, m_image.Handle(), VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &vk::kColorRange);
    VkImageMemoryBarrier cleared = toGeneral;
    cleared.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    cleared.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    cleared.oldLayout = VK_IMAGE_LAYOUT_GENERAL;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, 0, 0,
                         nullptr, 0, nullptr, 1, &cleared);
}

void RenderTarget::recordReadback(VkCommandBuffer cmd) const
{
    VkImageMemoryBarrier toSource{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    toSource.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    toSource.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    toSource.oldLayout = VK_IMAGE_LAYOUT_GENERAL;
    toSource.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    toSource.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toSource.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toSource.image = m_image.Handle();
    toSource.subresourceRange = vk::kColorRange;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
                         nullptr, 0, nullptr, 1, &toSource);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {width(), height(), 1};
    vkCmdCopyImageToBuffer(cmd, m_image.Handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, m_readback.Handle(), 1,
                           &region);
    // Back to GENERAL for the next dispatch's storage-image writes, after the copy has read the image.
    VkImageMemoryBarrier toGeneral = toSource;
    toGeneral.srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    toGeneral.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    toGeneral.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    toGeneral.newLayout = VK_IMAGE_LAYOUT_GENERAL;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, 0, 0,
                         nullptr, 0, nullptr, 1, &toGeneral);
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr,
                         0, nullptr);
}

Image RenderTarget::readEstimate(std::uint32_t samples) const
{
    Image image(static_cast<int>(width()), static_cast<int>(height()));
    const auto* texels = static_cast<const float*>(m_readback.mapped());
    const float count = static_cast<float>(std::max<std::uint32_t>(samples, 1));
    for (std::size_t i = 0; i < image.pixelCount(); ++i)
        image.data()[i] = vec3(texels[4 * i], texels[4 * i + 1], texels[4 * i + 2]) / count;
    return image;
}
} // namespace rt::gpu
