// Host data to device-local buffers and images through staging buffers, all copies in one submission.
#pragma once

#include <vector>

#include "Vulkan/Buffer.h"
#include "Vulkan/CommandPool.h"
#include "Vulkan/Image.h"

namespace rt::vk
{
class UploadBatch final
{
public:
    explicit UploadBatch(const Device& device) : m_device(&device) {}
    UploadBatch(const UploadBatch&) = delete;
    UploadBatch& operator=(const UploadBatch&) = delete;

    /// A device-local buffer of `size` bytes (TRANSFER_DST added to `usage`) that holds `data` once submit()
    /// has run. `data` is copied into staging memory now and may go away.
    Buffer buffer(const void* data, VkDeviceSize size, VkBufferUsageFlags usage);

    template <typename T>
    Buffer buffer(const std::vector<T>& data, VkBufferUsageFlags usage)
    {
        return buffer(data.data(), data.size() * sizeof(T), usage);
    }

    /// Fills `image` (fresh, layout UNDEFINED, TRANSFER_DST usage) with tightly packed texels and leaves it in
    /// SHADER_READ_ONLY_OPTIMAL for the ray-tracing stages once submit() has run.
    void image(const Image& image, const void* texels, VkDeviceSize size);

    /// Records every copy into one command buffer, submits it and waits; the staging memory is released.
    /// The buffers are made visible to `readers` / `readAccess` (default: the ray-tracing shaders and
    /// acceleration-structure builds).
    void submit(const CommandPool& pool,
                VkPipelineStageFlags readers = VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR |
                                               VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                VkAccessFlags readAccess = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR);

private:
    struct BufferCopy
    {
        VkBuffer source;
        VkBuffer destination;
        VkDeviceSize size;
    };
    struct ImageCopy
    {
        VkBuffer source;
        VkImage destination;
        VkExtent2D extent;
    };

    const Buffer& stage(const void* data, VkDeviceSize size);

    const Device* m_device;
    std::vector<Buffer> m_staging;
    std::vector<BufferCopy> m_bufferCopies;
    std::vector<ImageCopy> m_imageCopies;
};
} // namespace rt::vk
