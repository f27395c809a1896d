// A pool of timestamp queries, read back as GPU seconds.
#pragma once

#include <cstdint>
#include <vector>

#include "Vulkan/Device.h"
#include "Vulkan/DeviceHandle.h"

namespace rt::vk
{
class QueryPool final
{
public:
    QueryPool() = default;
    QueryPool(const Device& device, std::uint32_t timestampCount);
    RT_VK_MOVE_ONLY(QueryPool)
    ~QueryPool() = default;

    VkQueryPool Handle() const { return m_pool.get(); }

    /// Seconds between timestamps `first` and `first + 1`, both written and finished.
    /// `nanosecondsPerTick` is VkPhysicalDeviceLimits::timestampPeriod.
    double secondsBetween(std::uint32_t first, float nanosecondsPerTick) const;
    /// The ticks of timestamps `first` .. `first + count - 1`, all written and finished.
    std::vector<std::uint64_t> ticks(std::uint32_t first, std::uint32_t count) const;

private:
    DeviceHandle<VkQueryPool, &vkDestroyQueryPool> m_pool;
};
} // namespace rt::vk
