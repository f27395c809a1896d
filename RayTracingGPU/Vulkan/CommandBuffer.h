// A primary command buffer, and the record-submit-wait helper used for uploads, builds and dispatches.
#pragma once

#include <functional>

#include "Vulkan/CommandPool.h"

namespace rt::vk
{
class CommandBuffer final
{
public:
    CommandBuffer() = default;
    CommandBuffer(const Device& device, const CommandPool& pool);
    ~CommandBuffer();
    CommandBuffer(const CommandBuffer&) = delete;
    CommandBuffer& operator=(const CommandBuffer&) = delete;
    CommandBuffer(CommandBuffer&& other) noexcept;
    CommandBuffer& operator=(CommandBuffer&& other) noexcept;

    VkCommandBuffer Handle() const { return m_buffer; }

private:
    void free();

    VkDevice m_device = VK_NULL_HANDLE;
    VkCommandPool m_pool = VK_NULL_HANDLE;
    VkCommandBuffer m_buffer = VK_NULL_HANDLE;
};

/// Records `record` into a fresh one-time command buffer, submits it to the device's queue and waits for it.
/// Throws rt::DeviceError when submission or the wait fails (e.g. the device is lost).
void submitAndWait(const Device& device, const CommandPool& pool, const std::function<void(VkCommandBuffer)>& record);
} // namespace rt::vk
