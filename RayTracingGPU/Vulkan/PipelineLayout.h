#pragma once

#include <cstdint>
#include <vector>

#include "Vulkan/DescriptorSetLayout.h"

namespace rt::vk
{
/// Descriptor set layouts (set 0, 1, ...) and one push-constant range of `pushConstantBytes` (0: none) for
/// `stages`.
class PipelineLayout final
{
public:
    PipelineLayout() = default;
    PipelineLayout(const Device& device, const DescriptorSetLayout& setLayout, std::uint32_t pushConstantBytes,
                   VkShaderStageFlags stages);
    PipelineLayout(const Device& device, const std::vector<VkDescriptorSetLayout>& setLayouts,
                   std::uint32_t pushConstantBytes, VkShaderStageFlags stages);
    RT_VK_MOVE_ONLY(PipelineLayout)
    ~PipelineLayout() = default;

    VkPipelineLayout Handle() const { return m_layout.get(); }

private:
    DeviceHandle<VkPipelineLayout, &vkDestroyPipelineLayout> m_layout;
};
} // namespace rt::vk
