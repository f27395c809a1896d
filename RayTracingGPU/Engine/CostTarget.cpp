#include "Engine/CostTarget.h"

#include <cstring>

#include "Check.h"
#include "Shared/HostDevice.h"
#include "Vulkan/Barriers.h"
#include "Vulkan/CommandBuffer.h"

namespace rt::gpu
{
void writeCostSet(const vk::Device& device, VkDescriptorSet set, VkImageView image, VkBuffer stats)
{
    const VkDescriptorImageInfo imageInfo{VK_NULL_HANDLE, image, VK_IMAGE_LAYOUT_GENERAL};
    const VkDescriptorBufferInfo bufferInfo{stats, 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet writes[2]{};
    for (VkWriteDescriptorSet& w : writes)
    {
        w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        w.dstSet = set;
        w.descriptorCount = 1;
    }
    writes[0].dstBinding = shader::kBindingCost;
    writes[0].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    writes[0].pImageInfo = &imageInfo;
    writes[1].dstBinding = shader::kBindingCostStats;
    writes[1].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[1].pBufferInfo = &bufferInfo;
    vkUpdateDescriptorSets(device.Handle(), 2, writes, 0, nullptr);
}

CostTarget::CostTarget(const vk::Device& device, const std::filesystem::path& shaderDir, Specialize specialize,
                       std::uint32_t width, std::uint32_t height)
    : m_pipeline(device, shaderDir, RayGenVariant::Cost, specialize),
      m_image(device, {width, height}, VK_FORMAT_R32_SFLOAT,
              VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT),
      m_view(device, m_image),
      m_stats(device, sizeof(shader::CostStats), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Readback),
      m_pool(device, m_pipeline.costBindings(), 0)
{
    RT_CHECK(device.shaderClock());
    std::memset(m_stats.mapped(), 0, sizeof(shader::CostStats));
    m_set = m_pool.allocate(m_pipeline.costSetLayout(), 0);
    writeCostSet(device, m_set, m_view.Handle(), m_stats.Handle());
}

void CostTarget::recordClear(VkCommandBuffer cmd) const
{
    vk::imageBarrier(cmd, m_image.Handle(),
                     {VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                      VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT});
    const VkClearColorValue zero{};
    vkCmdClearColorImage(cmd, m_image.Handle(), VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &vk::kColorRange);
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
}

std::vector<float> CostTarget::readTicks(const vk::Device& device, const vk::CommandPool& pool) const
{
    const VkExtent2D size = m_image.extent();
    const std::size_t pixels = std::size_t(size.width) * size.height;
    const vk::Buffer readback(device, VkDeviceSize(sizeof(float)) * pixels, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                              vk::MemoryUse::Readback);
    vk::submitAndWait(device, pool, [&](VkCommandBuffer cmd) {
        vk::recordImageReadback(cmd, m_image.Handle(), size, readback.Handle(), VK_IMAGE_LAYOUT_GENERAL,
                                VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_SHADER_WRITE_BIT,
                                VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR,
                                VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    });
    std::vector<float> ticks(pixels);
    std::memcpy(ticks.data(), readback.mapped(), sizeof(float) * pixels);
    return ticks;
}
} // namespace rt::gpu
