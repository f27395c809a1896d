#pragma once

#include <vector>

#include "Vulkan/Device.h"
#include "Vulkan/DeviceHandle.h"

namespace rt::vk
{
/// One binding of a set layout; `flags` are VkDescriptorBindingFlags (partially bound, variable count).
struct DescriptorBinding
{
    std::uint32_t binding;
    VkDescriptorType type;
    std::uint32_t count;
    VkShaderStageFlags stages;
    VkDescriptorBindingFlags flags = 0;
};

class DescriptorSetLayout final
{
public:
    DescriptorSetLayout() = default;
    DescriptorSetLayout(const Device& device, const std::vector<DescriptorBinding>& bindings);
    RT_VK_MOVE_ONLY(DescriptorSetLayout)
    ~DescriptorSetLayout() = default;

    VkDescriptorSetLayout Handle() const { return m_layout.get(); }

private:
    DeviceHandle<VkDescriptorSetLayout, &vkDestroyDescriptorSetLayout> m_layout;
};
} // namespace rt::vk
