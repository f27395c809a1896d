// The shader binding table: raygen, miss and hit-group records laid out with the device's queried handle
// size, handle alignment and base alignment (32/16/32 on lavapipe, 32/32/64 on NVIDIA: never assumed).
// The records hold only handles: per-instance data is found through instanceCustomIndex, not the SBT. Hit
// record i holds the handle of whichever pipeline group the scene's HitGroupLayout puts there
// (hitRecordGroups), so a pipeline with more groups than the scene needs (the general one) serves it too.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "Vulkan/Buffer.h"

namespace rt::gpu
{
/// Where each region starts (from an aligned base) and its stride and size, in bytes.
struct SbtLayout
{
    struct Region
    {
        VkDeviceSize offset = 0;
        VkDeviceSize stride = 0;
        VkDeviceSize size = 0;
    };
    Region raygen;
    Region miss;
    Region hit;
    VkDeviceSize totalSize = 0;
};

/// Pure layout arithmetic (Vulkan spec, "Shader Binding Table"): region starts aligned to `baseAlignment`,
/// strides to `handleAlignment`, the raygen region's size equal to its stride.
SbtLayout computeSbtLayout(std::uint32_t handleSize, std::uint32_t handleAlignment, std::uint32_t baseAlignment,
                           std::uint32_t missCount, std::uint32_t hitCount);

/// Which shader group's handle goes where, from the aligned base: the layout and one (offset, group) per record.
struct SbtPlan
{
    struct Copy
    {
        VkDeviceSize offset = 0;
        std::uint32_t group = 0; // the pipeline's shader group index
    };
    SbtLayout layout;
    std::vector<Copy> copies;
};

/// Raygen is group `rayGenGroup`, miss record i group 1 + i, hit record i group hitRecordGroups[i]. Pure.
SbtPlan planSbt(std::uint32_t handleSize, std::uint32_t handleAlignment, std::uint32_t baseAlignment,
                std::uint32_t missCount, std::span<const std::uint32_t> hitRecordGroups,
                std::uint32_t rayGenGroup = 0);

class ShaderBindingTable final
{
public:
    ShaderBindingTable() = default;
    /// Fetches the handles of `pipeline`'s `groupCount` groups (raygen first, then the `missCount` miss groups)
    /// and writes them into a new buffer as planSbt places them: the raygen record gets group `rayGenGroup`
    /// (a pipeline may have a second raygen), hit record i group hitRecordGroups[i].
    ShaderBindingTable(const vk::Device& device, VkPipeline pipeline, std::uint32_t groupCount,
                       std::uint32_t missCount, std::span<const std::uint32_t> hitRecordGroups,
                       std::uint32_t rayGenGroup = 0);
    ShaderBindingTable(const ShaderBindingTable&) = delete;
    ShaderBindingTable& operator=(const ShaderBindingTable&) = delete;
    ShaderBindingTable(ShaderBindingTable&&) noexcept = default;
    ShaderBindingTable& operator=(ShaderBindingTable&&) noexcept = default;
    ~ShaderBindingTable() = default;

    VkBuffer Handle() const { return m_buffer.Handle(); }
    const VkStridedDeviceAddressRegionKHR& raygen() const { return m_raygen; }
    const VkStridedDeviceAddressRegionKHR& miss() const { return m_miss; }
    const VkStridedDeviceAddressRegionKHR& hit() const { return m_hit; }
    const VkStridedDeviceAddressRegionKHR& callable() const { return m_callable; }

private:
    vk::Buffer m_buffer;
    VkStridedDeviceAddressRegionKHR m_raygen{};
    VkStridedDeviceAddressRegionKHR m_miss{};
    VkStridedDeviceAddressRegionKHR m_hit{};
    VkStridedDeviceAddressRegionKHR m_callable{}; // none
};
} // namespace rt::gpu
