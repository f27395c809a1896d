#include "Vulkan/CommandBuffer.h"

#include <utility>

#include "Vulkan/Check.h"
#include "Vulkan/Fence.h"

namespace rt::vk
{
CommandBuffer::CommandBuffer(const Device& device, const CommandPool& pool)
    : m_device(device.Handle()), m_pool(pool.Handle())
{
    VkCommandBufferAllocateInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    info.commandPool = m_pool;
    info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    info.commandBufferCount = 1;
    check(vkAllocateCommandBuffers(m_device, &info, &m_buffer), "vkAllocateCommandBuffers");
}

CommandBuffer::~CommandBuffer() { free(); }

CommandBuffer::CommandBuffer(CommandBuffer&& other) noexcept
    : m_device(std::exchange(other.m_device, VK_NULL_HANDLE)), m_pool(std::exchange(other.m_pool, VK_NULL_HANDLE)),
      m_buffer(std::exchange(other.m_buffer, VK_NULL_HANDLE))
{
}

CommandBuffer& CommandBuffer::operator=(CommandBuffer&& other) noexcept
{
    if (this != &other)
    {
        free();
        m_device = std::exchange(other.m_device, VK_NULL_HANDLE);
        m_pool = std::exchange(other.m_pool, VK_NULL_HANDLE);
        m_buffer = std::exchange(other.m_buffer, VK_NULL_HANDLE);
    }
    return *this;
}

void CommandBuffer::free()
{
    if (m_buffer != VK_NULL_HANDLE)
        vkFreeCommandBuffers(m_device, m_pool, 1, &m_buffer);
    m_buffer = VK_NULL_HANDLE;
}

void submitAndWait(const Device& device, const CommandPool& pool, const std::function<void(VkCommandBuffer)>& record)
{
    const CommandBuffer commands(device, pool);
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(commands.Handle(), &begin), "vkBeginCommandBuffer");
    record(commands.Handle());
    check(vkEndCommandBuffer(commands.Handle()), "vkEndCommandBuffer");

    const Fence& fence = pool.submitFence();
    fence.reset();
    const VkCommandBuffer handle = commands.Handle();
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &handle;
    check(vkQueueSubmit(device.queue(), 1, &submit, fence.Handle()), "vkQueueSubmit");
    try
    {
        fence.wait();
    }
    catch (...)
    {
        // A wait that failed short of a lost device (out of host or device memory) leaves the submission pending:
        // its command buffer is freed on the way out and the pool's fence reset before the next submission, both
        // invalid while it is. The device idle first (an error there changes nothing of what is thrown).
        vkDeviceWaitIdle(device.Handle());
        throw;
    }
}
} // namespace rt::vk
