#include "Vulkan/UploadBatch.h"

#include <cstring>

#include "Vulkan/Barriers.h"
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

void UploadBatch::submit(const CommandPool& pool, VkPipelineStageFlags readers, VkAccessFlags readAccess)
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
            imageBarrier(cmd, c.destination,
                         {VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
                          0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT});
            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.imageExtent = {c.extent.width, c.extent.height, 1};
            vkCmdCopyBufferToImage(cmd, c.source, c.destination, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
            imageBarrier(cmd, c.destination,
                         {VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                          VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_SHADER_READ_BIT});
        }
        memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, readers, readAccess);
    });
    m_staging.clear();
    m_bufferCopies.clear();
    m_imageCopies.clear();
}
} // namespace rt::vk
