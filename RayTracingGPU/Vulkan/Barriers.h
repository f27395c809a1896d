// The pipeline barriers the engine records, one call each: a global memory barrier, a layout transition of
// a colour image, and the copy of a colour image into a host-visible buffer.
#pragma once

#include "Vulkan/Loader.h"

namespace rt::vk
{
/// Makes `srcAccess` by `srcStages` available, and visible to `dstAccess` by `dstStages`.
void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags srcStages, VkAccessFlags srcAccess,
                   VkPipelineStageFlags dstStages, VkAccessFlags dstAccess);

struct ImageTransition
{
    VkImageLayout oldLayout;
    VkImageLayout newLayout;
    VkPipelineStageFlags srcStages;
    VkAccessFlags srcAccess;
    VkPipelineStageFlags dstStages;
    VkAccessFlags dstAccess;
};

/// Moves the colour image (one mip level, one layer) from `t.oldLayout` to `t.newLayout`.
void imageBarrier(VkCommandBuffer cmd, VkImage image, const ImageTransition& t);

/// Copies the colour image, in `layout` and last written by `srcStages` / `srcAccess`, into `buffer` (texels
/// tightly packed), returns it to `layout` for `dstStages` / `dstAccess`, and makes the copy visible to the
/// host. Reading the buffer after the submission's fence is then safe.
void recordImageReadback(VkCommandBuffer cmd, VkImage image, VkExtent2D extent, VkBuffer buffer, VkImageLayout layout,
                         VkPipelineStageFlags srcStages, VkAccessFlags srcAccess, VkPipelineStageFlags dstStages,
                         VkAccessFlags dstAccess);
} // namespace rt::vk
