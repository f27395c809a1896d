#include "Vulkan/UploadBatch.h"

#include <cstring>

#include "Vulkan/CommandBuffer.h"

namespace rt::vk
{
const Buffer& UploadBatch::stage(const void* data, VkDeviceSize size)
{
    m_staging.emplace_back(*m_device, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Upload);
    if (size > 0)
        std::memcpy(m_staging.back().mapped(), data, static_cast<std::size_t>(size));
    return m_staging.back();
}

Buffer UploadBatch::buffer(const void* data, VkDeviceSize size, VkBufferUsageFlags usage)
{
    Buffer destination(*m_device, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::DeviceLocal);
    if (size > 0)
        m_bufferCopies.push_back({stage(data, size).Handle(), destination.Handle(), size});
    return destination;
}

void UploadBatch::image(const Image& image, const void* texels, VkDeviceSize size)
{
    m_imageCopies.push_back({stage(texels, size).Handle(), image.Handle(), image.extent()});
}

void UploadBatch::submit(const CommandPool& pool)
{
    if (m_bufferCopies.empty() && m_imageCopies.empty())
        return;
    submitAndWait(*m_device, pool, [&](VkCommandBuffer cmd) {
        for (const BufferCopy& c : m_bufferCopies)
        {
            const VkBufferCopy region{0, 0, c.size};
            vkCmdCopyBuffer(cmd, c.source, c.destination, 1, &region);
        }
        for (const ImageCopy& c : m_imageCopies)
        {
            VkImageMemoryBarrier toTransfer{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
            toTransfer.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
            toTransfer.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
            toTransfer.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
            toTransfer.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            toTransfer.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            toTransfer.image = c.destination;
            toTransfer.subresourceRange = kColorRange;
            vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr,
                                 0, nullptr, 1, &toTransfer);
            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.imageExtent = {c.extent.width, c.extent.height, 1};
            vkCmdCopyBufferToImage(cmd, c.source, c.destination, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
            VkImageMemoryBarrier toShader = toTransfer;
            toShader.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
            toShader.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
            toShader.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
            toShader.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
            vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, 0, 0,
                                 nullptr, 0, nullptr, 1, &toShader);
        }
        // Buffers feed acceleration-structure builds and shaders.
        VkMemoryBarrier done{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        done.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        done.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                             VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR |
                                 VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                             0, 1, &done, 0, nullptr, 0, nullptr);
    });
    m_staging.clear();
    m_bufferCopies.clear();
    m_imageCopies.clear();
}
} // namespace rt::vk
