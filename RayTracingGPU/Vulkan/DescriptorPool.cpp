#include "Vulkan/DescriptorPool.h"

#include <map>

#include "Vulkan/Check.h"

namespace rt::vk
{
DescriptorPool::DescriptorPool(const Device& device, const std::vector<DescriptorBinding>& bindings,
                               std::uint32_t variableCount)
{
    std::map<VkDescriptorType, std::uint32_t> counts;
    for (const DescriptorBinding& b : bindings)
        counts[b.type] += (b.flags & VK_DESCRIPTOR_BINDING_VARIABLE_DESCRIPTOR_COUNT_BIT) ? variableCount : b.count;
    std::vector<VkDescriptorPoolSize> sizes;
    for (const auto& [type, count] : counts)
        if (count > 0)
            sizes.push_back({type, count});
    VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    info.maxSets = 1;
    info.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
    info.pPoolSizes = sizes.data();
    VkDescriptorPool pool = VK_NULL_HANDLE;
    check(vkCreateDescriptorPool(device.Handle(), &info, nullptr, &pool), "vkCreateDescriptorPool");
    m_pool = DeviceHandle<VkDescriptorPool, &vkDestroyDescriptorPool>(device.Handle(), pool);
}

VkDescriptorSet DescriptorPool::allocate(const DescriptorSetLayout& layout, std::uint32_t variableCount) const
{
    VkDescriptorSetVariableDescriptorCountAllocateInfo variable{
        VK_STRUCTURE_TYPE_DESCRIPTOR_SET_VARIABLE_DESCRIPTOR_COUNT_ALLOCATE_INFO};
    variable.descriptorSetCount = 1;
    variable.pDescriptorCounts = &variableCount;
    const VkDescriptorSetLayout handle = layout.Handle();
    VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    info.pNext = &variable;
    info.descriptorPool = m_pool.get();
    info.descriptorSetCount = 1;
    info.pSetLayouts = &handle;
    VkDescriptorSet set = VK_NULL_HANDLE;
    check(vkAllocateDescriptorSets(m_pool.device(), &info, &set), "vkAllocateDescriptorSets");
    return set;
}
} // namespace rt::vk
