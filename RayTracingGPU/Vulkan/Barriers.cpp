#include "Vulkan/Barriers.h"

#include "Vulkan/Image.h"

namespace rt::vk
{
void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags srcStages, VkAccessFlags srcAccess,
                   VkPipelineStageFlags dstStages, VkAccessFlags dstAccess)
{
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = srcAccess;
    barrier.dstAccessMask = dstAccess;
    vkCmdPipelineBarrier(cmd, srcStages, dstStages, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

void imageBarrier(VkCommandBuffer cmd, VkImage image, const ImageTransition& t)
{
    VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    barrier.srcAccessMask = t.srcAccess;
    barrier.dstAccessMask = t.dstAccess;
    barrier.oldLayout = t.oldLayout;
    barrier.newLayout = t.newLayout;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = kColorRange;
    vkCmdPipelineBarrier(cmd, t.srcStages, t.dstStages, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

void recordImageReadback(VkCommandBuffer cmd, VkImage image, VkExtent2D extent, VkBuffer buffer, VkImageLayout layout,
                         VkPipelineStageFlags srcStages, VkAccessFlags srcAccess, VkPipelineStageFlags dstStages,
                         VkAccessFlags dstAccess)
{
    imageBarrier(cmd, image,
                 {layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, srcStages, srcAccess, VK_PIPELINE_STAGE_TRANSFER_BIT,
                  VK_ACCESS_TRANSFER_READ_BIT});
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent.width, extent.height, 1};
    vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1, &region);
    // The way back only waits for the copy's reads to finish: no memory to make visible.
    imageBarrier(cmd, image,
                 {VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, dstStages, dstAccess});
    memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                  VK_ACCESS_HOST_READ_BIT);
}
} // namespace rt::vk
