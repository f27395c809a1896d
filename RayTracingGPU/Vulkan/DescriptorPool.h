// A descriptor pool sized for one set of a given layout; the set is freed with the pool.
#pragma once

#include <vector>

#include "Vulkan/DescriptorSetLayout.h"

namespace rt::vk
{
class DescriptorPool final
{
public:
    DescriptorPool() = default;
    /// Room for one set with `bindings` (a variable-count binding counts `variableCount` descriptors).
    DescriptorPool(const Device& device, const std::vector<DescriptorBinding>& bindings, std::uint32_t variableCount);
    RT_VK_MOVE_ONLY(DescriptorPool)
    ~DescriptorPool() = default;

    VkDescriptorPool Handle() const { return m_pool.get(); }

    /// Allocates the one set, giving its variable-count binding `variableCount` descriptors.
    VkDescriptorSet allocate(const DescriptorSetLayout& layout, std::uint32_t variableCount) const;

private:
    DeviceHandle<VkDescriptorPool, &vkDestroyDescriptorPool> m_pool;
};
} // namespace rt::vk
