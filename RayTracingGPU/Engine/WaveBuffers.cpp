#include "Engine/WaveBuffers.h"

#include <algorithm>
#include <cstring>

#include "Shared/HostDevice.h"
#include "Vulkan/Barriers.h"

namespace rt::gpu
{
namespace
{
constexpr std::uint64_t kPathBytes = shader::kWaveFieldCount * 16; // a uvec4 per field
} // namespace

std::uint32_t waveCapacityFor(bool cpuDevice, std::uint64_t deviceLocalBytes)
{
    if (cpuDevice)
        return std::uint32_t(1) << 16;
    // A sixteenth of the device's memory at most: the scene and the images keep the rest. Each wave ends with
    // launches over its last few long paths (about 25 us each on an H100 at depth 50), so fewer, larger waves
    // are faster: 16 M paths (then the engine's paths per batch) rendered book 2's BSDF sampling of
    // cornell-box-lights 1.19x faster than 4 M there (129 against 153 ms).
    std::uint32_t capacity = std::uint32_t(1) << 24;
    while (capacity > (1u << 16) && std::uint64_t(capacity) * kPathBytes > deviceLocalBytes / 16)
        capacity /= 2;
    return capacity;
}

WaveBuffers::WaveBuffers(const vk::Device& device, std::uint32_t capacity)
    : m_capacity(std::max(capacity, 1u)),
      m_paths(device, VkDeviceSize(m_capacity) * kPathBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
              vk::MemoryUse::DeviceLocal),
      m_queues(device, VkDeviceSize(m_capacity) * shader::kWaveQueueCount * sizeof(std::uint32_t),
               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::DeviceLocal),
      m_counters(device, sizeof(shader::WaveCounters),
                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                     VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                     VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                 vk::MemoryUse::DeviceLocal),
      m_countersReadback(device, sizeof(shader::WaveCounters), VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUse::Readback)
{
}

void WaveBuffers::recordCountersReadback(VkCommandBuffer cmd) const
{
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR,
                      VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    const VkBufferCopy region{0, 0, sizeof(shader::WaveCounters)};
    vkCmdCopyBuffer(cmd, m_counters.Handle(), m_countersReadback.Handle(), 1, &region);
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                      VK_ACCESS_HOST_READ_BIT);
}

shader::WaveCounters WaveBuffers::readCounters() const
{
    shader::WaveCounters c;
    std::memcpy(&c, m_countersReadback.mapped(), sizeof(c));
    return c;
}
} // namespace rt::gpu
