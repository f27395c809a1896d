#include "Vulkan/QueryPool.h"

#include "Vulkan/Check.h"

namespace rt::vk
{
QueryPool::QueryPool(const Device& device, std::uint32_t timestampCount)
{
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = timestampCount;
    VkQueryPool pool = VK_NULL_HANDLE;
    check(vkCreateQueryPool(device.Handle(), &info, nullptr, &pool), "vkCreateQueryPool");
    m_pool = DeviceHandle<VkQueryPool, &vkDestroyQueryPool>(device.Handle(), pool);
}

double QueryPool::secondsBetween(std::uint32_t first, float nanosecondsPerTick) const
{
    std::uint64_t ticks[2] = {0, 0};
    check(vkGetQueryPoolResults(m_pool.device(), m_pool.get(), first, 2, sizeof(ticks), ticks, sizeof(std::uint64_t),
                                VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
          "vkGetQueryPoolResults");
    return ticks[1] >= ticks[0] ? double(ticks[1] - ticks[0]) * double(nanosecondsPerTick) * 1e-9 : 0.0;
}

std::vector<std::uint64_t> QueryPool::ticks(std::uint32_t first, std::uint32_t count) const
{
    std::vector<std::uint64_t> ticks(count);
    if (count > 0)
        check(vkGetQueryPoolResults(m_pool.device(), m_pool.get(), first, count, ticks.size() * sizeof(std::uint64_t),
                                    ticks.data(), sizeof(std::uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
              "vkGetQueryPoolResults");
    return ticks;
}
} // namespace rt::vk
