#include "ComputeKernel.h"

#include <cstring>

#include "Vulkan/Buffer.h"
#include "Vulkan/Check.h"
#include "Vulkan/CommandBuffer.h"
#include "Vulkan/DescriptorPool.h"
#include "Vulkan/Pipeline.h"
#include "Vulkan/PipelineLayout.h"
#include "Vulkan/ShaderModule.h"

namespace rt::gpu::test
{
std::vector<std::byte> runKernel(const GpuContext& context, const std::filesystem::path& spirv,
                                 const std::vector<KernelBuffer>& buffers, std::size_t resultBinding,
                                 const void* pushConstants, std::uint32_t pushBytes, std::uint32_t groupCount)
{
    const vk::Device& device = context.device();
    std::vector<vk::DescriptorBinding> bindings;
    std::vector<vk::Buffer> deviceBuffers;
    for (std::size_t i = 0; i < buffers.size(); ++i)
    {
        bindings.push_back({static_cast<std::uint32_t>(i), VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
                            VK_SHADER_STAGE_COMPUTE_BIT});
        deviceBuffers.emplace_back(device, buffers[i].bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Readback);
        if (buffers[i].data)
            std::memcpy(deviceBuffers.back().mapped(), buffers[i].data, buffers[i].bytes);
        else
            std::memset(deviceBuffers.back().mapped(), 0, buffers[i].bytes);
    }
    const vk::DescriptorSetLayout setLayout(device, bindings);
    const vk::PipelineLayout layout(device, setLayout, pushBytes, VK_SHADER_STAGE_COMPUTE_BIT);
    const vk::DescriptorPool pool(device, bindings, 0);
    const VkDescriptorSet set = pool.allocate(setLayout, 0);
    std::vector<VkDescriptorBufferInfo> infos;
    for (const vk::Buffer& b : deviceBuffers)
        infos.push_back({b.Handle(), 0, VK_WHOLE_SIZE});
    std::vector<VkWriteDescriptorSet> writes;
    for (std::size_t i = 0; i < infos.size(); ++i)
    {
        VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        w.dstSet = set;
        w.dstBinding = static_cast<std::uint32_t>(i);
        w.descriptorCount = 1;
        w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        w.pBufferInfo = &infos[i];
        writes.push_back(w);
    }
    vkUpdateDescriptorSets(device.Handle(), static_cast<std::uint32_t>(writes.size()), writes.data(), 0, nullptr);

    const vk::ShaderModule module(device, spirv);
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module.Handle();
    info.stage.pName = "main";
    info.layout = layout.Handle();
    VkPipeline handle = VK_NULL_HANDLE;
    vk::check(vkCreateComputePipelines(device.Handle(), VK_NULL_HANDLE, 1, &info, nullptr, &handle),
              "vkCreateComputePipelines");
    const vk::Pipeline pipeline(device, handle);

    vk::submitAndWait(device, context.commandPool(), [&](VkCommandBuffer cmd) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.Handle());
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout.Handle(), 0, 1, &set, 0, nullptr);
        if (pushBytes > 0)
            vkCmdPushConstants(cmd, layout.Handle(), VK_SHADER_STAGE_COMPUTE_BIT, 0, pushBytes, pushConstants);
        vkCmdDispatch(cmd, groupCount, 1, 1);
        VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        toHost.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0,
                             nullptr, 0, nullptr);
    });
    const vk::Buffer& result = deviceBuffers.at(resultBinding);
    std::vector<std::byte> out(buffers[resultBinding].bytes);
    std::memcpy(out.data(), result.mapped(), out.size());
    return out;
}
} // namespace rt::gpu::test
