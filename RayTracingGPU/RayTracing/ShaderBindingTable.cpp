#include "RayTracing/ShaderBindingTable.h"

#include <cstring>
#include <vector>

#include "Check.h"
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

SbtPlan planSbt(std::uint32_t handleSize, std::uint32_t handleAlignment, std::uint32_t baseAlignment,
                std::uint32_t missCount, std::span<const std::uint32_t> hitRecordGroups, std::uint32_t rayGenGroup)
{
    const auto hitCount = static_cast<std::uint32_t>(hitRecordGroups.size());
    SbtPlan plan{computeSbtLayout(handleSize, handleAlignment, baseAlignment, missCount, hitCount), {}};
    plan.copies.push_back({plan.layout.raygen.offset, rayGenGroup});
    for (std::uint32_t i = 0; i < missCount; ++i)
        plan.copies.push_back({plan.layout.miss.offset + i * plan.layout.miss.stride, 1 + i});
    for (std::uint32_t i = 0; i < hitCount; ++i)
        plan.copies.push_back({plan.layout.hit.offset + i * plan.layout.hit.stride, hitRecordGroups[i]});
    return plan;
}

ShaderBindingTable::ShaderBindingTable(const vk::Device& device, VkPipeline pipeline, std::uint32_t groupCount,
                                       std::uint32_t missCount, std::span<const std::uint32_t> hitRecordGroups,
                                       std::uint32_t rayGenGroup)
{
    const auto& properties = device.properties().rayTracing;
    const std::uint32_t handleSize = properties.shaderGroupHandleSize;
    const std::uint32_t baseAlignment = properties.shaderGroupBaseAlignment;
    const SbtPlan plan =
        planSbt(handleSize, properties.shaderGroupHandleAlignment, baseAlignment, missCount, hitRecordGroups,
                rayGenGroup);
    const SbtLayout& layout = plan.layout;

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
    for (const SbtPlan::Copy& c : plan.copies)
    {
        RT_CHECK_LT(c.group, groupCount);
        std::memcpy(bytes + c.offset, handles.data() + std::size_t(c.group) * handleSize, handleSize);
    }

    m_raygen = {base + layout.raygen.offset, layout.raygen.stride, layout.raygen.size};
    m_miss = {base + layout.miss.offset, layout.miss.stride, layout.miss.size};
    // A scene without geometry has no hit record: an empty region (size 0) is what Vulkan asks for then.
    if (!hitRecordGroups.empty())
        m_hit = {base + layout.hit.offset, layout.hit.stride, layout.hit.size};
}
} // namespace rt::gpu
