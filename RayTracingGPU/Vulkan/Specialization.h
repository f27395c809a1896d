// VkSpecializationInfo over an array of 32-bit constants: constant id i takes values[i]. The values must
// outlive the info (it points into them).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "Vulkan/Loader.h"

namespace rt::vk
{
class Specialization final
{
public:
    explicit Specialization(std::span<const std::uint32_t> values)
    {
        for (std::uint32_t id = 0; id < values.size(); ++id)
            m_entries.push_back({id, static_cast<std::uint32_t>(id * sizeof(std::uint32_t)), sizeof(std::uint32_t)});
        m_info.mapEntryCount = static_cast<std::uint32_t>(m_entries.size());
        m_info.pMapEntries = m_entries.data();
        m_info.dataSize = values.size_bytes();
        m_info.pData = values.data();
    }
    Specialization(const Specialization&) = delete;
    Specialization& operator=(const Specialization&) = delete;

    /// Null when there are no values.
    const VkSpecializationInfo* info() const { return m_entries.empty() ? nullptr : &m_info; }

private:
    std::vector<VkSpecializationMapEntry> m_entries;
    VkSpecializationInfo m_info{};
};
} // namespace rt::vk
