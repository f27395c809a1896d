#include "Vulkan/PipelineLayout.h"

#include "Vulkan/Check.h"

namespace rt::vk
{
PipelineLayout::PipelineLayout(const Device& device, const DescriptorSetLayout& setLayout,
                               std::uint32_t pushConstantBytes, VkShaderStageFlags stages)
    : PipelineLayout(device, std::vector<VkDescriptorSetLayout>{setLayout.Handle()}, pushConstantBytes, stages)
{
}

PipelineLayout::PipelineLayout(const Device& device, const std::vector<VkDescriptorSetLayout>& setLayouts,
                               std::uint32_t pushConstantBytes, VkShaderStageFlags stages)
{
    const VkPushConstantRange range{stages, 0, pushConstantBytes};
    VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    info.setLayoutCount = static_cast<std::uint32_t>(setLayouts.size());
    info.pSetLayouts = setLayouts.data();
    info.pushConstantRangeCount = pushConstantBytes > 0 ? 1 : 0;
    info.pPushConstantRanges = &range;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    check(vkCreatePipelineLayout(device.Handle(), &info, nullptr, &layout), "vkCreatePipelineLayout");
    m_layout = DeviceHandle<VkPipelineLayout, &vkDestroyPipelineLayout>(device.Handle(), layout);
}
} // namespace rt::vk
