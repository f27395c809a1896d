#include "Vulkan/DescriptorSetLayout.h"

#include "Vulkan/Check.h"

namespace rt::vk
{
DescriptorSetLayout::DescriptorSetLayout(const Device& device, const std::vector<DescriptorBinding>& bindings)
{
    std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
    std::vector<VkDescriptorBindingFlags> flags;
    for (const DescriptorBinding& b : bindings)
    {
        layoutBindings.push_back({b.binding, b.type, b.count, b.stages, nullptr});
        flags.push_back(b.flags);
    }
    VkDescriptorSetLayoutBindingFlagsCreateInfo flagsInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_BINDING_FLAGS_CREATE_INFO};
    flagsInfo.bindingCount = static_cast<std::uint32_t>(flags.size());
    flagsInfo.pBindingFlags = flags.data();
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.pNext = &flagsInfo;
    info.bindingCount = static_cast<std::uint32_t>(layoutBindings.size());
    info.pBindings = layoutBindings.data();
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    check(vkCreateDescriptorSetLayout(device.Handle(), &info, nullptr, &layout), "vkCreateDescriptorSetLayout");
    m_layout = DeviceHandle<VkDescriptorSetLayout, &vkDestroyDescriptorSetLayout>(device.Handle(), layout);
}
} // namespace rt::vk
