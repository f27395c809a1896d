#include "Engine/RestirBuffers.h"

#include <algorithm>

#include <spdlog/fmt/fmt.h>

#include "Vulkan/Device.h"

namespace rt::gpu
{
namespace
{
vk::Buffer storage(const vk::Device& device, std::uint64_t bytes)
{
    return vk::Buffer(device, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::DeviceLocal);
}
} // namespace

RestirBuffers::RestirBuffers(const vk::Device& device, std::uint64_t pixels)
    : m_pixels(std::max<std::uint64_t>(pixels, 1)), m_surfaces(storage(device, m_pixels * kSurfaceBytesPerPixel)),
      m_temporal(storage(device, m_pixels * sizeof(shader::Reservoir))),
      m_final(storage(device, m_pixels * sizeof(shader::Reservoir))),
      m_traced(storage(device, m_pixels * kTracedBytesPerPixel))
{
}

std::optional<std::string> RestirBuffers::tooLargeFor(const vk::Device& device, std::uint64_t pixels)
{
    const std::uint64_t range = device.properties().limits.maxStorageBufferRange;
    if (pixels * kSurfaceBytesPerPixel <= range)
        return std::nullopt;
    return fmt::format("restir-di's surfaces of {} pixels take {} MiB, more than one storage buffer of device '{}' "
                       "may bind (maxStorageBufferRange {} MiB): render fewer pixels",
                       pixels, pixels * kSurfaceBytesPerPixel >> 20, device.properties().name, range >> 20);
}

std::map<std::string, std::uint64_t> RestirBuffers::bytesPerPixel()
{
    return {{"reservoirs", kReservoirBytesPerPixel}, {"surfaces", kSurfaceBytesPerPixel + kTracedBytesPerPixel}};
}
} // namespace rt::gpu
