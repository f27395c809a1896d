#include "RayTracing/ShaderBindingTable.h"

#include <cstring>
#include <vector>

#include "Vulkan/Check.h"

namespace rt::gpu
{
using vk::alignUp;

SbtLayout computeSbtLayout(std::uint32_t handleSize, std::uint32_t handleAlignment, std::uint32_t baseAlignment,
                           std::uint32_t missCount, std::uint32_t hitCount)
{
    SbtLayout l;
    const VkDeviceSize stride = alignUp(handleSize, handleAlignment);
    l.raygen.stride = alignUp(handleSize, baseAlignment);
    l.raygen.size = l.raygen.stride;
    l.miss.offset = alignUp(l.raygen.offset + l.raygen.size, baseAlignment);
    l.miss.stride = stride;
    l.miss.size = alignUp(missCount * stride, baseAlignment);
    l.hit.offset = alignUp(l.miss.offset + l.miss.size, baseAlignment);
    l.hit.stride = stride;
    l.hit.size = alignUp(hitCount * stride, baseAlignment);
    l.totalSize = l.hit.offset + l.hit.size;
    return l;
}

ShaderBindingTable::ShaderBindingTable(const vk::Device& device, VkPipeline pipeline, std::uint32_t missCount,
                                       std::uint32_t hitCount)
{
    const auto& properties = device.properties().rayTracing;
    const std::uint32_t handleSize = properties.shaderGroupHandleSize;
    const std::uint32_t baseAlignment = properties.shaderGroupBaseAlignment;
    const SbtLayout layout =
        computeSbtLayout(handleSize, properties.shaderGroupHandleAlignment, baseAlignment, missCount, hitCount);

    const std::uint32_t groupCount = 1 + missCount + hitCount;
    std::vector<std::uint8_t> handles(std::size_t(groupCount) * handleSize);
    vk::check(vkGetRayTracingShaderGroupHandlesKHR(device.Handle(), pipeline, 0, groupCount, handles.size(),
                                                   handles.data()),
              "vkGetRayTracingShaderGroupHandlesKHR");

    // The buffer's own alignment may be below shaderGroupBaseAlignment: over-allocate and align the base.
    m_buffer = vk::Buffer(device, layout.totalSize + baseAlignment,
                          VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                          vk::MemoryUse::Upload);
    const VkDeviceAddress address = m_buffer.address();
    const VkDeviceAddress base = alignUp(address, baseAlignment);
    auto* bytes = static_cast<std::uint8_t*>(m_buffer.mapped()) + (base - address);
    std::memset(bytes, 0, layout.totalSize);

    const auto copyHandle = [&](std::uint32_t group, VkDeviceSize offset) {
        std::memcpy(bytes + offset, handles.data() + std::size_t(group) * handleSize, handleSize);
    };
    copyHandle(0, layout.raygen.offset);
    for (std::uint32_t i = 0; i < missCount; ++i)
        copyHandle(1 + i, layout.miss.offset + i * layout.miss.stride);
    for (std::uint32_t i = 0; i < hitCount; ++i)
        copyHandle(1 + missCount + i, layout.hit.offset + i * layout.hit.stride);

    m_raygen = {base + layout.raygen.offset, layout.raygen.stride, layout.raygen.size};
    m_miss = {base + layout.miss.offset, layout.miss.stride, layout.miss.size};
    m_hit = {base + layout.hit.offset, layout.hit.stride, layout.hit.size};
}
} // namespace rt::gpu
