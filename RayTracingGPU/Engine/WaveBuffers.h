// The wavefront integrator's memory (HostDevice.h kWave* fields, WaveCounters; Shaders/Wavefront/): the state of
// `capacity` paths, kWaveQueueCount queues of as many path indices, and the counters its indirect launches
// read. Bound at kBindingWavePaths, kBindingWaveQueues and kBindingWaveCounters of every descriptor set the
// tracer makes (a megakernel-only tracer binds buffers of one path).
#pragma once

#include <cstdint>

#include "Shared/HostDevice.h"
#include "Vulkan/Buffer.h"

namespace rt::gpu
{
/// Paths a wave holds on a device with `deviceLocalBytes` of device-local memory: 16 M (3 GiB) on a GPU with
/// 48 GiB or more, less on smaller ones, 64 K on a CPU device (lavapipe), where the kernels are short.
std::uint32_t waveCapacityFor(bool cpuDevice, std::uint64_t deviceLocalBytes);

class WaveBuffers final
{
public:
    /// Throws rt::DeviceError when the device cannot allocate them.
    WaveBuffers(const vk::Device& device, std::uint32_t capacity);
    WaveBuffers(WaveBuffers&&) noexcept = default;
    WaveBuffers& operator=(WaveBuffers&&) noexcept = default;

    std::uint32_t capacity() const { return m_capacity; }
    const vk::Buffer& paths() const { return m_paths; }
    const vk::Buffer& queues() const { return m_queues; }
    const vk::Buffer& counters() const { return m_counters; }

    /// Records the copy of the counters to the host (after the kernels' writes), for readCounters once the
    /// submission is done.
    void recordCountersReadback(VkCommandBuffer cmd) const;
    shader::WaveCounters readCounters() const;

private:
    std::uint32_t m_capacity;
    vk::Buffer m_paths;
    vk::Buffer m_queues;
    vk::Buffer m_counters;
    vk::Buffer m_countersReadback;
};
} // namespace rt::gpu
