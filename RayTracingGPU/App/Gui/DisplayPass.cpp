#include "App/Gui/DisplayPass.h"

#include <cstdint>
#include <vector>

#include "Vulkan/GraphicsPipeline.h"

namespace rt::gpu::gui
{
namespace
{
const std::vector<vk::DescriptorBinding>& displayBindings()
{
    static const std::vector<vk::DescriptorBinding> bindings = {
        {shader::kDisplayBindingAccumulation, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_FRAGMENT_BIT},
        {shader::kDisplayBindingCost, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_FRAGMENT_BIT},
    };
    return bindings;
}

vk::Pipeline createDisplayPipeline(const vk::Device& device, const std::filesystem::path& shaderDir,
                                   const vk::PipelineLayout& layout, VkRenderPass renderPass)
{
    vk::GraphicsPipelineDesc desc;
    desc.vertexShader = shaderDir / "Window" / "Display.vert.spv";
    desc.fragmentShader = shaderDir / "Window" / "Display.frag.spv";
    desc.layout = layout.Handle();
    desc.renderPass = renderPass;
    return vk::createGraphicsPipeline(device, desc);
}
} // namespace

DisplayPass::DisplayPass(const vk::Device& device, const std::filesystem::path& shaderDir, VkRenderPass renderPass)
    : m_device(&device), m_setLayout(device, displayBindings()),
      m_layout(device, m_setLayout, sizeof(shader::DisplayPushConstants), VK_SHADER_STAGE_FRAGMENT_BIT),
      m_pipeline(createDisplayPipeline(device, shaderDir, m_layout, renderPass)),
      m_pool(device, displayBindings(), 0), m_set(m_pool.allocate(m_setLayout, 0))
{
}

void DisplayPass::setImages(VkImageView accumulation, VkImageView cost) const
{
    const VkDescriptorImageInfo images[2] = {{VK_NULL_HANDLE, accumulation, VK_IMAGE_LAYOUT_GENERAL},
                                             {VK_NULL_HANDLE, cost, VK_IMAGE_LAYOUT_GENERAL}};
    VkWriteDescriptorSet writes[2]{};
    for (int i = 0; i < 2; ++i)
    {
        writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        writes[i].dstSet = m_set;
        writes[i].dstBinding = i == 0 ? shader::kDisplayBindingAccumulation : shader::kDisplayBindingCost;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
        writes[i].pImageInfo = &images[i];
    }
    vkUpdateDescriptorSets(m_device->Handle(), 2, writes, 0, nullptr);
}

void DisplayPass::record(VkCommandBuffer cmd, const PixelRect& rect, Extent image,
                         shader::DisplayPushConstants push) const
{
    if (rect.empty() || image.width <= 0 || image.height <= 0)
        return;
    push.imageOrigin = shader::vec2(float(rect.x), float(rect.y));
    push.texelsPerPixel = shader::vec2(float(image.width) / float(rect.width), float(image.height) / float(rect.height));
    const VkViewport viewport{float(rect.x), float(rect.y), float(rect.width), float(rect.height), 0.0f, 1.0f};
    const VkRect2D scissor{{rect.x, rect.y}, {std::uint32_t(rect.width), std::uint32_t(rect.height)}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, m_pipeline.Handle());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, m_layout.Handle(), 0, 1, &m_set, 0, nullptr);
    vkCmdPushConstants(cmd, m_layout.Handle(), VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(push), &push);
    vkCmdDraw(cmd, 3, 1, 0, 0);
}
} // namespace rt::gpu::gui
